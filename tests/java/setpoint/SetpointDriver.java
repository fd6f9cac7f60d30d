import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.commands.SendTtActionCommand;
import ttctl.ttapi.enums.TtAction;
import ttctl.ttapi.msg.DjiPoseStamped;
import ttctl.ttapi.msg.TtCommandAck;
import ttctl.ttapi.msg.TtOdometry;
import ttctl.ttapi.runtime.CommandException;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.SendSetpoint;
import ttctl.ttapi.runtime.Session;
import ttctl.ttapi.runtime.UdpLink;

/**
 * The tablet end of tests/test_java_setpoints.py: set-points sent as an app sends them (one
 * Session, {@link SendSetpoint}), their results as the app sees them. Arguments: MODE port=P;
 * prints "EVENT ..." lines and one "RESULT {json}" line (flat: strings, numbers, booleans).
 *
 * fly port=ONBOARD     a set-point while landed (refused), take-off, a flyable set-point (done,
 *     and the vehicle's odometry moves north), one at 0.2 m (refused), two in a row (the first
 *     superseded, the second done).
 * silent port=SINK     a set-point nobody answers, submitted while an older one is in flight.
 * idle port=ONBOARD    take-off, then 13 s of nothing from the app (the session's own
 *     heartbeats keep the vehicle hearing its tablet).
 * idle-no-heartbeat port=ONBOARD   the same with Session.Options.heartbeatMillis = 0.
 */
public final class SetpointDriver {
    static final int SYS = 255;
    static final int COMP = 190;
    static final long T0 = System.nanoTime();
    static final StringBuilder OUT = new StringBuilder();

    static void event(String text) {
        System.out.println(String.format(Locale.ROOT, "EVENT %.3f %s", (System.nanoTime() - T0) / 1e9, text));
        System.out.flush();
    }

    static void put(String k, Object v) {
        String s = v instanceof String ? "\"" + ((String) v).replace("\\", "\\\\").replace("\"", "\\\"") + "\""
                : String.valueOf(v);
        OUT.append(OUT.length() > 0 ? ", " : "").append('"').append(k).append("\": ").append(s);
    }

    /** A set-point's result as the app sees it, with where its callback ran. */
    static final class Probe extends SendSetpoint {
        final CompletableFuture<String> called = new CompletableFuture<>();

        Probe(double n, double e, double alt) {
            super(1, n, e, alt);
        }

        @Override
        protected void onSuccess(MavlinkMessage reply) {
            DjiPoseStamped echo = (DjiPoseStamped) reply;
            called.complete("onSuccess on " + Thread.currentThread().getName() + " echo " + echo.sec + "/" + echo.nsec);
        }

        @Override
        protected void onFailure(Throwable error) {
            called.complete("onFailure on " + Thread.currentThread().getName());
        }
    }

    static String result(CompletableFuture<MavlinkMessage> f, long waitMs) throws Exception {
        try {
            DjiPoseStamped echo = (DjiPoseStamped) f.get(waitMs, TimeUnit.MILLISECONDS);
            return String.format(Locale.ROOT, "DONE %.1f %.1f %.1f", echo.position[0], echo.position[1],
                    echo.position[2]);
        } catch (ExecutionException e) {
            CommandException c = (CommandException) e.getCause();
            return c.reason() + " " + c.getMessage() + " (tries " + c.tries() + ")";
        }
    }

    static String send(Session s, double n, double e, double alt, String key) throws Exception {
        Probe p = new Probe(n, e, alt);
        long t0 = System.nanoTime();
        String r = result(s.submit(p), 20000);
        put(key, r);
        put(key + "_s", (System.nanoTime() - t0) / 1e9);
        put(key + "_callback", p.called.get(5, TimeUnit.SECONDS));
        event(key + ": " + r);
        return r;
    }

    public static void main(String[] argv) throws Exception {
        int port = Integer.parseInt(argv[1].substring(argv[1].indexOf('=') + 1));
        UdpLink udp = UdpLink.open("127.0.0.1", 0, "127.0.0.1", port, Ttapi.INSTANCE);
        udp.setLearnsRemote(false);
        Session.Options options = new Session.Options();
        if ("idle-no-heartbeat".equals(argv[0])) {
            options.heartbeatMillis = 0; // the session's own heartbeats off: the vehicle must take the tablet for lost
        }
        Session s = new Session(udp, SYS, COMP, options);
        final double[] ned = {Double.NaN, Double.NaN, Double.NaN};
        s.dispatcher().on(TtOdometry.MSG_ID, TtOdometry.class, (TtOdometry o) -> {
            synchronized (ned) {
                for (int i = 0; i < 3; i++) {
                    ned[i] = o.position[i];
                }
            }
        });
        s.start();
        if (argv[0].startsWith("idle")) {
            // take off, then nothing at all from the app for 13 s: only the session's heartbeats
            put("hello", action(s, TtAction.TT_ACTION_SYNC_TIME));
            String takeoff = action(s, TtAction.TT_ACTION_TAKE_OFF);
            event("TAKE_OFF: " + takeoff);
            put("takeoff", takeoff);
            put("airborne", await(ned, 2, -1.0, 30000));
            event("idle");
            Thread.sleep(13000);
            put("idle_s", 13);
        } else if ("silent".equals(argv[0])) {
            // one in flight (sent twice, unanswered), then a newer one: the older ends SUPERSEDED
            Probe first = new Probe(1, 0, 10);
            CompletableFuture<MavlinkMessage> f = s.submit(first);
            Thread.sleep(2000);
            send(s, 5, 0, 10, "silent");
            put("first", result(f, 1000));
            put("first_callback", first.called.get(5, TimeUnit.SECONDS));
        } else {
            String hello = action(s, TtAction.TT_ACTION_SYNC_TIME);
            event("SYNC_TIME: " + hello);
            send(s, 5, 0, 10, "landed");
            String takeoff = action(s, TtAction.TT_ACTION_TAKE_OFF);
            event("TAKE_OFF: " + takeoff);
            put("takeoff", takeoff);
            put("airborne", await(ned, 2, -1.0, 30000)); // up: NED d below -1 m
            double n0;
            synchronized (ned) {
                n0 = ned[0];
            }
            put("north_before", n0);
            send(s, n0 + 5, 0, 5, "fly");
            put("moved", await(ned, 0, n0 + 1.0, 20000)); // north by more than a metre
            synchronized (ned) {
                put("north_after", ned[0]);
            }
            send(s, 0, 0, 0.2, "low");
            send(s, 1e9, 0, 10, "far"); // 80 bytes of words: a full TT_LOG chunk and an empty last one
            // two in a row (the queue paused so the vehicle cannot answer the older first): the
            // newer supersedes the older
            s.commands().pause();
            Probe older = new Probe(0, 0, 6);
            CompletableFuture<MavlinkMessage> f1 = s.submit(older);
            Probe newer = new Probe(0, 0, 7);
            CompletableFuture<MavlinkMessage> f2 = s.submit(newer);
            s.commands().resume();
            put("older", result(f1, 20000));
            put("older_callback", older.called.get(5, TimeUnit.SECONDS));
            put("newer", result(f2, 20000));
        }
        event("closing");
        s.close();
        System.out.println("RESULT {" + OUT + "}");
        System.out.flush();
        System.exit(0);
    }

    static String action(Session s, int action) throws Exception {
        try {
            TtCommandAck ack = (TtCommandAck) s.submit(new SendTtActionCommand(1, 240, action, new float[4],
                    new byte[48])).get(15000, TimeUnit.MILLISECONDS);
            return ack.ok() ? "ok " + ack.resultName() : "not ok " + ack.resultName();
        } catch (ExecutionException e) {
            return "failed " + e.getCause().getMessage();
        }
    }

    /** Whether ned[axis] passes `bound` (above it for a positive bound... below for d) in time. */
    static boolean await(double[] ned, int axis, double bound, long millis) throws InterruptedException {
        long t0 = System.nanoTime();
        while ((System.nanoTime() - t0) / 1e6 < millis) {
            double v;
            synchronized (ned) {
                v = ned[axis];
            }
            if (!Double.isNaN(v) && (axis == 2 ? v < bound : v > bound)) {
                return true;
            }
            Thread.sleep(20);
        }
        return false;
    }
}
