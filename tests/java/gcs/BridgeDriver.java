import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.commands.SendTtActionCommand;
import ttctl.ttapi.enums.TtAction;
import ttctl.ttapi.runtime.CommandContext;
import ttctl.ttapi.runtime.CommandException;
import ttctl.ttapi.runtime.GcsBridge;
import ttctl.ttapi.runtime.Session;
import ttctl.ttapi.runtime.Signing;
import ttctl.ttapi.runtime.UdpLink;

/**
 * The tablet app of tests/test_java_bridge.py: a Session on a UdpLink to `ttctl link relay`
 * (the emulated radio, paced at the uplink's rate) and a GcsBridge on it that sends to the
 * ground station at 127.0.0.1:GCS_PORT and also listens on LISTEN_PORT.
 *
 * Arguments: RELAY_PORT GCS_PORT LISTEN_PORT RATE [PASSPHRASE: the link signed with the key of
 * `ttctl --key PASSPHRASE`]. Prints "ready"; then reads commands, one a
 * line: "v1" prints the MAVLink 1 counters, "problems" what onProblem was told; "lat SECONDS" sends the app's own command (TT_ACTION_SYNC_TIME to the onboard end, one
 * after another) for that long and prints "LAT [ms,...] TRY [ms,...] errors N": each command's
 * time to its ack, and the time from its last try to the ack (the round trip through the link
 * as loaded, whatever tries the radio's loss cost); "stats" prints the bridge's
 * counters; end of input closes the bridge and the session and prints "closed".
 */
public final class BridgeDriver {
    private BridgeDriver() {
    }

    public static void main(String[] argv) throws Exception {
        final AtomicInteger uncaught = new AtomicInteger();
        Thread.setDefaultUncaughtExceptionHandler((t, e) -> {
            uncaught.incrementAndGet();
            System.out.println("EVENT uncaught " + t.getName() + " " + e);
        });
        int relay = Integer.parseInt(argv[0]);
        int gcsPort = Integer.parseInt(argv[1]);
        int listenPort = Integer.parseInt(argv[2]);
        double rate = Double.parseDouble(argv[3]);
        Signing signing = argv.length > 4 ? new Signing(Signing.keyFromPassphrase(argv[4]), 1, false) : null;
        UdpLink link = new UdpLink(new DatagramSocket(new InetSocketAddress("127.0.0.1", 0)),
                new InetSocketAddress("127.0.0.1", relay), Ttapi.INSTANCE, signing);
        Session.Options o = new Session.Options();
        o.rate = rate;
        o.signing = signing; // the scheduler signs every frame, the ground stations' too
        Session session = new Session(link, 255, 190, o).start();
        final List<String> problems = Collections.synchronizedList(new ArrayList<String>());
        GcsBridge bridge = GcsBridge.start(session, new GcsBridge.Config()
                .sendTo("127.0.0.1", gcsPort)
                .listen("127.0.0.1", listenPort)
                .onProblem(problems::add));
        System.out.println("ready " + bridge.port());
        System.out.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, "UTF-8"));
        String line;
        while ((line = in.readLine()) != null) {
            String[] w = line.trim().split("\\s+");
            if (w[0].equals("lat")) {
                long end = System.nanoTime() + (long) (Double.parseDouble(w[1]) * 1e9);
                List<String> ms = new ArrayList<>();
                List<String> lastTry = new ArrayList<>();
                int errors = 0;
                while (System.nanoTime() < end) {
                    long t0 = System.nanoTime();
                    final AtomicLong tried = new AtomicLong(t0);
                    SendTtActionCommand c = new SendTtActionCommand(1, 240, TtAction.TT_ACTION_SYNC_TIME,
                            new float[4], new byte[48]) {
                        @Override
                        protected void attempt(CommandContext ctx, int attempt) throws Exception {
                            tried.set(System.nanoTime());
                            super.attempt(ctx, attempt);
                        }
                    };
                    // six tries, 0.5 s growing by 1.5x (10.4 s in all): at 10 % loss each way a try
                    // fails 19 % of the time on the radio alone, so the default four fail one
                    // command in 770, and a run of this driver sends about 90; what is measured
                    // here is whether the ground station's traffic delays or loses commands
                    c.setMaxRetries(5);
                    c.setBackoff(1.5);
                    try {
                        session.submit(c).get(15, TimeUnit.SECONDS);
                        long t1 = System.nanoTime();
                        ms.add(String.format(Locale.ROOT, "%.1f", (t1 - t0) / 1e6));
                        lastTry.add(String.format(Locale.ROOT, "%.1f", (t1 - tried.get()) / 1e6));
                    } catch (java.util.concurrent.ExecutionException e) {
                        if (e.getCause() instanceof CommandException) {
                            errors++;
                            System.out.println("EVENT command " + e.getCause().getMessage());
                            System.err.println("command failed: " + e.getCause().getMessage());
                        } else {
                            throw e;
                        }
                    }
                    Thread.sleep(20);
                }
                System.out.println("LAT [" + String.join(",", ms) + "] TRY [" + String.join(",", lastTry) + "] errors "
                        + errors);
            } else if (w[0].equals("problems")) {
                synchronized (problems) {
                    System.out.println("PROBLEMS " + String.join(" | ", problems));
                }
            } else if (w[0].equals("v1")) {
                System.out.println(String.format(Locale.ROOT, "V1 up=%d down=%d dropped=%d notCarried=%d",
                        bridge.v1Up(), bridge.v1Down(), bridge.v1Dropped(), bridge.notCarried()));
            } else if (w[0].equals("stats")) {
                System.out.println(String.format(Locale.ROOT, "STATS carried=%d carriedBytes=%d duplicates=%d overflow=%d replaced=%d "
                        + "notCarried=%d unknown=%d toGcs=%d radio=%d fromVehicle=%d waiting=%d peak=%d peers=%d "
                        + "datagrams=%d problems=%d uncaught=%d queued=%d resent=%d itemsResent=%d itemsAnswered=%d paramsRead=%d",
                        bridge.carried(), bridge.carriedBytes(), bridge.duplicates(),
                        bridge.overflow(), bridge.replaced(), bridge.notCarried(), bridge.unknown(), bridge.toGcs(),
                        bridge.radioStatus(), bridge.fromVehicle(), bridge.waiting(), bridge.peakWaiting(),
                        bridge.peers(), bridge.datagrams(), problems.size(), uncaught.get(),
                        session.scheduler().queued(), bridge.resent(),
                        bridge.missionItemsResent(), bridge.missionItemsAnswered(), bridge.paramsReadAgain()));
            }
            System.out.flush();
        }
        bridge.close();
        session.close();
        System.out.println("closed " + problems);
        System.out.flush();
    }
}
