import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.PacketReceiver;
import ttctl.ttapi.runtime.Packetizer;

/**
 * Equivalence driver for tests/test_java_packets.py: reads cases, one a line, on stdin and prints
 * one result line per case, in the format tests/java/packets/oracle.py prints for the Python
 * Packetizer and PacketReceiver.
 *
 * <pre>
 * P mtu frame...      -> P token-per-add flush-token        token: packets (hex, comma-joined)/pending
 * R packet...         -> R token-per-packet flush-token stats   token: frames/pending
 * </pre>
 * A packet "-" is empty; a frame out is S or U (signed or not) + hex of its unsigned re-encoding.
 * Odd-numbered packets are fed from the middle of a larger array to exercise off/len. Ends with
 * "DONE".
 */
public final class PacketsDriver {
    private PacketsDriver() {
    }

    public static void main(String[] args) throws Exception {
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.US_ASCII));
        PrintStream out = new PrintStream(System.out, false, "US-ASCII");
        String line;
        while ((line = in.readLine()) != null) {
            line = line.trim();
            if (line.isEmpty()) {
                continue;
            }
            String[] t = line.split(" ");
            try {
                if (t[0].equals("P")) {
                    out.println(packetize(t));
                } else if (t[0].equals("R")) {
                    out.println(receive(t));
                } else {
                    out.println("ERR unknown case " + t[0]);
                }
            } catch (Throwable e) {
                out.println("ERR " + e);
            }
        }
        out.println("DONE");
        out.flush();
    }

    private static String packetize(String[] t) {
        Packetizer p = new Packetizer(Integer.parseInt(t[1]));
        StringBuilder sb = new StringBuilder("P");
        final List<byte[]> got = new ArrayList<>();
        for (int i = 2; i < t.length; i++) {
            byte[] f = unhex(t[i]);
            if (i % 2 == 1) {
                byte[] big = new byte[f.length + 7];
                System.arraycopy(f, 0, big, 3, f.length);
                p.add(big, 3, f.length, got::add);
            } else {
                p.add(f, got::add);
            }
            sb.append(' ').append(packets(got)).append('/').append(p.pending());
            got.clear();
        }
        p.flush(got::add);
        sb.append(' ').append(packets(got)).append('/').append(p.pending());
        return sb.toString();
    }

    private static String receive(String[] t) {
        PacketReceiver rx = new PacketReceiver(Ttapi.INSTANCE);
        StringBuilder sb = new StringBuilder("R");
        final List<MavlinkMessage> got = new ArrayList<>();
        for (int i = 1; i < t.length; i++) {
            byte[] p = t[i].equals("-") ? new byte[0] : unhex(t[i]);
            int n;
            if (i % 2 == 1) {
                byte[] big = new byte[p.length + 9];
                for (int k = 0; k < big.length; k++) {
                    big[k] = (byte) 0xFD; // magic bytes around the packet must not leak in
                }
                System.arraycopy(p, 0, big, 5, p.length);
                n = rx.feed(big, 5, p.length, got::add);
            } else {
                List<MavlinkMessage> l = rx.feed(p);
                got.addAll(l);
                n = l.size();
            }
            if (n != got.size()) {
                throw new IllegalStateException("feed returned " + n + " for " + got.size() + " messages");
            }
            sb.append(' ').append(messages(got)).append('/').append(rx.pending());
            got.clear();
        }
        got.addAll(rx.flush());
        sb.append(' ').append(messages(got)).append('/').append(rx.pending());
        PacketReceiver.Stats s = rx.stats();
        sb.append(' ').append(s.packets()).append(':').append(s.frames()).append(':').append(s.badFrames()).append(':')
                .append(s.carriesDropped()).append(':').append(s.rescans()).append(':').append(s.unknown());
        return sb.toString();
    }

    private static String packets(List<byte[]> ps) {
        StringBuilder sb = new StringBuilder();
        for (byte[] p : ps) {
            if (sb.length() > 0) {
                sb.append(',');
            }
            sb.append(hex(p));
        }
        return sb.toString();
    }

    private static String messages(List<MavlinkMessage> ms) {
        StringBuilder sb = new StringBuilder();
        for (MavlinkMessage m : ms) {
            if (sb.length() > 0) {
                sb.append(',');
            }
            sb.append(m.signed() ? 'S' : 'U').append(hex(m.pack(m.seq(), m.sysId(), m.compId())));
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
