import java.io.BufferedReader;
import java.io.InputStreamReader;

import ttctl.ttapi.runtime.GcsUplink;

/**
 * The Java GcsUplink given a script on stdin (tests/test_java_bridge.py plays the same one to the
 * Python bridge's uplink): "budget B_PER_S BURST", then "put MICROS HEX" (a frame offered) and
 * "pull MICROS" (the scheduler asks). Prints one line per step: the offer's verdict in lower case;
 * the frame pulled in hex, or "- READY_MICROS" (when the next may go, -1: nothing waits).
 */
public final class UplinkScript {
    private UplinkScript() {
    }

    static byte[] unhex(String s) {
        byte[] b = new byte[s.length() / 2];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) Integer.parseInt(s.substring(2 * i, 2 * i + 2), 16);
        }
        return b;
    }

    public static void main(String[] argv) throws Exception {
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, "US-ASCII"));
        String[] head = in.readLine().split(" ");
        GcsUplink u = new GcsUplink(Double.parseDouble(head[1]), Integer.parseInt(head[2]));
        StringBuilder out = new StringBuilder();
        String line;
        while ((line = in.readLine()) != null) {
            String[] w = line.split(" ");
            long now = Long.parseLong(w[1]) * 1000L;
            if (w[0].equals("put")) {
                out.append(u.offer(unhex(w[2]), now).name().toLowerCase(java.util.Locale.ROOT)).append('\n');
            } else {
                byte[] f = u.pull(now);
                if (f != null) {
                    StringBuilder h = new StringBuilder();
                    for (byte x : f) {
                        h.append(String.format("%02x", x & 0xFF));
                    }
                    out.append(h).append('\n');
                } else {
                    long at = u.readyAt(now);
                    out.append("- ").append(at < 0 ? -1 : (at + 999) / 1000).append('\n');
                }
            }
        }
        out.append("overflow ").append(u.overflow()).append(" duplicates ").append(u.duplicates()).append(" replaced ")
                .append(u.replaced()).append('\n');
        System.out.print(out);
    }
}
