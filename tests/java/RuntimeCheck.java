import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.enums.MavSysStatusSensor;
import ttctl.ttapi.enums.TtAction;
import ttctl.ttapi.enums.TtVrButtons;
import ttctl.ttapi.msg.Heartbeat;
import ttctl.ttapi.msg.SystemTime;
import ttctl.ttapi.msg.TtActionCommand;
import ttctl.ttapi.msg.TtCommandAck;
import ttctl.ttapi.msg.TtFileDataWide;
import ttctl.ttapi.msg.TtLog;
import ttctl.ttapi.msg.TtVrPose;
import ttctl.ttapi.runtime.Crc;
import ttctl.ttapi.runtime.DecodeException;
import ttctl.ttapi.runtime.Dispatcher;
import ttctl.ttapi.runtime.Frame;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.MessageMatcher;
import ttctl.ttapi.runtime.Parser;
import ttctl.ttapi.runtime.Unsigned;

/**
 * Test driver for the generated ttapi runtime (run by tests/test_gen_java.py): Parser resync on
 * split, lost and corrupted chunks, Dispatcher semantics, Frame errors and helpers. Prints one
 * "ok" line per check; exits 1 on the first failure.
 */
public final class RuntimeCheck {
    private static int checks;

    private RuntimeCheck() {
    }

    static void check(boolean condition, String what) {
        if (!condition) {
            System.out.println("FAIL " + what);
            System.exit(1);
        }
    }

    static void ok(String what) {
        checks++;
        System.out.println("ok " + what);
    }

    /**
     * Frames of assorted messages (some truncated), every 7th signed if asked. Loss tests use
     * unsigned frames only: signatures are not verified, so a signed frame that lost signature
     * bytes still decodes and takes 13 bytes of what follows as its signature.
     */
    static List<byte[]> frames(Random rnd, int count, boolean signed) {
        List<byte[]> out = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            MavlinkMessage m;
            switch (i % 5) {
                case 0:
                    Heartbeat hb = new Heartbeat();
                    hb.type = rnd.nextInt(256);
                    hb.custom_mode = rnd.nextInt() & 0xFFFFFFFFL;
                    m = hb;
                    break;
                case 1:
                    TtLog log = new TtLog();
                    log.time_boot_ms = rnd.nextInt() & 0xFFFFFFFFL;
                    log.setTextString("line " + i + " \u00e9\u4e2d");
                    m = log;
                    break;
                case 2:
                    TtActionCommand cmd = new TtActionCommand();
                    cmd.command_id = rnd.nextInt(65536);
                    cmd.time_usec = rnd.nextLong();
                    cmd.param[rnd.nextInt(4)] = rnd.nextFloat();
                    m = cmd;
                    break;
                case 3:
                    TtVrPose pose = new TtVrPose();
                    pose.time_usec = rnd.nextLong();
                    pose.position[0] = rnd.nextFloat();
                    pose.orientation[3] = 1f;
                    m = pose;
                    break;
                default:
                    SystemTime t = new SystemTime();
                    t.time_unix_usec = i;
                    m = t;
                    break;
            }
            byte[] f = m.pack(i, 1 + rnd.nextInt(255), rnd.nextInt(256));
            if (signed && i % 7 == 6) { // signed: flag set, CRC recomputed, 13 signature bytes appended
                f[2] = 1;
                int plen = f[1] & 0xFF;
                int crc = Frame.checksum(f, 0, plen, m.crcExtra());
                f[10 + plen] = (byte) crc;
                f[11 + plen] = (byte) (crc >>> 8);
                byte[] s = Arrays.copyOf(f, f.length + 13);
                for (int k = f.length; k < s.length; k++) {
                    s[k] = (byte) rnd.nextInt(256);
                }
                f = s;
            }
            out.add(f);
        }
        return out;
    }

    static byte[] concat(List<byte[]> frames) {
        int n = 0;
        for (byte[] f : frames) {
            n += f.length;
        }
        byte[] out = new byte[n];
        int o = 0;
        for (byte[] f : frames) {
            System.arraycopy(f, 0, out, o, f.length);
            o += f.length;
        }
        return out;
    }

    /** Re-packs a parsed message the way it came (same header) and compares with the frame. */
    static boolean same(MavlinkMessage m, byte[] frame) {
        byte[] again = m.pack(m.seq(), m.sysId(), m.compId());
        if (m.signed()) {
            byte[] unsigned = Arrays.copyOf(frame, frame.length - 13);
            unsigned[2] = 0;
            int plen = unsigned[1] & 0xFF;
            int crc = Frame.checksum(unsigned, 0, plen, m.crcExtra());
            unsigned[10 + plen] = (byte) crc;
            unsigned[11 + plen] = (byte) (crc >>> 8);
            return Arrays.equals(again, unsigned);
        }
        return Arrays.equals(again, frame);
    }

    static List<MavlinkMessage> feedInChunks(Parser p, byte[] data, Random rnd, int maxChunk) {
        List<MavlinkMessage> got = new ArrayList<>();
        int o = 0;
        while (o < data.length) {
            int n = Math.min(data.length - o, 1 + rnd.nextInt(maxChunk));
            got.addAll(p.feed(data, o, n));
            o += n;
        }
        return got;
    }

    static void parserSplits() {
        Random rnd = new Random(1);
        List<byte[]> frames = frames(rnd, 40, true);
        byte[] stream = concat(frames);
        for (int chunk : new int[] {1, 2, 3, 7, 12, 13, 64, 1000, stream.length}) {
            Parser p = new Parser(Ttapi.INSTANCE);
            List<MavlinkMessage> got = feedInChunks(p, stream, new Random(chunk), chunk);
            check(got.size() == frames.size(), "split " + chunk + ": " + got.size() + " of " + frames.size());
            for (int i = 0; i < got.size(); i++) {
                check(same(got.get(i), frames.get(i)), "split " + chunk + ": frame " + i + " differs");
            }
            check(p.pending() == 0 && p.stats().badCrc() == 0 && p.stats().skippedBytes() == 0,
                    "split " + chunk + ": " + p.stats());
        }
        ok("parser: frames split into chunks of any size are all decoded, byte-exact");
    }

    /** Frames wholly outside [from, to) of the stream, in order. */
    static List<byte[]> untouched(List<byte[]> frames, int from, int to) {
        List<byte[]> keep = new ArrayList<>();
        int o = 0;
        for (byte[] f : frames) {
            int end = o + f.length;
            if (end <= from || o >= to) {
                keep.add(f);
            }
            o = end;
        }
        return keep;
    }

    static void expectExactly(List<MavlinkMessage> got, List<byte[]> want, String what) {
        check(got.size() == want.size(), what + ": got " + got.size() + " messages, want " + want.size());
        for (int i = 0; i < want.size(); i++) {
            check(same(got.get(i), want.get(i)), what + ": message " + i + " differs");
        }
    }

    static void parserLostChunks() {
        Random rnd = new Random(2);
        for (int trial = 0; trial < 300; trial++) {
            List<byte[]> frames = frames(rnd, 12, false);
            byte[] stream = concat(frames);
            int from = rnd.nextInt(stream.length);
            int to = Math.min(stream.length, from + 1 + rnd.nextInt(120));
            byte[] lossy = new byte[stream.length - (to - from)];
            System.arraycopy(stream, 0, lossy, 0, from);
            System.arraycopy(stream, to, lossy, from, stream.length - to);
            Parser p = new Parser(Ttapi.INSTANCE);
            List<MavlinkMessage> got = feedInChunks(p, lossy, rnd, 1 + rnd.nextInt(80));
            got.addAll(p.flush());
            expectExactly(got, untouched(frames, from, to), "lost [" + from + "," + to + ") trial " + trial);
            check(p.pending() == 0, "lost chunk: flush left bytes");
        }
        ok("parser: a lost chunk costs only the frames that overlapped it (300 trials)");
    }

    static void parserCorruptedChunks() {
        Random rnd = new Random(3);
        for (int trial = 0; trial < 300; trial++) {
            List<byte[]> frames = frames(rnd, 12, false);
            byte[] stream = concat(frames);
            int from = rnd.nextInt(stream.length);
            int to = Math.min(stream.length, from + 1 + rnd.nextInt(40));
            for (int i = from; i < to; i++) {
                stream[i] ^= (byte) (1 + rnd.nextInt(255));
            }
            Parser p = new Parser(Ttapi.INSTANCE);
            List<MavlinkMessage> got = feedInChunks(p, stream, rnd, 1 + rnd.nextInt(80));
            got.addAll(p.flush());
            expectExactly(got, untouched(frames, from, to), "corrupted [" + from + "," + to + ") trial " + trial);
        }
        ok("parser: a corrupted chunk costs only the frames that overlapped it (300 trials)");
    }

    static void parserStaleHead() {
        // a stale magic claiming a long payload of a known message must not hold back the frames behind it
        Random rnd = new Random(4);
        List<byte[]> frames = frames(rnd, 3, false);
        int wide = TtFileDataWide.MSG_ID;
        byte[] head = new byte[] {(byte) 0xFD, (byte) TtFileDataWide.PAYLOAD_LENGTH, 0, 0, 0, 1, 1, (byte) wide,
            (byte) (wide >>> 8), (byte) (wide >>> 16)};
        byte[] stream = concat(frames);
        byte[] data = new byte[head.length + stream.length];
        System.arraycopy(head, 0, data, 0, head.length);
        System.arraycopy(stream, 0, data, head.length, stream.length);
        Parser p = new Parser(Ttapi.INSTANCE);
        List<MavlinkMessage> got = p.feed(data);
        check(got.size() < frames.size(), "stale head: expected frames held back before flush");
        got.addAll(p.flush());
        expectExactly(got, frames, "stale head then flush");
        // garbage and unknown ids are skipped and counted
        p = new Parser(Ttapi.INSTANCE);
        byte[] junk = new byte[] {1, 2, 3, (byte) 0xFD, 5, 0, 0, 0, 1, 1, (byte) 0xEE, (byte) 0xEE, (byte) 0xEE, 0, 0, 0};
        byte[] mixed = new byte[junk.length + stream.length];
        System.arraycopy(junk, 0, mixed, 0, junk.length);
        System.arraycopy(stream, 0, mixed, junk.length, stream.length);
        expectExactly(p.feed(mixed), frames, "junk first");
        check(p.stats().unknown() == 1 && p.stats().skippedBytes() == junk.length && p.stats().messages() == 3,
                "junk stats " + p.stats());
        ok("parser: stale heads wait only until flush(); junk and unknown ids are skipped and counted");
    }

    static void dispatcher() throws InterruptedException {
        Dispatcher d = new Dispatcher(Runnable::run); // handlers on the caller's thread
        final List<String> calls = new ArrayList<>();
        final List<Throwable> errors = new ArrayList<>();
        d.setErrorListener(new Dispatcher.ErrorListener() {
            @Override
            public void onError(MavlinkMessage msg, Throwable error) {
                errors.add(error);
            }
        });
        d.on(Heartbeat.MSG_ID, Heartbeat.class, new Dispatcher.Handler<Heartbeat>() {
            @Override
            public void handle(Heartbeat msg) {
                calls.add("first:" + msg.type);
                throw new IllegalStateException("boom");
            }
        });
        Dispatcher.Registration second = d.on(Heartbeat.MSG_ID, Heartbeat.class, new Dispatcher.Handler<Heartbeat>() {
            @Override
            public void handle(Heartbeat msg) {
                calls.add("second:" + msg.type);
            }
        });
        d.on(TtCommandAck.MSG_ID, new Dispatcher.Handler<MavlinkMessage>() {
            @Override
            public void handle(MavlinkMessage msg) {
                calls.add("ack");
            }
        });
        d.onAny(new Dispatcher.Handler<MavlinkMessage>() {
            @Override
            public void handle(MavlinkMessage msg) {
                calls.add("any:" + msg.name());
            }
        });
        Heartbeat hb = new Heartbeat();
        hb.type = 7;
        int called = d.dispatch(hb);
        check(called == 3, "dispatch count " + called);
        check(calls.equals(Arrays.asList("first:7", "second:7", "any:HEARTBEAT")), "order " + calls);
        check(errors.size() == 1 && d.errors() == 1 && "boom".equals(errors.get(0).getMessage()), "errors " + errors);
        calls.clear();
        second.remove();
        d.accept(hb);
        check(calls.equals(Arrays.asList("first:7", "any:HEARTBEAT")), "after remove " + calls);
        calls.clear();
        d.accept(new SystemTime());
        check(calls.equals(Arrays.asList("any:SYSTEM_TIME")), "other id " + calls);
        ok("dispatcher: two handlers on one msgid in order, a throwing one does not stop the other");

        // the default: accept() hands messages to the dispatcher's own thread, in order
        Dispatcher own = new Dispatcher();
        final List<String> seen = java.util.Collections.synchronizedList(new ArrayList<String>());
        final Thread caller = Thread.currentThread();
        own.onAny(new Dispatcher.Handler<MavlinkMessage>() {
            @Override
            public void handle(MavlinkMessage msg) throws InterruptedException {
                Thread.sleep(100); // a slow handler
                seen.add(msg.name() + (Thread.currentThread() == caller ? "@caller" : ""));
            }
        });
        long t0 = System.nanoTime();
        own.accept(hb);
        own.accept(new SystemTime());
        long took = (System.nanoTime() - t0) / 1000000;
        check(took < 50 && seen.isEmpty(), "accept returned at once: " + took + " ms " + seen);
        while (seen.size() < 2 && (System.nanoTime() - t0) / 1000000 < 3000) {
            Thread.sleep(5);
        }
        check(seen.equals(Arrays.asList("HEARTBEAT", "SYSTEM_TIME")), "handled in order, off the caller: " + seen);
        own.close();
        ok("dispatcher: accept() returns at once, handlers run on the dispatcher's thread in order");
    }

    static void frameErrors() {
        byte[] f = new TtCommandAck().pack(0, 1, 1);
        check(f.length == 13, "all-zero payload truncated to one byte: " + f.length);
        String[] expect = {"truncated", "after the frame", "bad magic", "bad CRC", "unknown msgid", "at least 12"};
        byte[][] bad = new byte[6][];
        bad[0] = Arrays.copyOf(f, f.length - 1);
        bad[1] = Arrays.copyOf(f, f.length + 1);
        bad[2] = f.clone();
        bad[2][0] = (byte) 0xFE;
        bad[3] = f.clone();
        bad[3][12] ^= 1;
        bad[4] = f.clone();
        bad[4][9] = 0x7F;
        bad[5] = new byte[] {(byte) 0xFD, 0};
        for (int i = 0; i < bad.length; i++) {
            try {
                Frame.decode(bad[i], Ttapi.INSTANCE);
                check(false, "decoded bad frame " + i);
            } catch (DecodeException e) {
                check(e.getMessage().contains(expect[i]), "error " + i + ": " + e.getMessage());
            }
        }
        ok("frame: truncated, trailing, bad magic, bad CRC, unknown msgid and short frames are refused");
    }

    static void crcExtraOverTruncatedLength() {
        // MAVLink 2 CRC covers the truncated payload only (then CRC_EXTRA)
        TtCommandAck ack = new TtCommandAck();
        ack.command_id = 0x1234;
        byte[] f = ack.pack(0, 1, 1);
        int plen = f[1] & 0xFF;
        check(plen < TtCommandAck.PAYLOAD_LENGTH, "payload truncated");
        int crc = Crc.accumulate(Crc.compute(f, 1, 9 + plen), TtCommandAck.CRC_EXTRA);
        check(((f[f.length - 2] & 0xFF) | (f[f.length - 1] & 0xFF) << 8) == crc, "crc over truncated payload");
        check(Crc.compute("123456789".getBytes(java.nio.charset.StandardCharsets.US_ASCII), 0, 9) == 0x6F91,
                "CRC-16/MCRF4XX check value");
        ok("crc: MCRF4XX check value; frame CRC over the truncated payload then CRC_EXTRA");
    }

    static void helpers() {
        String[] u = {"0", "1", "9223372036854775807", "9223372036854775808", "18446744073709551615"};
        for (String s : u) {
            check(Unsigned.toString(Unsigned.parse(s)).equals(s), "unsigned " + s);
        }
        for (String s : new String[] {"", "-1", "18446744073709551616", "99999999999999999999", "1x", "+"}) {
            try {
                Unsigned.parse(s);
                check(false, "parsed " + s);
            } catch (NumberFormatException expected) {
                // refused
            }
        }
        check(Unsigned.compare(-1L, 1L) > 0 && Unsigned.compare(1L, 2L) < 0, "unsigned compare");
        check("TT_ACTION_LAND".equals(TtAction.name(TtAction.TT_ACTION_LAND)) && TtAction.name(9999) == null,
                "enum name");
        check("TT_VR_BUTTONS_TRIGGER|TT_VR_BUTTONS_GRIP|0x100".equals(TtVrButtons.flags(1 | 16 | 256)),
                "bitmask flags " + TtVrButtons.flags(1 | 16 | 256));
        check(MavSysStatusSensor.name(2147483648L) != null, "long enum values");
        TtLog log = new TtLog();
        log.setTextString("h\u00e9llo \u4e16\u754c");
        check("h\u00e9llo \u4e16\u754c".equals(log.getTextString()), "UTF-8 text helpers");
        try {
            log.setTextString(new String(new char[81]).replace('\0', 'x'));
            check(false, "81 bytes in char[80]");
        } catch (IllegalArgumentException expected) {
            // refused
        }
        Heartbeat hb = new Heartbeat();
        check(hb.mavlink_version == Ttapi.VERSION, "mavlink_version default");
        hb.type = 256;
        try {
            hb.pack(0, 1, 1);
            check(false, "uint8 256 packed");
        } catch (IllegalArgumentException e) {
            check(e.getMessage().contains("HEARTBEAT.type"), "range error names the field: " + e.getMessage());
        }
        TtCommandAck ack = new TtCommandAck();
        ack.command_id = 5;
        MessageMatcher m = MessageMatcher.of(TtCommandAck.MSG_ID, TtCommandAck.class, a -> a.command_id == 5);
        check(m.matches(ack) && !m.matches(new Heartbeat()), "matcher");
        check(Ttapi.INSTANCE.info("TT_COMMAND_ACK").msgId() == TtCommandAck.MSG_ID
                && Ttapi.create("TT_COMMAND_ACK") instanceof TtCommandAck && Ttapi.create("NOPE") == null, "registry");
        check(ack.toString().contains("command_id=5"), "toString " + ack);
        ok("helpers: Unsigned, enum lookups, text helpers, range checks, matcher, registry");
    }

    public static void main(String[] args) throws InterruptedException {
        parserSplits();
        parserLostChunks();
        parserCorruptedChunks();
        parserStaleHead();
        dispatcher();
        frameErrors();
        crcExtraOverTruncatedLength();
        helpers();
        System.out.println("DONE " + checks + " checks");
    }
}
