import java.io.File;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.commands.SendTtActionCommand;
import ttctl.ttapi.enums.TtAction;
import ttctl.ttapi.msg.TtCommandAck;
import ttctl.ttapi.msg.TtOdometry;
import ttctl.ttapi.runtime.Command;
import ttctl.ttapi.runtime.CommandException;
import ttctl.ttapi.runtime.DjiLink;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.PacketReceiver;
import ttctl.ttapi.runtime.Session;
import ttctl.ttapi.runtime.Signing;
import ttctl.ttapi.runtime.UdpLink;
import ttctl.ttapi.transfer.Transfer;
import ttctl.ttapi.transfer.TransferConfig;
import ttctl.ttapi.transfer.TransferResult;

/**
 * The tablet end of tests/test_java_session.py: the generated Java runtime as an app uses it
 * (one Session), against real ttctl processes. Arguments: MODE key=value...; prints "EVENT ..."
 * lines and one "RESULT {json}" line.
 *
 * restart port=RELAY id=N phase=first|again   TAKE_OFF with command_id N and time_usec 0; the
 *     vehicle's telemetry must show it airborne; phase first then lands it (LAND, id N+1).
 * preempt port=RELAY rate=B/s                 idle round trips, then LAND (urgent) behind a HOVER
 *     the fake onboard end never answers.
 * sdkerrors port=ONBOARD errors=MS            a DjiLink whose SDK completes every packet with
 *     "The product is not connected" for MS ms, then forwards them to the onboard end.
 * wrongkey key=HEX                            UdpLink verifying with that key; waits for frames
 *     from the onboard end (udpout to our PORT), then a command.
 * signedto port=ONBOARD key=HEX               a signing Session sends TAKE_OFF first, to an onboard end
 *     with another key or none; the command's reason and words.
 * djikey key=HEX                              DjiLink verifying with that key, fed frames signed
 *     with another, then with it.
 * inbox port=LISTEN dir=DIR serve=DIR secs=S  takes pushed files, serves fetches, for S seconds
 *     [inbound=B/s]                            (sharing that inbound capacity out by rate grants).
 * listener port=ONBOARD n=N                   a 400 ms handler on telemetry; N commands meanwhile.
 */
public final class SessionDriver {
    static final int SYS = 255;
    static final int COMP = 190;
    static final long T0 = System.nanoTime();

    static double ms(long since) {
        return (System.nanoTime() - since) / 1e6;
    }

    static void event(String text) {
        System.out.println(String.format(Locale.ROOT, "EVENT %.3f %s", (System.nanoTime() - T0) / 1e9, text));
        System.out.flush();
    }

    public static void main(String[] argv) throws Exception {
        Map<String, String> a = new HashMap<>();
        for (int i = 1; i < argv.length; i++) {
            int k = argv[i].indexOf('=');
            a.put(argv[i].substring(0, k), argv[i].substring(k + 1));
        }
        Json out = new Json();
        switch (argv[0]) {
            case "restart":
                restart(a, out);
                break;
            case "preempt":
                preempt(a, out);
                break;
            case "sdkerrors":
                sdkErrors(a, out);
                break;
            case "wrongkey":
                wrongKey(a, out);
                break;
            case "signedto":
                signedTo(a, out);
                break;
            case "djikey":
                djiKey(a, out);
                break;
            case "inbox":
                inbox(a, out);
                break;
            case "listener":
                listener(a, out);
                break;
            default:
                throw new IllegalArgumentException(argv[0]);
        }
        System.out.println("RESULT " + out);
        System.out.flush();
        System.exit(0);
    }

    static Session udpSession(int port, double rate) throws Exception {
        UdpLink udp = UdpLink.open("127.0.0.1", 0, "127.0.0.1", port, Ttapi.INSTANCE);
        udp.setLearnsRemote(false);
        Session.Options o = new Session.Options();
        o.rate = rate;
        return new Session(udp, SYS, COMP, o);
    }

    static SendTtActionCommand action(int id, int action) {
        return new SendTtActionCommand(1, 240, id, action, 0L, new float[4], new byte[48]);
    }

    /** The vehicle's height above home from its odometry (NED: -d), or NaN before any. */
    static final class Height {
        volatile double up = Double.NaN;

        boolean await(boolean airborne, long millis) throws InterruptedException {
            long t0 = System.nanoTime();
            while (ms(t0) < millis) {
                double h = up;
                if (!Double.isNaN(h) && (airborne ? h > 1.0 : h < 0.05)) {
                    return true;
                }
                Thread.sleep(20);
            }
            return false;
        }
    }

    static String submitOk(Session s, Command c, long waitMs) throws Exception {
        try {
            TtCommandAck ack = (TtCommandAck) s.submit(c).get(waitMs, TimeUnit.MILLISECONDS);
            return ack.ok() ? "ok " + ack.resultName() + " id " + ack.command_id : "not ok " + ack.resultName();
        } catch (ExecutionException e) {
            return "failed " + e.getCause().getMessage();
        }
    }

    // -- a restarted app's command ------------------------------------------------------------
    static void restart(Map<String, String> a, Json out) throws Exception {
        int id = Integer.parseInt(a.get("id"));
        Session s = udpSession(Integer.parseInt(a.get("port")), 500);
        final Height h = new Height();
        s.dispatcher().on(TtOdometry.MSG_ID, TtOdometry.class, (TtOdometry o) -> h.up = -o.position[2]);
        s.start();
        String hello = submitOk(s, action(0, TtAction.TT_ACTION_SYNC_TIME), 15000); // the vehicle learns us
        boolean landed = h.await(false, 10000); // its telemetry follows
        event("SYNC_TIME: " + hello + "; on the ground: " + landed + " (" + h.up + " m)");
        out.put("hello", hello).put("height_before", h.up);
        if ("first".equals(a.get("phase"))) { // a LAND on the ground: refused, in the vehicle's words
            String refused = submitOk(s, action(0, TtAction.TT_ACTION_LAND), 15000);
            event("LAND on the ground: " + refused);
            out.put("refused", refused);
        }
        String takeoff = submitOk(s, action(id, TtAction.TT_ACTION_TAKE_OFF), 15000);
        event("TAKE_OFF id " + id + ": " + takeoff);
        boolean up = h.await(true, 10000);
        event("airborne " + up + " at " + h.up + " m");
        out.put("takeoff", takeoff).put("airborne", up);
        if ("first".equals(a.get("phase")) || up) {
            String land = submitOk(s, action(id + 1, TtAction.TT_ACTION_LAND), 15000);
            boolean down = h.await(false, 10000);
            event("LAND id " + (id + 1) + ": " + land + ", landed " + down);
            out.put("land", land).put("landed", down);
        }
        s.close();
    }

    // -- an urgent command behind an unanswered one ---------------------------------------------
    static void preempt(Map<String, String> a, Json out) throws Exception {
        Session s = udpSession(Integer.parseInt(a.get("port")), Double.parseDouble(a.get("rate")));
        s.start();
        List<Double> idle = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            long t0 = System.nanoTime();
            String r = submitOk(s, new SendTtActionCommand(1, 240, TtAction.TT_ACTION_SYNC_TIME, new float[4],
                    new byte[48]), 10000);
            if (r.startsWith("ok")) {
                idle.add(ms(t0));
            } else {
                event("idle command: " + r);
            }
        }
        out.put("idle_ms", idle);
        List<Double> land = new ArrayList<>();
        List<Boolean> hoverPending = new ArrayList<>();
        List<String> errors = new ArrayList<>();
        long[] delays = {150, 600, 1300};
        for (long d : delays) {
            SendTtActionCommand hover = new SendTtActionCommand(1, 240, TtAction.TT_ACTION_HOVER, new float[4],
                    new byte[48]);
            hover.setTimeoutMillis(500).setBackoff(2.0).setMaxRetries(3); // 0.5 + 1 + 2 + 4 = 7.5 s of waiting
            CompletableFuture<MavlinkMessage> fh = s.submit(hover);
            Thread.sleep(d);
            SendTtActionCommand l = new SendTtActionCommand(1, 240, TtAction.TT_ACTION_LAND, new float[4],
                    new byte[48]);
            l.setPriority(Command.URGENT_PRIORITY);
            long t0 = System.nanoTime();
            String r = submitOk(s, l, 10000);
            double took = ms(t0);
            boolean pending = !fh.isDone();
            event("LAND " + d + " ms after the HOVER: " + r + " in " + String.format(Locale.ROOT, "%.1f", took)
                    + " ms, HOVER still waiting: " + pending);
            if (r.startsWith("ok")) {
                land.add(took);
            } else {
                errors.add(r);
            }
            hoverPending.add(pending);
            fh.cancel(true); // the next trial starts without it
            try {
                fh.get(5, TimeUnit.SECONDS);
            } catch (Exception e) {
                // cancelled
            }
        }
        out.put("land_ms", land).put("hover_pending", hoverPending).put("errors", errors);
        s.close();
    }

    // -- an SDK that refuses every packet --------------------------------------------------------
    static final class RefusingSdk implements DjiLink.PacketSender {
        final DatagramSocket socket;
        final InetSocketAddress onboard;
        final long refuseUntil;
        final List<Long> sends = Collections.synchronizedList(new ArrayList<Long>());
        final ScheduledExecutorService sdkThread = Executors.newSingleThreadScheduledExecutor();
        volatile DjiLink link;
        volatile boolean closed;

        RefusingSdk(int port, long refuseMillis) throws Exception {
            socket = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
            onboard = new InetSocketAddress("127.0.0.1", port);
            refuseUntil = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(refuseMillis);
        }

        @Override
        public void send(byte[] packet, DjiLink.Completion done) throws Exception {
            long now = System.nanoTime();
            sends.add(now);
            final boolean refuse = now < refuseUntil;
            if (!refuse) {
                socket.send(new DatagramPacket(packet, packet.length, onboard));
            }
            sdkThread.schedule(() -> done.done(refuse ? "The product is not connected" : null), 5,
                    TimeUnit.MILLISECONDS);
        }

        void start() {
            Thread t = new Thread(() -> {
                byte[] buf = new byte[2048];
                while (!closed) {
                    DatagramPacket p = new DatagramPacket(buf, buf.length);
                    try {
                        socket.receive(p);
                    } catch (Exception e) {
                        continue;
                    }
                    link.onDataFromOnboard(java.util.Arrays.copyOf(p.getData(), p.getLength()));
                }
            }, "fake-dji-data-callback");
            t.setDaemon(true);
            t.start();
        }
    }

    static void sdkErrors(Map<String, String> a, Json out) throws Exception {
        long refuse = Long.parseLong(a.get("errors"));
        RefusingSdk sdk = new RefusingSdk(Integer.parseInt(a.get("port")), refuse);
        DjiLink dji = new DjiLink(sdk, new PacketReceiver(Ttapi.INSTANCE));
        sdk.link = dji;
        final List<String> states = Collections.synchronizedList(new ArrayList<String>());
        final List<String> stateThreads = Collections.synchronizedList(new ArrayList<String>());
        dji.setStateListener((stalled, why) -> {
            states.add((stalled ? "problem: " : "ok: ") + why);
            stateThreads.add(Thread.currentThread().getName());
            event("link " + (stalled ? "problem" : "ok") + ": " + why);
        });
        Session.Options o = new Session.Options();
        o.linkRate = 500;
        o.transfers = new TransferConfig();
        o.transfers.giveUpAfter = 3;
        Session s = new Session(dji, SYS, COMP, o).start();
        sdk.start();
        long t0 = System.nanoTime();
        File f = new File(a.getOrDefault("file", "up.bin"));
        Transfer up = s.files().send(f, f.getName(), 1, 240, false, null);
        SendTtActionCommand cmd = new SendTtActionCommand(1, 240, TtAction.TT_ACTION_SYNC_TIME, new float[4],
                new byte[48]);
        cmd.setTimeoutMillis(400).setBackoff(1.0).setMaxRetries(3);
        String command = submitOk(s, cmd, 10000);
        event("command during the refusals: " + command);
        TransferResult r = up.await(10, TimeUnit.SECONDS);
        event("upload during the refusals: " + r);
        out.put("problem", String.valueOf(s.problem())).put("refusing", dji.isRefusing());
        out.put("command", command).put("upload_code", r == null ? "HANG" : r.code)
                .put("upload_message", r == null ? "" : r.message);
        while (System.nanoTime() - sdk.refuseUntil < 0) {
            Thread.sleep(20);
        }
        long recovered = System.nanoTime();
        int before = sdk.sends.size();
        String after = submitOk(s, new SendTtActionCommand(1, 240, TtAction.TT_ACTION_SYNC_TIME, new float[4],
                new byte[48]), 10000);
        double afterMs = ms(recovered);
        event("command after the SDK recovered: " + after + " in " + afterMs + " ms");
        Thread.sleep(300);
        List<Double> times = new ArrayList<>();
        synchronized (sdk.sends) {
            for (int i = 0; i < before; i++) {
                times.add((sdk.sends.get(i) - t0) / 1e9);
            }
        }
        out.put("refused_send_times", times).put("refused_sends", before).put("refusing_seconds", refuse / 1000.0)
                .put("after", after).put("after_ms", afterMs).put("states", states).put("state_threads", stateThreads)
                .put("problem_after", String.valueOf(s.problem())).put("dji_failed", dji.failed());
        s.close();
        sdk.closed = true;
        sdk.sdkThread.shutdownNow();
        sdk.socket.close();
    }

    // -- a wrong key -------------------------------------------------------------------------
    static void wrongKey(Map<String, String> a, Json out) throws Exception {
        Signing signing = new Signing(unhex(a.get("key")), 1, false);
        UdpLink udp = new UdpLink(new DatagramSocket(new InetSocketAddress("127.0.0.1", 0)), null, Ttapi.INSTANCE,
                signing);
        Session.Options o = new Session.Options();
        o.signing = signing;
        o.rate = 8000;
        Session s = new Session(udp, SYS, COMP, o).start();
        System.out.println("PORT " + udp.localPort());
        System.out.flush();
        long t0 = System.nanoTime();
        while (udp.stats().packets() == 0 && ms(t0) < 15000) {
            Thread.sleep(20);
        }
        Thread.sleep(200);
        SendTtActionCommand cmd = new SendTtActionCommand(1, 240, TtAction.TT_ACTION_SYNC_TIME, new float[4],
                new byte[48]);
        cmd.setTimeoutMillis(300).setBackoff(1.0).setMaxRetries(2);
        String r = submitOk(s, cmd, 10000);
        event("command: " + r);
        out.put("command", r).put("problem", String.valueOf(s.problem())).put("bad_frames", udp.stats().badFrames())
                .put("bad_signatures", udp.stats().badSignatures()).put("unsigned", udp.stats().unsignedRefused());
        s.close();
    }

    /** A signing tablet that speaks first: the vehicle has another key (silence) or none (unsigned answers). */
    static void signedTo(Map<String, String> a, Json out) throws Exception {
        Signing signing = new Signing(unhex(a.get("key")), 1, false);
        UdpLink udp = new UdpLink(new DatagramSocket(new InetSocketAddress("127.0.0.1", 0)),
                new InetSocketAddress("127.0.0.1", Integer.parseInt(a.get("port"))), Ttapi.INSTANCE, signing);
        Session.Options o = new Session.Options();
        o.signing = signing;
        o.rate = 8000;
        Session s = new Session(udp, SYS, COMP, o).start();
        SendTtActionCommand cmd = new SendTtActionCommand(1, 240, TtAction.TT_ACTION_TAKE_OFF, new float[4],
                new byte[48]);
        cmd.setTimeoutMillis(500).setBackoff(1.0).setMaxRetries(3);
        try {
            s.submit(cmd).get(20, TimeUnit.SECONDS);
            out.put("reason", "none");
        } catch (ExecutionException e) {
            CommandException why = (CommandException) e.getCause();
            out.put("reason", why.reason().name()).put("words", why.getMessage());
        }
        out.put("unsigned", udp.stats().unsignedRefused());
        s.close();
    }

    /** DjiLink verifying with one key, fed frames signed with another (as the drone would send them). */
    static void djiKey(Map<String, String> a, Json out) throws Exception {
        Signing ours = new Signing(unhex(a.get("key")), 1, false);
        Signing theirs = new Signing(Signing.keyFromPassphrase("not the tablet's key"), 1, false);
        final List<String> states = Collections.synchronizedList(new ArrayList<String>());
        DjiLink dji = new DjiLink((p, done) -> done.done(null), new PacketReceiver(Ttapi.INSTANCE, ours));
        dji.setStateListener((bad, why) -> states.add((bad ? "problem: " : "ok: ") + why));
        for (int i = 0; i < 5; i++) {
            dji.onDataFromOnboard(theirs.sign(new TtOdometry().pack(i, 1, 240)));
            Thread.sleep(20);
        }
        long t0 = System.nanoTime();
        while (states.isEmpty() && ms(t0) < 3000) {
            Thread.sleep(10);
        }
        out.put("problem", String.valueOf(dji.problem())).put("states", states);
        for (int i = 0; i < 3; i++) { // the right key after all
            dji.onDataFromOnboard(ours.sign(new TtOdometry().pack(10 + i, 1, 240)));
            Thread.sleep(20);
        }
        t0 = System.nanoTime();
        while (states.size() < 2 && ms(t0) < 3000) {
            Thread.sleep(10);
        }
        out.put("problem_after", String.valueOf(dji.problem())).put("states_after", states);
        dji.close();
    }

    // -- the inbox and the served folder -----------------------------------------------------------
    static void inbox(Map<String, String> a, Json out) throws Exception {
        int port = Integer.parseInt(a.get("port"));
        UdpLink udp = new UdpLink(new DatagramSocket(new InetSocketAddress("127.0.0.1", port)), null, Ttapi.INSTANCE);
        Session.Options o = new Session.Options();
        o.rate = Double.parseDouble(a.getOrDefault("rate", "8000"));
        o.transfers = new TransferConfig();
        o.transfers.giveUpAfter = Double.parseDouble(a.getOrDefault("timeout", "20"));
        Session s = new Session(udp, SYS, COMP, o);
        final List<String> results = Collections.synchronizedList(new ArrayList<String>());
        s.files().acceptInto(new File(a.get("dir")));
        if (a.containsKey("inbound")) {
            s.files().setInboundCapacity(Double.parseDouble(a.get("inbound")));
        }
        if (a.containsKey("serve")) {
            s.files().serve(new File(a.get("serve")));
        }
        s.files().setIncomingListener(t -> {
            event("incoming " + t + (t.isUpload() ? " (served)" : " (pushed)"));
            return new Transfer.Listener() {
                long last;

                @Override
                public void onProgress(Transfer tr, long done, long size) {
                    if (done - last >= 8192 || done == size) {
                        last = done;
                        event("progress " + tr.name() + " " + done + "/" + size);
                    }
                }

                @Override
                public void onComplete(Transfer tr, TransferResult r) {
                    Json j = new Json().put("name", r.name).put("ok", r.ok).put("code", r.code).put("message", r.message)
                            .put("size", r.size).put("resumed", r.resumedBytes).put("moved", r.bytesMoved)
                            .put("seconds", r.seconds).put("goodput", r.goodput()).put("served", tr.isUpload())
                            .put("peer", tr.peer()).put("file", r.file == null ? null : r.file.getPath())
                            .put("deflated", r.deflatedSize);
                    results.add(j.toString());
                    event("done " + j);
                }
            };
        });
        s.start();
        System.out.println("READY " + udp.localPort());
        System.out.flush();
        long end = System.nanoTime() + (long) (Double.parseDouble(a.getOrDefault("secs", "60")) * 1e9);
        File stop = new File(a.get("dir") + ".stop");
        while (System.nanoTime() < end && !stop.exists()) {
            Thread.sleep(100);
        }
        out.put("results", results).put("refused", s.files().refused()).put("dropped", s.files().dropped())
                .put("ignored", s.files().ignored()).put("bad_frames", udp.stats().badFrames());
        s.close();
    }

    // -- a slow listener -----------------------------------------------------------------------
    static void listener(Map<String, String> a, Json out) throws Exception {
        Session s = udpSession(Integer.parseInt(a.get("port")), 0);
        final AtomicLong received = new AtomicLong();
        final AtomicLong handled = new AtomicLong();
        final AtomicInteger onReader = new AtomicInteger();
        s.dispatcher().onAny(msg -> { // the app's slow handler: 400 ms for every message, acks included
            if (Thread.currentThread().getName().startsWith("ttctl-udp")) {
                onReader.incrementAndGet();
            }
            Thread.sleep(400);
            handled.incrementAndGet();
        });
        ((UdpLink) s.link()).addListener(msg -> received.incrementAndGet());
        s.start();
        Thread.sleep(1500); // a backlog builds up: telemetry comes faster than the handler
        int n = Integer.parseInt(a.get("n"));
        List<Double> lat = new ArrayList<>();
        List<Long> backlog = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            long t0 = System.nanoTime();
            String r = submitOk(s, new SendTtActionCommand(1, 240, TtAction.TT_ACTION_SYNC_TIME, new float[4],
                    new byte[48]), 5000);
            if (r.startsWith("ok")) {
                lat.add(ms(t0));
            } else {
                event("command: " + r);
            }
            backlog.add(received.get() - handled.get());
            Thread.sleep(100);
        }
        out.put("command_ms", lat).put("backlog", backlog).put("received", received.get()).put("handled", handled.get())
                .put("handled_on_reader_thread", onReader.get());
        s.close();
    }

    static byte[] unhex(String h) {
        byte[] b = new byte[h.length() / 2];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) Integer.parseInt(h.substring(2 * i, 2 * i + 2), 16);
        }
        return b;
    }

    /** A flat JSON object. */
    static final class Json {
        final List<String> parts = Collections.synchronizedList(new ArrayList<String>());

        Json put(String k, Object v) {
            parts.add("\"" + k + "\": " + value(v));
            return this;
        }

        static String value(Object v) {
            if (v == null) {
                return "null";
            }
            if (v instanceof Boolean || v instanceof Integer || v instanceof Long) {
                return v.toString();
            }
            if (v instanceof Double) {
                double d = (Double) v;
                return Double.isNaN(d) || Double.isInfinite(d) ? "null" : String.format(Locale.ROOT, "%.6f", d);
            }
            if (v instanceof List) {
                StringBuilder b = new StringBuilder("[");
                synchronized (v) {
                    for (Object x : (List<?>) v) {
                        b.append(b.length() > 1 ? ", " : "").append(x instanceof String && ((String) x).startsWith("{")
                                ? x : value(x));
                    }
                }
                return b.append(']').toString();
            }
            String s = v.toString().replace("\\", "\\\\").replace("\"", "\\\"");
            StringBuilder b = new StringBuilder("\"");
            for (char c : s.toCharArray()) {
                b.append(c < 0x20 ? String.format("\\u%04x", (int) c) : String.valueOf(c));
            }
            return b.append('"').toString();
        }

        @Override
        public String toString() {
            return "{" + String.join(", ", parts) + "}";
        }
    }
}
