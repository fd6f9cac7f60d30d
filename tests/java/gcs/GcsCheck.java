import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.msg.CommandAck;
import ttctl.ttapi.msg.CommandLong;
import ttctl.ttapi.msg.FileTransferProtocol;
import ttctl.ttapi.msg.Heartbeat;
import ttctl.ttapi.msg.ManualControl;
import ttctl.ttapi.msg.ParamRequestRead;
import ttctl.ttapi.runtime.Frame;
import ttctl.ttapi.runtime.GcsBridge;
import ttctl.ttapi.runtime.GcsQuality;
import ttctl.ttapi.runtime.GcsResend;
import ttctl.ttapi.runtime.GcsRoutes;
import ttctl.ttapi.runtime.GcsRules;
import ttctl.ttapi.runtime.GcsUplink;
import ttctl.ttapi.runtime.Link;
import ttctl.ttapi.runtime.LinkScheduler;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.Parser;
import ttctl.ttapi.runtime.Signing;

/**
 * The ground-station bridge's rules without a vehicle (tests/test_java_bridge.py): the sans-IO
 * GcsUplink (classes, duplicates, bounds, the budget on a virtual clock), GcsQuality, and a
 * GcsBridge on a LinkScheduler whose link records its packets, with a UDP socket as the ground
 * station. Prints "FRAME name hex" lines for pymavlink to check, and "RESULT key=value ..." at
 * the end; exits 1 with "FAIL why" on the first rule broken.
 */
public final class GcsCheck {
    private static final List<String> RESULT = new ArrayList<>();

    private GcsCheck() {
    }

    static void check(boolean ok, String what) {
        if (!ok) {
            System.out.println("FAIL " + what);
            System.exit(1);
        }
    }

    static String hex(byte[] b) {
        StringBuilder s = new StringBuilder();
        for (byte x : b) {
            s.append(String.format(Locale.ROOT, "%02x", x & 0xFF));
        }
        return s.toString();
    }

    static byte[] command(int seq, int target, float p1) {
        CommandLong c = new CommandLong();
        c.target_system = target;
        c.target_component = 1;
        c.command = 400;
        c.param1 = p1;
        return c.pack(seq, 200, 190);
    }

    static byte[] manual(int seq, int sys, short x) {
        ManualControl m = new ManualControl();
        m.target = 1;
        m.x = x;
        return m.pack(seq, sys, 190);
    }

    static void uplink() {
        GcsUplink u = new GcsUplink(0, 100);
        check(u.offer(command(1, 1, 1f), 0) == GcsUplink.Offer.QUEUED, "a command queued");
        check(u.offer(command(2, 1, 1f), 0) == GcsUplink.Offer.DUPLICATE, "a retry (another seq) is a duplicate");
        check(u.offer(command(3, 1, 0f), 0) == GcsUplink.Offer.QUEUED, "another payload is not a duplicate");
        check(u.offer(manual(4, 200, (short) 1), 0) == GcsUplink.Offer.QUEUED, "manual control queued");
        check(u.offer(manual(5, 201, (short) 1), 0) == GcsUplink.Offer.QUEUED, "another source's slot");
        check(u.offer(manual(6, 200, (short) 2), 0) == GcsUplink.Offer.REPLACED, "a newer frame replaces the slot");
        check(u.waiting() == 4, "4 waiting, not " + u.waiting());
        check(GcsRules.msgId(u.pull(0)) == CommandLong.MSG_ID, "protocol first");
        check(GcsRules.msgId(u.pull(0)) == CommandLong.MSG_ID, "protocol first (2)");
        byte[] m = u.pull(0);
        check(GcsRules.msgId(m) == ManualControl.MSG_ID && m[5] == (byte) 201,
              "the oldest slot first: 201's (200's was replaced, its slot went behind)");
        m = u.pull(0);
        check(m[5] == (byte) 200 && m[4] == 6, "then 200's newest frame (seq 6)");
        check(u.pull(0) == null && u.waitingBytes() == 0, "empty");
        for (int i = 0; i < 100; i++) {
            u.offer(command(i, 1, i), 0);
            u.offer(manual(i, i, (short) i), 0);
        }
        check(u.waiting() == GcsUplink.PROTOCOL_LIMIT + GcsUplink.NEWEST_LIMIT, "bounded: " + u.waiting());
        check(u.overflow() == 72, "36 + 36 dropped, counted: " + u.overflow());
        check(GcsRules.msgId(u.pull(0)) == CommandLong.MSG_ID, "after overflow, a command");
        u.clear();
        // the budget: 300 B/s, burst 100; 30-byte frames offered as fast as they come for 10 s
        GcsUplink b = new GcsUplink(300, 100);
        long sent = 0;
        long t0 = 1_000_000_000L;
        for (long t = t0; t <= t0 + 10_000_000_000L; t += 1_000_000L) {
            b.offer(manual((int) t, 7, (short) (t / 1000)), t);
            byte[] f = b.pull(t);
            if (f != null) {
                sent += f.length;
            } else {
                check(b.readyAt(t) > t, "refused: ready later");
            }
        }
        check(sent >= 3000 && sent <= 3100 + 100, "budget 300 B/s x 10 s (+ a burst): " + sent);
        RESULT.add("budget_bytes=" + sent);
    }

    static void rules(Parser p) throws Exception {
        byte[] c = command(9, 7, 1f);
        check(GcsRules.targetSystem(c) == 7 && GcsRules.targetComponent(c) == 1, "COMMAND_LONG's targets");
        check(GcsRules.targetSystem(new Heartbeat().pack(0, 1, 1)) == -1, "HEARTBEAT has no target");
        byte[] moved = GcsRules.withSource(c, 254, CommandLong.CRC_EXTRA);
        MavlinkMessage m = Frame.decode(moved, Ttapi.INSTANCE);
        check(m.sysId() == 254 && m.compId() == 190 && m.seq() == 9, "re-sourced frame decodes");
        CommandAck ack = new CommandAck();
        ack.command = 400;
        ack.result = 0;
        ack.target_system = 254;
        ack.target_component = 190;
        byte[] back = GcsRules.withTargetSystem(ack.pack(3, 1, 1), 255, CommandAck.CRC_EXTRA);
        check(((CommandAck) Frame.decode(back, Ttapi.INSTANCE)).target_system == 255, "target given back");
        // without CRC_EXTRA (messages the dialect lacks): the same bytes as with it
        check(java.util.Arrays.equals(GcsRules.withByte(c, 5, 254), moved), "withByte re-sources as withSource");
        byte[] strange = GcsRules.withByte(GcsRules.withByte(c, 7, 52123 & 0xFF), 8, 52123 >> 8 & 0xFF);
        byte[] datagram = new byte[c.length * 2 + strange.length];
        System.arraycopy(c, 0, datagram, 0, c.length);
        System.arraycopy(strange, 0, datagram, c.length, strange.length);
        System.arraycopy(c, 0, datagram, c.length + strange.length, c.length);
        java.util.List<byte[]> found = GcsRules.unknownFrames(datagram, 0, datagram.length, Ttapi.INSTANCE);
        check(found.size() == 1 && java.util.Arrays.equals(found.get(0), strange), "the unknown frame between two known");
        byte[] signedStrange = new Signing(new byte[32], 1, false).sign(strange);
        found = GcsRules.unknownFrames(signedStrange, 0, signedStrange.length, Ttapi.INSTANCE);
        check(found.size() == 1 && java.util.Arrays.equals(found.get(0), strange), "a signed unknown frame, unsigned");
        byte[] back52123 = GcsRules.withByte(GcsRules.withByte(strange, 7, c[7] & 0xFF), 8, c[8] & 0xFF);
        check(java.util.Arrays.equals(back52123, c), "the msgid changed back: the CRC is the message's again");
        check(GcsRules.unknownFrames(strange, 0, strange.length - 1, Ttapi.INSTANCE).isEmpty(), "a cut frame is none");
        System.out.println("FRAME resourced " + hex(moved));
        System.out.println("FRAME retargeted " + hex(back));
        System.out.println("FRAME radio " + hex(GcsRules.radioStatus(5, 1, 229, 87, 70000, 3)));
        System.out.println("FRAME radio_zero " + hex(GcsRules.radioStatus(6, 1, 0, 0, 0, 0)));
        check(GcsQuality.txbuf(0) == 100 && GcsQuality.txbuf(64 * 60) == 0 && GcsQuality.txbuf(99999) == 0
              && GcsQuality.txbuf(64 * 30) == 50, "txbuf");
        GcsQuality q = new GcsQuality();
        long s = 1_000_000_000L;
        for (int i = 0; i < 100; i++) {
            if (i % 10 != 3) { // one in ten lost
                q.frame(1, 1, i, s + i * 40_000_000L);
            }
        }
        long end = s + 99 * 40_000_000L;
        check(q.lost() == 10 && Math.abs(q.rssi(end) - 229) <= 3, "rssi 254 x 0.9: " + q.rssi(end) + " lost " + q.lost());
        check(q.rssi(end + 3_600_000_000L) == 0, "silent 3.6 s: rssi 0");
        RESULT.add("rssi=" + q.rssi(end));
        GcsQuality late = new GcsQuality();
        int[] order = {1, 2, 4, 3, 5, 6, 6}; // 3 overtaken by 4, then 6 twice
        for (int k = 0; k < order.length; k++) {
            late.frame(1, 1, order[k], s + k * 100_000_000L);
        }
        check(late.lost() == 0 && late.rssi(s + 700_000_000L) == 254, "a late frame takes its loss back: " + late.lost());
    }

    /** GcsRoutes on a virtual clock: the clash remap, routing by target, forgetting, the bound. */
    static void routes() {
        GcsRoutes<String> r = new GcsRoutes<>(1, 255, 190);
        r.addFixed("qgc");
        check(r.destinations(-1, -1).size() == 1 && r.destinations(255, 190).isEmpty(), "a fixed one, unheard");
        check(r.heard("qgc", 255, 190, 0) == 254, "QGC's 255/190 carried as 254");
        check(r.heard("tool", 253, 190, 0) == 253, "others as they are");
        check(r.heard("second-qgc", 255, 190, 0) == 252, "a second 255/190: 254 carried, 253 heard: 252");
        check(r.heard("qgc", 255, 190, 1) == 254, "stable");
        List<GcsRoutes.Destination<String>> d = r.destinations(254, 190);
        check(d.size() == 1 && d.get(0).address.equals("qgc") && d.get(0).targetSystem == 255, "254 -> qgc as 255: " + d);
        d = r.destinations(252, 0);
        check(d.size() == 1 && d.get(0).address.equals("second-qgc") && d.get(0).targetSystem == 255, "252: " + d);
        d = r.destinations(253, 1);
        check(d.isEmpty(), "253/1 is nobody's: " + d);
        d = r.destinations(253, 190);
        check(d.size() == 1 && d.get(0).targetSystem == 0, "253/190 as it is: " + d);
        check(r.destinations(0, 0).size() == 3 && r.destinations(-1, -1).size() == 3, "broadcasts to all three");
        check(r.destinations(7, 1).isEmpty(), "for system 7: nobody");
        r.expire(GcsRoutes.FORGET_NANOS + 2);
        check(r.size() == 1 && r.all().get(0).equals("qgc"), "silent 30 s: forgotten, the fixed one kept: " + r.all());
        for (int i = 0; i < 40; i++) {
            r.heard("peer" + i, 10 + i, 1, 100 + i);
        }
        check(r.size() == GcsRoutes.MAX_STATIONS + 1 && r.all().contains("qgc") && r.all().contains("peer39")
              && !r.all().contains("peer0"), "at most 16 heard, the longest silent forgotten: " + r.size());
        GcsRoutes<String> crowded = new GcsRoutes<>(254, 255, 190);
        check(crowded.heard("q", 255, 190, 0) == 253, "never the vehicle's own id");
    }

    /** A link that keeps every packet the scheduler sends. */
    static final class Recording implements Link {
        final List<byte[]> packets = Collections.synchronizedList(new ArrayList<byte[]>());

        @Override
        public void send(byte[] packet) {
            packets.add(packet.clone());
        }

        @Override
        public void close() {
        }
    }

    static List<MavlinkMessage> sent(Recording link) {
        Parser p = new Parser(Ttapi.INSTANCE);
        List<MavlinkMessage> out = new ArrayList<>();
        synchronized (link.packets) {
            for (byte[] pk : link.packets) {
                out.addAll(p.feed(pk));
            }
        }
        return out;
    }

    static void bridge() throws Exception {
        Recording link = new Recording();
        LinkScheduler sched = new LinkScheduler(link, 0).start();
        final List<String> problems = Collections.synchronizedList(new ArrayList<String>());
        GcsBridge bridge = GcsBridge.start(link, sched, new GcsBridge.Config().listen("127.0.0.1", 0)
                .uplinkRate(10000).onProblem(problems::add));
        DatagramSocket gcs = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        gcs.setSoTimeout(3000);
        InetSocketAddress to = new InetSocketAddress("127.0.0.1", bridge.port());
        Heartbeat hb = new Heartbeat();
        hb.type = 6;
        hb.autopilot = 8;
        byte[] qgcHeartbeat = hb.pack(1, 255, 190); // QGC's default ids: the tablet's
        gcs.send(new DatagramPacket(qgcHeartbeat, qgcHeartbeat.length, to));
        ParamRequestRead prr = new ParamRequestRead();
        prr.target_system = 1;
        prr.target_component = 1;
        prr.param_index = -1;
        prr.param_id = "SYSID_THISMAV".getBytes("US-ASCII");
        prr.param_id = java.util.Arrays.copyOf(prr.param_id, 16);
        byte[] read = prr.pack(2, 255, 190);
        gcs.send(new DatagramPacket(read, read.length, to));
        gcs.send(new DatagramPacket(read, read.length, to)); // may be a duplicate if still waiting
        byte[] stranger = command(3, 7, 1f);
        stranger = GcsRules.withSource(stranger, 255, CommandLong.CRC_EXTRA);
        gcs.send(new DatagramPacket(stranger, stranger.length, to));
        byte[] garbage = "not mavlink at all \u00fd\u00fd".getBytes("ISO-8859-1");
        gcs.send(new DatagramPacket(garbage, garbage.length, to));
        long deadline = System.currentTimeMillis() + 3000;
        while (bridge.datagrams() < 5 && System.currentTimeMillis() < deadline) {
            Thread.sleep(10);
        }
        Thread.sleep(200);
        List<MavlinkMessage> up = sent(link);
        boolean sawHb = false;
        boolean sawRead = false;
        for (MavlinkMessage m : up) {
            check(m.sysId() == 254 && m.compId() == 190, "carried under 254/190: " + m.name() + " " + m.sysId());
            check(!(m instanceof CommandLong), "the command for system 7 is not carried");
            sawHb |= m instanceof Heartbeat;
            sawRead |= m instanceof ParamRequestRead;
        }
        check(sawHb && sawRead, "heartbeat and param read carried: " + up.size());
        check(bridge.notCarried() == 2 && bridge.unknown() == 1 && bridge.lastNotCarriedFor() == 7,
              "not carried: the stranger and the garbage: " + bridge);
        // down: the vehicle answers 254/190 (the clashing GCS) and broadcasts a heartbeat
        ttctl.ttapi.msg.ParamValue pv = new ttctl.ttapi.msg.ParamValue();
        pv.param_id = java.util.Arrays.copyOf("SYSID_THISMAV".getBytes("US-ASCII"), 16);
        pv.param_value = 1f;
        pv.param_count = 1;
        CommandAck ack = new CommandAck();
        ack.command = 400;
        ack.target_system = 254;
        ack.target_component = 190;
        CommandAck other = new CommandAck();
        other.command = 400;
        other.target_system = 9;
        other.target_component = 190;
        Heartbeat vhb = new Heartbeat();
        vhb.type = 2;
        vhb.autopilot = 12;
        for (byte[] f : new byte[][] {other.pack(20, 1, 1), ack.pack(21, 1, 1), vhb.pack(22, 1, 1), vhb.pack(23, 1, 240)}) {
            bridge.accept(Frame.decode(f, Ttapi.INSTANCE));
        }
        byte[] buf = new byte[300];
        List<MavlinkMessage> down = new ArrayList<>();
        Parser dp = new Parser(Ttapi.INSTANCE);
        long until = System.currentTimeMillis() + 1600;
        boolean radio = false;
        while (System.currentTimeMillis() < until && !(radio && down.size() >= 3)) {
            DatagramPacket p = new DatagramPacket(buf, buf.length);
            try {
                gcs.receive(p);
            } catch (SocketTimeoutException e) {
                break;
            }
            for (MavlinkMessage m : dp.feed(buf, 0, p.getLength())) {
                down.add(m);
                if (m.msgId() == GcsRules.RADIO_STATUS_ID) {
                    radio = true;
                    check(m.sysId() == 1 && m.compId() == 68, "RADIO_STATUS from 1/68");
                    System.out.println("FRAME radio_live " + hex(m.pack(m.seq(), m.sysId(), m.compId())));
                }
            }
        }
        check(radio, "RADIO_STATUS within 1.6 s");
        int acks = 0;
        int hbs = 0;
        for (MavlinkMessage m : down) {
            if (m instanceof CommandAck) {
                acks++;
                check(((CommandAck) m).target_system == 255 && m.seq() == 21, "the ack given back to 255, seq kept");
            }
            if (m instanceof Heartbeat) {
                hbs++;
                check(m.compId() == 1 && m.seq() == 22, "the vehicle's heartbeat, not the onboard end's");
            }
        }
        check(acks == 1 && hbs == 1, "one ack (not the one for system 9), one heartbeat: " + acks + " " + hbs);
        check(problems.isEmpty() && bridge.problem() == null, "no problem: " + problems);
        RESULT.add("carried=" + bridge.carried());
        RESULT.add("duplicates=" + bridge.duplicates());
        RESULT.add("notCarried=" + bridge.notCarried());
        RESULT.add("toGcs=" + bridge.toGcs());
        bridge.close();
        bridge.close();
        check(sched.queued() == 0, "scheduler left clean");
        // a port in use: start() throws, nothing half made
        DatagramSocket busy = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        try {
            GcsBridge.start(link, sched, new GcsBridge.Config().listen("127.0.0.1", busy.getLocalPort()));
            check(false, "a port in use must be refused");
        } catch (IOException e) {
            RESULT.add("busy=refused");
        }
        busy.close();
        sched.close();
        gcs.close();
    }

    /** On a signed link the scheduler signs the ground stations' frames as they leave (rule 6). */
    static void signed() throws Exception {
        final Signing signing = new Signing(Signing.keyFromPassphrase("our secret"), 1, false);
        Recording link = new Recording();
        LinkScheduler sched = new LinkScheduler(link, 0).setSigner(signing::sign).start();
        GcsBridge bridge = GcsBridge.start(link, sched, new GcsBridge.Config().listen("127.0.0.1", 0));
        DatagramSocket gcs = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        InetSocketAddress to = new InetSocketAddress("127.0.0.1", bridge.port());
        for (int i = 0; i < 3; i++) {
            byte[] f = command(i, 1, i); // unsigned from the ground station
            gcs.send(new DatagramPacket(f, f.length, to));
        }
        long deadline = System.currentTimeMillis() + 3000;
        while (bridge.carried() < 3 && System.currentTimeMillis() < deadline) {
            Thread.sleep(10);
        }
        Thread.sleep(100);
        Parser verifying = new Parser(Ttapi.INSTANCE, new Signing(Signing.keyFromPassphrase("our secret"), 2, false));
        int n = 0;
        synchronized (link.packets) {
            for (byte[] pk : link.packets) {
                for (MavlinkMessage m : verifying.feed(pk)) {
                    check(m.signed() && m instanceof CommandLong, "a signed command: " + m.name());
                    n++;
                }
            }
        }
        check(n == 3 && verifying.stats().badSignature() == 0, "3 commands signed and verified: " + n + " "
              + verifying.stats());
        RESULT.add("signed=" + n);
        bridge.close();
        sched.close();
        gcs.close();
    }

    static void refused(Runnable r, String what) {
        try {
            r.run();
        } catch (IllegalArgumentException e) {
            check(e.getMessage() != null && !e.getMessage().isEmpty(), what + ": said why");
            return;
        }
        check(false, what + " must be refused");
    }

    /** Bad settings are refused with words, at once. */
    static void config() {
        refused(() -> new GcsBridge.Config().share(0), "share 0");
        refused(() -> new GcsBridge.Config().share(1.5), "share 1.5");
        refused(() -> new GcsBridge.Config().listen(70000), "port 70000");
        refused(() -> new GcsBridge.Config().sendTo("127.0.0.1", 0), "sending to port 0");
        refused(() -> new GcsBridge.Config().vehicle(0), "vehicle 0");
        refused(() -> new GcsBridge.Config().tablet(256, 190), "tablet 256");
        refused(() -> new GcsBridge.Config().uplinkRate(-1), "a negative rate");
        refused(() -> new GcsBridge.Config().sendTo("no-such-host.invalid", 14550), "an unknown host");
    }

    /** A send the socket refuses is told, in words, to the problem listener and in problem(). */
    static void problems() throws Exception {
        Recording link = new Recording();
        LinkScheduler sched = new LinkScheduler(link, 0).start();
        final List<String> told = Collections.synchronizedList(new ArrayList<String>());
        // bound to loopback, sending elsewhere: the kernel refuses every send ("Invalid argument")
        GcsBridge bridge = GcsBridge.start(link, sched, new GcsBridge.Config().listen("127.0.0.1", 0)
                .sendTo("192.0.2.1", 14550).onProblem(told::add));
        long deadline = System.currentTimeMillis() + 4000;
        while (told.isEmpty() && System.currentTimeMillis() < deadline) {
            Thread.sleep(20);
        }
        check(told.size() == 1 && told.get(0).startsWith("sending to the ground station at 192.0.2.1:14550 failed: ")
              && bridge.problem() != null && bridge.sendErrors() >= 1, "told once: " + told + " " + bridge.problem());
        System.out.println("PROBLEM " + told.get(0));
        bridge.close();
        sched.close();
    }

    /** A MAVLink FTP frame (payload: seq, session 0, opcode, size, req_opcode, offset) from {@code from}. */
    static byte[] ftp(int seq, int opcode, int offset, int reqOpcode, int[] to, int[] from) {
        byte[] p = new byte[251];
        p[0] = (byte) seq;
        p[1] = (byte) (seq >>> 8);
        p[3] = (byte) opcode;
        p[4] = (byte) (opcode == 5 || opcode == 15 ? 239 : 0);
        p[5] = (byte) reqOpcode;
        for (int i = 0; i < 4; i++) {
            p[8 + i] = (byte) (offset >>> (8 * i));
        }
        return new FileTransferProtocol(0, to[0], to[1], p).pack(0, from[0], from[1]);
    }

    /**
     * GcsResend and MAVLink FTP (as tests/test_bridge_resend.py checks the Python bridge): a request
     * is followed from its station's own retry on, until the reply of seq + 1 for its opcode; a burst
     * read never.
     */
    static void ftpResend() {
        int[] station = {254, 190};
        int[] vehicle = {1, 1};
        long s = 1_000_000_000L;
        GcsResend r = new GcsResend();
        GcsUplink up = new GcsUplink(0, 100);
        byte[] read = ftp(24, 5, 4063, 0, vehicle, station);
        byte[] burst = ftp(2, 15, 0, 0, vehicle, station);
        r.request(read, FileTransferProtocol.CRC_EXTRA, 0);
        r.request(burst, FileTransferProtocol.CRC_EXTRA, 0);
        check(r.pending() == 0 && r.due(3 * s, up).isEmpty(), "an FTP request sent once is its station's business");
        r.request(read, FileTransferProtocol.CRC_EXTRA, 4 * s);
        r.request(burst, FileTransferProtocol.CRC_EXTRA, 4 * s);
        check(r.pending() == 1, "the station's retry of a read is followed, of a burst not: " + r.pending());
        List<byte[]> again = r.due(5 * s, up);
        check(again.size() == 1 && java.util.Arrays.equals(again.get(0), read), "the read is resent as it was");
        r.answer(ftp(24, 128, 3107, 5, station, vehicle), 6 * s); // the reply to seq 23
        r.answer(ftp(25, 128, 5258, 15, station, vehicle), 6 * s); // a burst's reply of seq 25
        check(r.pending() == 1, "another request's reply is not the answer");
        r.answer(ftp(25, 128, 4063, 5, station, vehicle), 6 * s);
        check(r.pending() == 0 && r.due(9 * s, up).isEmpty(), "the reply of seq + 1 to its opcode answers it");
        RESULT.add("ftp_resend=ok");
    }

    public static void main(String[] argv) throws Exception {
        config();
        uplink();
        rules(new Parser(Ttapi.INSTANCE));
        routes();
        bridge();
        signed();
        problems();
        ftpResend();
        System.out.println("RESULT " + String.join(" ", RESULT));
    }
}
