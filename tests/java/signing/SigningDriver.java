import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.runtime.Frame;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.PacketReceiver;
import ttctl.ttapi.runtime.Parser;
import ttctl.ttapi.runtime.Signing;

/**
 * Signing driver for tests/test_java_signing.py: one command a line on stdin, one answer line each.
 *
 * <pre>
 * NEW keyhex link allow(0|1) clock(sys|n)  -> OK           a new Signing (clock n: fixed at n)
 * CLOCK n                                  -> OK           moves the fixed clock
 * SIGN hex                                 -> SIGNED hex
 * CHECK hex                                -> RESULT OK|BAD_SIGNATURE|REPLAYED|UNSIGNED_REFUSED
 * PARSE hex / PARSE0 hex                   -> PARSED n badSignature msg...   (PARSE0: no Signing)
 * RECV pkt... / RECV0 pkt...               -> RECEIVED n badFrames msg...    (RECV0: no Signing)
 * BADKEY                                   -> BADKEY n     constructor calls refused with IllegalArgumentException
 * THREADS threads each                     -> THREADS distinct total verified
 * TS                                       -> TS timestamp
 * </pre>
 * msg: S|U msgid:seq:sysid:compid. Ends with "DONE".
 */
public final class SigningDriver {
    private static final AtomicLong FIXED = new AtomicLong(-1);
    private static Signing signing;
    private static byte[] key;

    private SigningDriver() {
    }

    public static void main(String[] args) throws Exception {
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.US_ASCII));
        PrintStream out = new PrintStream(System.out, false, "US-ASCII");
        String line;
        while ((line = in.readLine()) != null) {
            String[] t = line.trim().split(" ");
            if (t[0].isEmpty()) {
                continue;
            }
            try {
                out.println(run(t));
            } catch (Throwable e) {
                out.println("ERR " + e);
            }
        }
        out.println("DONE");
        out.flush();
    }

    private static String run(String[] t) throws Exception {
        switch (t[0]) {
            case "NEW":
                FIXED.set(t[4].equals("sys") ? -1 : Long.parseLong(t[4]));
                key = unhex(t[1]);
                signing = new Signing(key, Integer.parseInt(t[2]), t[3].equals("1"), () -> {
                    long f = FIXED.get();
                    return f < 0 ? Signing.now() : f;
                });
                return "OK";
            case "CLOCK":
                FIXED.set(Long.parseLong(t[1]));
                return "OK";
            case "SIGN":
                return "SIGNED " + hex(signing.sign(unhex(t[1])));
            case "CHECK": {
                byte[] f = unhex(t[1]);
                return "RESULT " + signing.check(f, 0, f.length);
            }
            case "PARSE":
            case "PARSE0": {
                Parser p = new Parser(Ttapi.INSTANCE, t[0].equals("PARSE") ? signing : null);
                List<MavlinkMessage> got = new ArrayList<>(p.feed(unhex(t[1])));
                got.addAll(p.flush());
                return "PARSED " + got.size() + " " + p.stats().badSignature() + messages(got);
            }
            case "RECV":
            case "RECV0": {
                PacketReceiver rx = new PacketReceiver(Ttapi.INSTANCE, t[0].equals("RECV") ? signing : null);
                List<MavlinkMessage> got = new ArrayList<>();
                for (int i = 1; i < t.length; i++) {
                    byte[] p = unhex(t[i]);
                    rx.feed(p, 0, p.length, got::add);
                }
                rx.flush(got::add);
                return "RECEIVED " + got.size() + " " + rx.stats().badFrames() + messages(got);
            }
            case "BADKEY":
                return "BADKEY " + badKeys();
            case "THREADS":
                return "THREADS " + threads(Integer.parseInt(t[1]), Integer.parseInt(t[2]));
            case "TS":
                return "TS " + signing.timestamp();
            default:
                return "ERR unknown command " + t[0];
        }
    }

    private static int badKeys() {
        int refused = 0;
        Object[][] calls = {{new byte[31], 0}, {new byte[33], 0}, {new byte[0], 0}, {new byte[32], 256}, {new byte[32], -1}};
        for (Object[] c : calls) {
            try {
                new Signing((byte[]) c[0], (Integer) c[1], false);
            } catch (IllegalArgumentException e) {
                refused++;
            }
        }
        return refused;
    }

    /** Signs from several threads at once: every timestamp distinct, every frame verifies. */
    private static String threads(int n, int each) throws InterruptedException {
        final byte[] unsigned = Frame.encode(new ttctl.ttapi.msg.Heartbeat(), 0, 1, 1);
        final List<byte[]> all = Collections.synchronizedList(new ArrayList<>());
        Thread[] ts = new Thread[n];
        for (int k = 0; k < n; k++) {
            ts[k] = new Thread(() -> {
                for (int i = 0; i < each; i++) {
                    all.add(signing.sign(unsigned));
                }
            });
            ts[k].start();
        }
        for (Thread th : ts) {
            th.join();
        }
        Set<Long> stamps = new HashSet<>();
        List<byte[]> sorted = new ArrayList<>(all);
        for (byte[] f : sorted) {
            stamps.add(timestamp(f));
        }
        sorted.sort((a, b) -> Long.compare(timestamp(a), timestamp(b)));
        Signing check = new Signing(key, signing.linkId(), false);
        int verified = 0;
        for (byte[] f : sorted) {
            if (check.check(f, 0, f.length) == Signing.Result.OK) {
                verified++;
            }
        }
        return stamps.size() + " " + all.size() + " " + verified;
    }

    private static long timestamp(byte[] f) {
        long ts = 0;
        for (int k = 5; k >= 0; k--) {
            ts = ts << 8 | (f[f.length - 12 + k] & 0xFF);
        }
        return ts;
    }

    private static String messages(List<MavlinkMessage> ms) {
        StringBuilder sb = new StringBuilder();
        for (MavlinkMessage m : ms) {
            sb.append(' ').append(m.signed() ? 'S' : 'U').append(m.msgId()).append(':').append(m.seq()).append(':')
                    .append(m.sysId()).append(':').append(m.compId());
        }
        return sb.toString();
    }

    private static String hex(byte[] b) {
        StringBuilder sb = new StringBuilder(2 * b.length);
        for (byte x : b) {
            sb.append(Character.forDigit((x >> 4) & 0xF, 16)).append(Character.forDigit(x & 0xF, 16));
        }
        return sb.toString();
    }

    private static byte[] unhex(String s) {
        byte[] b = new byte[s.length() / 2];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) Integer.parseInt(s.substring(2 * i, 2 * i + 2), 16);
        }
        return b;
    }
}
