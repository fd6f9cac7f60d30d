package ttctl.ttapi.runtime;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;

import ttctl.ttapi.Ttapi;

/**
 * The Java bridge's MAVLink 1 codec (GcsV1), sans-IO, for tests/test_java_bridge_mavlink1.py to
 * compare with ttctl's Python one (wire/v1.py). One request a line, one answer a line:
 * "up HEX [v1]" (a datagram; v1: its station spoke MAVLink 1 before) -> "UP HEX upgraded badcrc
 * v2frames unknown unknownId"; "down HEX" -> "DOWN HEX" or "DOWN none".
 */
public final class V1Check {
    private V1Check() {
    }

    public static void main(String[] args) throws Exception {
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        String line;
        while ((line = in.readLine()) != null) {
            String[] w = line.trim().split(" ");
            byte[] b = unhex(w[1]);
            if (w[0].equals("up")) {
                GcsV1.Result r = GcsV1.upgrade(b, 0, b.length, Ttapi.INSTANCE, w.length > 2);
                System.out.println("UP " + hex(r.bytes) + " " + r.upgraded + " " + r.badCrc + " " + r.v2Frames + " "
                        + r.unknown + " " + r.unknownId);
            } else {
                byte[] d = GcsV1.downgrade(b, Ttapi.INSTANCE);
                System.out.println("DOWN " + (d == null ? "none" : hex(d)));
            }
            System.out.flush();
        }
    }

    static byte[] unhex(String s) {
        byte[] b = new byte[s.length() / 2];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) Integer.parseInt(s.substring(2 * i, 2 * i + 2), 16);
        }
        return b;
    }

    static String hex(byte[] b) {
        StringBuilder s = new StringBuilder();
        for (byte x : b) {
            s.append(String.format("%02x", x & 0xFF));
        }
        return s.length() == 0 ? "-" : s.toString();
    }
}
