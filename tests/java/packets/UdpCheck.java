import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.runtime.UdpLink;

/**
 * UdpLink receive path for tests/test_java_packets.py: binds 127.0.0.1 on a free port, prints
 * "PORT n", then "MSG msgid seq sysid compid millis" for every message received (millis since
 * start), until stdin closes; then "STATS ..." and "DONE".
 */
public final class UdpCheck {
    private UdpCheck() {
    }

    public static void main(String[] args) throws Exception {
        final long t0 = System.nanoTime();
        UdpLink link = UdpLink.open("127.0.0.1", 0, null, 0, Ttapi.INSTANCE);
        link.addListener(m -> {
            synchronized (System.out) {
                System.out.println("MSG " + m.msgId() + " " + m.seq() + " " + m.sysId() + " " + m.compId() + " "
                        + (System.nanoTime() - t0) / 1_000_000);
                System.out.flush();
            }
        });
        link.start();
        synchronized (System.out) {
            System.out.println("PORT " + link.localPort());
            System.out.flush();
        }
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.US_ASCII));
        while (in.readLine() != null) {
            // wait for the test to close stdin
        }
        link.close();
        synchronized (System.out) {
            System.out.println("STATS " + link.stats());
            System.out.println("DONE");
            System.out.flush();
        }
    }
}
