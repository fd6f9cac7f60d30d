import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.runtime.Session;
import ttctl.ttapi.runtime.UdpLink;

/**
 * A tablet app of ttctl's own dialect (ttapi) on UDP, one Session with an onProblem callback,
 * for tests/test_tablet_msg_steps.py: the vehicle (`ttctl emulate onboard --dialect survey.xml`)
 * speaks another dialect, and sends a message ttapi lacks. Arguments: PORT SECONDS. Prints each
 * problem told ("PROBLEM words"), then "UNKNOWN count" (Session.unknownMessages()) and
 * "HEARD n" (the vehicle's frames of ttapi that were decoded).
 */
public final class UnknownTablet {
    public static void main(String[] argv) throws Exception {
        int port = Integer.parseInt(argv[0]);
        double seconds = Double.parseDouble(argv[1]);
        final List<String> problems = new CopyOnWriteArrayList<>();
        final int[] heard = new int[1];
        UdpLink udp = UdpLink.open("127.0.0.1", 0, "127.0.0.1", port, Ttapi.INSTANCE);
        Session.Options options = new Session.Options();
        options.rate = 500;
        options.onProblem = words -> problems.add(words);
        Session session = new Session(udp, 255, 190, options).start();
        session.dispatcher().onAny(m -> {
            synchronized (heard) {
                heard[0]++;
            }
        });
        try {
            Thread.sleep((long) (seconds * 1000));
        } finally {
            session.close();
        }
        Thread.sleep(200); // the listener executor finishes what is queued
        for (String p : problems) {
            System.out.println("PROBLEM " + p);
        }
        System.out.println("UNKNOWN " + session.unknownMessages());
        synchronized (heard) {
            System.out.println("HEARD " + heard[0]);
        }
    }
}
