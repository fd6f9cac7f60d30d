import java.io.File;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.commands.SendTtActionCommand;
import ttctl.ttapi.enums.TtAction;
import ttctl.ttapi.msg.TtCommandAck;
import ttctl.ttapi.msg.TtFileData;
import ttctl.ttapi.msg.TtFileStatus;
import ttctl.ttapi.runtime.CommandException;
import ttctl.ttapi.runtime.CommandQueue;
import ttctl.ttapi.runtime.DjiLink;
import ttctl.ttapi.runtime.Link;
import ttctl.ttapi.runtime.LinkScheduler;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.PacketReceiver;
import ttctl.ttapi.runtime.Signing;
import ttctl.ttapi.runtime.UdpLink;
import ttctl.ttapi.transfer.FileTransfers;
import ttctl.ttapi.transfer.Transfer;
import ttctl.ttapi.transfer.TransferConfig;
import ttctl.ttapi.transfer.TransferResult;

/**
 * The tablet end of tests/test_java_transfer.py: the generated Java runtime (LinkScheduler,
 * CommandQueue, FileTransfers, UdpLink or DjiLink with a fake DJI SDK) against real ttctl
 * processes. Arguments are key=value; prints one "RESULT {json}" line, and "EVENT ..." lines.
 *
 * link=udp|dji port=RELAY rate=B/s timeout=S [mtu=BYTES (udp; default 100)] [send=FILE] [fetch=NAME dir=DIR] [idle=N]
 * [during=MS] [stall=MS_AFTER:MS_LONG] [garbage=1] [completion=MS] [key=64 hex digits: sign (dji)]
 */
public final class TabletDriver {
    static final int SYS = 255;
    static final int COMP = 190;
    static final AtomicInteger APP_THREAD_ERRORS = new AtomicInteger();
    static final AtomicInteger UNCAUGHT = new AtomicInteger();

    public static void main(String[] argv) throws Exception {
        Map<String, String> a = new HashMap<>();
        for (String s : argv) {
            int i = s.indexOf('=');
            a.put(s.substring(0, i), s.substring(i + 1));
        }
        Thread.setDefaultUncaughtExceptionHandler((t, e) -> {
            UNCAUGHT.incrementAndGet();
            System.out.println("EVENT uncaught " + t.getName() + " " + e);
        });
        int port = Integer.parseInt(a.get("port"));
        double rate = Double.parseDouble(a.get("rate"));
        double timeout = Double.parseDouble(a.getOrDefault("timeout", "20"));
        Json out = new Json();
        Link link;
        FakeSdk sdk = null;
        PacketReceiver prx = null;
        LinkScheduler sched;
        CommandQueue cq;
        TransferConfig cfg = new TransferConfig();
        cfg.giveUpAfter = timeout;
        FileTransfers files;
        if ("dji".equals(a.get("link"))) {
            sdk = new FakeSdk(port, rate, a.get("stall"));
            Signing signing = a.containsKey("key") ? new Signing(unhex(a.get("key")), 1, false) : null;
            prx = new PacketReceiver(Ttapi.INSTANCE, signing);
            sdk.signing = signing;
            DjiLink dji = new DjiLink(sdk, prx)
                    .setCompletionTimeoutMillis(Long.parseLong(a.getOrDefault("completion", "1000")))
                    .setStateListener((stalled, why) -> System.out.println("EVENT link " + (stalled ? "stalled" : "ok")
                            + ": " + why));
            sdk.link = dji;
            link = dji;
            sched = new LinkScheduler(dji, 0).start(); // DJI's completions pace it
            if (signing != null) {
                sched.setSigner(signing::sign); // every frame, commands and file data alike
            }
            files = new FileTransfers(sched, SYS, COMP, cfg).setLinkRate(rate).start();
            cq = new CommandQueue(sched, SYS, COMP).start();
            dji.addListener(cq).addListener(files);
            sdk.start();
            System.out.println("PORT " + sdk.socket.getLocalPort());
        } else {
            UdpLink udp = UdpLink.open("127.0.0.1", 0, "127.0.0.1", port, Ttapi.INSTANCE);
            udp.setLearnsRemote(false);
            udp.setMtu(Integer.parseInt(a.getOrDefault("mtu", "100"))); // the link's packet: the scheduler's and the frames'
            link = udp;
            sched = new LinkScheduler(udp, rate).start();
            files = new FileTransfers(sched, SYS, COMP, cfg).start();
            cq = new CommandQueue(sched, SYS, COMP).start();
            udp.addListener(cq).addListener(files);
            udp.start();
            System.out.println("PORT " + udp.localPort());
        }
        System.out.flush();
        AtomicBoolean garbageOn = new AtomicBoolean("1".equals(a.get("garbage")));
        if (sdk != null && garbageOn.get()) {
            sdk.startGarbage();
        }
        // idle command latency
        int idle = Integer.parseInt(a.getOrDefault("idle", "0"));
        List<Double> idleMs = new ArrayList<>();
        int idleFailed = 0;
        for (int i = 0; i < idle; i++) {
            double ms = command(cq, 4000);
            if (ms < 0) {
                idleFailed++;
            } else {
                idleMs.add(ms);
            }
        }
        out.put("idle_ms", idleMs).put("idle_failed", idleFailed);
        List<Transfer> running = new ArrayList<>();
        Transfer up = null;
        Transfer down = null;
        if (a.containsKey("send")) {
            File f = new File(a.get("send"));
            up = files.send(f, a.getOrDefault("name", f.getName()), 1, 240, false, listener("send"));
            running.add(up);
            out.put("send_sha256", hex(sha(f)));
        }
        if (a.containsKey("fetch")) {
            down = files.fetch(a.get("fetch"), new File(a.get("dir")), 1, 240, listener("fetch"));
            running.add(down);
        }
        // commands during the transfers, one at a time, every `during` ms
        long during = Long.parseLong(a.getOrDefault("during", "0"));
        List<Double> duringMs = new ArrayList<>();
        List<String> duringErrors = new ArrayList<>();
        long hardEnd = System.nanoTime() + (long) ((timeout * 3 + 60) * 1e9);
        while (!allDone(running) && System.nanoTime() < hardEnd) {
            if (during > 0) {
                Thread.sleep(during);
                if (allDone(running)) {
                    break;
                }
                CompletableFuture<MavlinkMessage> fut = cq.submit(action());
                long t0 = System.nanoTime();
                try {
                    fut.get(10, TimeUnit.SECONDS);
                    duringMs.add((System.nanoTime() - t0) / 1e6);
                } catch (Exception e) {
                    if (refusal(e)) {
                        duringMs.add((System.nanoTime() - t0) / 1e6); // answered: a round trip all the same
                    } else {
                        duringErrors.add(String.valueOf(e.getCause() != null ? e.getCause() : e));
                    }
                }
            } else {
                Thread.sleep(50);
            }
        }
        out.put("during_ms", duringMs).put("during_errors", duringErrors);
        out.put("refused", REFUSED.get());
        if (up != null) {
            TransferResult r = up.await(1, TimeUnit.SECONDS);
            result(out, "send", r, rate);
        }
        if (down != null) {
            TransferResult r = down.await(1, TimeUnit.SECONDS);
            result(out, "fetch", r, rate);
            File got = new File(a.get("dir"), a.get("fetch"));
            out.put("fetch_sha256", got.isFile() ? hex(sha(got)) : null);
        }
        garbageOn.set(false);
        if (sdk != null) {
            sdk.stopGarbage();
            DjiLink dji = (DjiLink) link;
            if (a.containsKey("stall")) {
                out.put("stalled_at_the_end", dji.isStalled());
                // the SDK came back: the command queue works again
                sdk.awaitRecovery();
                double ms = command(cq, 8000);
                out.put("after_stall_command_ms", ms);
            }
            // nothing more to send: every packet handed to the SDK is completed (or timed out)
            // within the completion timeout, so none is counted while still on the air
            sched.close();
            long settle = System.nanoTime() + 3_000_000_000L;
            while (dji.completed() + dji.timeouts() < dji.sent() && System.nanoTime() < settle) {
                Thread.sleep(10);
            }
            out.put("dji_sent", dji.sent()).put("dji_completed", dji.completed()).put("dji_timeouts", dji.timeouts())
                    .put("dji_stalled", dji.isStalled()).put("dji_received", dji.received())
                    .put("garbage_fed", sdk.garbage.get()).put("rx_bad_frames", prx.stats().badFrames());
        }
        out.put("scheduler_packets", sched.packets()).put("scheduler_errors", sched.sendErrors())
                .put("app_thread_errors", APP_THREAD_ERRORS.get()).put("uncaught", UNCAUGHT.get())
                .put("ignored", files.ignored());
        files.close();
        cq.close();
        sched.close();
        link.close();
        if (sdk != null) {
            sdk.close();
        }
        System.out.println("RESULT " + out);
        System.out.flush();
        System.exit(0);
    }

    static boolean allDone(List<Transfer> ts) {
        for (Transfer t : ts) {
            if (!t.isDone()) {
                return false;
            }
        }
        return true;
    }

    /**
     * SYNC_TIME: an action the onboard end always accepts (a TAKE_OFF repeated while flying is
     * DENIED, and a DENIED ack is a failure); command_id and time_usec left to the queue.
     */
    static SendTtActionCommand action() {
        return new SendTtActionCommand(1, 240, TtAction.TT_ACTION_SYNC_TIME, new float[4], new byte[48]);
    }

    static final AtomicInteger REFUSED = new AtomicInteger();

    /**
     * Whether a command's failure is the onboard end's answer (an ack that is not a yes: ttctl
     * recv-file carries out no commands and says UNSUPPORTED): a round trip all the same,
     * counted in "refused".
     */
    static boolean refusal(Exception e) {
        Throwable c = e.getCause();
        if (c instanceof CommandException && ((CommandException) c).reason() == CommandException.Reason.REFUSED) {
            REFUSED.incrementAndGet();
            return true;
        }
        return false;
    }

    /** One command's round trip in ms (answered yes or no), or -1 if it got no answer. */
    static double command(CommandQueue cq, long waitMs) {
        long t0 = System.nanoTime();
        try {
            cq.submit(action()).get(waitMs, TimeUnit.MILLISECONDS);
            return (System.nanoTime() - t0) / 1e6;
        } catch (Exception e) {
            if (refusal(e)) {
                return (System.nanoTime() - t0) / 1e6;
            }
            System.out.println("EVENT command failed: " + (e.getCause() != null ? e.getCause() : e));
            return -1;
        }
    }

    static Transfer.Listener listener(final String what) {
        return new Transfer.Listener() {
            long last;

            @Override
            public void onProgress(Transfer t, long done, long size) {
                if (done - last >= 8192 || done == size) {
                    last = done;
                    System.out.println("EVENT progress " + what + " " + done + "/" + size);
                }
            }

            @Override
            public void onComplete(Transfer t, TransferResult r) {
                System.out.println("EVENT done " + what + " " + r);
            }
        };
    }

    static void result(Json out, String what, TransferResult r, double rate) {
        if (r == null) {
            out.put(what + "_ok", false).put(what + "_code", "HANG");
            return;
        }
        out.put(what + "_ok", r.ok).put(what + "_code", r.code).put(what + "_message", r.message)
                .put(what + "_bytes", r.size).put(what + "_seconds", r.seconds).put(what + "_moved", r.bytesMoved)
                .put(what + "_sent", r.bytesSent)
                .put(what + "_retransmitted", r.bytesRetransmitted).put(what + "_resumed", r.resumedBytes)
                .put(what + "_efficiency", r.ok && r.seconds > 0 ? r.goodput() / rate : null)
                .put(what + "_deflated", r.deflatedSize);
    }

    static byte[] sha(File f) throws Exception {
        MessageDigest md = MessageDigest.getInstance("SHA-256");
        md.update(java.nio.file.Files.readAllBytes(f.toPath()));
        return md.digest();
    }

    static byte[] unhex(String h) {
        byte[] b = new byte[h.length() / 2];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) Integer.parseInt(h.substring(2 * i, 2 * i + 2), 16);
        }
        return b;
    }

    static String hex(byte[] b) {
        StringBuilder s = new StringBuilder();
        for (byte x : b) {
            s.append(String.format("%02x", x & 0xFF));
        }
        return s.toString();
    }

    /**
     * A fake DJI Mobile SDK: sendDataToOnboardSDKDevice forwards each packet over UDP at once
     * and confirms it on the "SDK thread" when its time on a link of `rate` B/s is over; the
     * data callback feeds what arrives to DjiLink.onDataFromOnboard from another thread.
     * stall=AFTER:LONG: AFTER ms after the first packet, swallow packets and never confirm them
     * for LONG ms.
     */
    static final class FakeSdk implements DjiLink.PacketSender {
        final DatagramSocket socket;
        final InetSocketAddress relay;
        final double rate;
        final ScheduledExecutorService sdkThread = Executors.newSingleThreadScheduledExecutor();
        final ScheduledExecutorService garbageThread = Executors.newSingleThreadScheduledExecutor();
        final AtomicLong garbage = new AtomicLong();
        final long stallAfter;
        final long stallFor;
        long firstSend;
        long busyUntil;
        volatile DjiLink link;
        volatile Signing signing; // frames for others are signed (they get past the signature check)
        volatile boolean closed;
        final Random rnd = new Random(7);

        FakeSdk(int relayPort, double rate, String stall) throws Exception {
            socket = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
            relay = new InetSocketAddress("127.0.0.1", relayPort);
            this.rate = rate;
            if (stall != null) {
                String[] p = stall.split(":");
                stallAfter = Long.parseLong(p[0]);
                stallFor = Long.parseLong(p[1]);
            } else {
                stallAfter = -1;
                stallFor = 0;
            }
        }

        boolean stalled(long now) {
            if (stallAfter < 0 || firstSend == 0) {
                return false;
            }
            long ms = (now - firstSend) / 1000000;
            return ms >= stallAfter && ms < stallAfter + stallFor;
        }

        void awaitRecovery() throws InterruptedException {
            while (stallAfter >= 0 && (firstSend == 0 || (System.nanoTime() - firstSend) / 1000000 < stallAfter + stallFor)) {
                Thread.sleep(50);
            }
        }

        @Override
        public synchronized void send(byte[] packet, DjiLink.Completion done) throws Exception {
            long now = System.nanoTime();
            if (firstSend == 0) {
                firstSend = now;
            }
            if (stalled(now)) {
                return; // the SDK swallows it and never calls back
            }
            socket.send(new DatagramPacket(packet, packet.length, relay));
            busyUntil = Math.max(now, busyUntil) + (long) (packet.length * 1e9 / rate);
            sdkThread.schedule(() -> {
                try {
                    done.done(null);
                } catch (Throwable e) {
                    APP_THREAD_ERRORS.incrementAndGet();
                    System.out.println("EVENT exception on the SDK thread: " + e);
                }
            }, busyUntil - now, TimeUnit.NANOSECONDS);
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
                    byte[] data = java.util.Arrays.copyOf(p.getData(), p.getLength());
                    try {
                        link.onDataFromOnboard(data);
                    } catch (Throwable e) {
                        APP_THREAD_ERRORS.incrementAndGet();
                        System.out.println("EVENT exception on the data callback thread: " + e);
                    }
                }
            }, "fake-dji-data-callback");
            t.setDaemon(true);
            t.start();
        }

        /** Garbage, frames for other systems and unknown transfers, fed as if from the drone. */
        void startGarbage() {
            garbageThread.scheduleAtFixedRate(() -> {
                try {
                    byte[] junk = new byte[1 + rnd.nextInt(100)];
                    rnd.nextBytes(junk);
                    if (rnd.nextBoolean()) {
                        junk[0] = (byte) 0xFD; // a plausible header start
                    }
                    link.onDataFromOnboard(junk);
                    TtFileStatus other = new TtFileStatus();
                    other.target_system = 77;
                    other.transfer_id = rnd.nextInt() & 0xFFFFFFFFL;
                    other.result = 1;
                    link.onDataFromOnboard(signed(other.pack(1, 1, 240)));
                    link.onDataFromOnboard(signed(new TtFileData(rnd.nextInt() & 0xFFFFFFFFL, 0, new byte[80])
                            .pack(2, 1, 240)));
                    link.onDataFromOnboard(signed(new TtCommandAck(77, 1, 5, 0, 0, 100).pack(3, 1, 240)));
                    link.onDataFromOnboard(null);
                    link.onDataFromOnboard(new byte[0]);
                    garbage.addAndGet(6);
                } catch (Throwable e) {
                    APP_THREAD_ERRORS.incrementAndGet();
                    System.out.println("EVENT exception feeding garbage: " + e);
                }
            }, 10, 50, TimeUnit.MILLISECONDS);
        }

        byte[] signed(byte[] frame) {
            Signing sg = signing;
            return sg == null ? frame : sg.sign(frame);
        }

        void stopGarbage() {
            garbageThread.shutdownNow();
        }

        void close() {
            closed = true;
            sdkThread.shutdownNow();
            garbageThread.shutdownNow();
            socket.close();
        }
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
                for (Object x : (List<?>) v) {
                    b.append(b.length() > 1 ? ", " : "").append(value(x));
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
