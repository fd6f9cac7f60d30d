import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.util.ArrayList;
import java.util.List;

import ttctl.ttapi.runtime.GcsDownloads;
import ttctl.ttapi.runtime.GcsMissions;
import ttctl.ttapi.runtime.GcsParamLists;
import ttctl.ttapi.runtime.GcsUplink;

/**
 * The Java bridge's mission and parameter protocols (GcsMissions, GcsDownloads, GcsParamLists and
 * the GcsUplink they wait in, in GcsProtocols' order) given a script on stdin;
 * tests/test_java_bridge.py plays the same one to the Python bridge's (ttctl/bridge/missions.py,
 * downloads.py, params.py, uplink.py). "budget B_PER_S BURST", then "gcs MICROS WHO HEX" (a
 * station's frame, carried as WHO = sys * 256 + comp), "veh MICROS HEX" (the vehicle's),
 * "tick MICROS", "pull MICROS". One line per step: what went on, what the stations were sent, what
 * was offered to the uplink (each frame described: id, source, its item / index), what was pulled.
 */
public final class ProtocolScript {
    private ProtocolScript() {
    }

    static int u8(byte[] f, int o) {
        return o < (f[1] & 0xFF) ? f[10 + o] & 0xFF : 0;
    }

    static int u16(byte[] f, int o) {
        return u8(f, o) | u8(f, o + 1) << 8;
    }

    /** id:sys/comp:field (item seq, count or index), :target for frames to a station. */
    static String describe(byte[] f) {
        int id = (f[7] & 0xFF) | (f[8] & 0xFF) << 8;
        int field = id == 73 || id == 39 ? u16(f, 28) : u16(f, 0);
        String s = id + ":" + (f[5] & 0xFF) + "/" + (f[6] & 0xFF) + ":" + field;
        if (id == 51 || id == 40) {
            s += ":" + u8(f, 2) + "/" + u8(f, 3) + ":" + u8(f, 4);
        }
        return s;
    }

    static String all(List<byte[]> fs) {
        StringBuilder b = new StringBuilder("[");
        for (byte[] f : fs) {
            b.append(b.length() > 1 ? "," : "").append(describe(f));
        }
        return b.append("]").toString();
    }

    public static void main(String[] argv) throws Exception {
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, "US-ASCII"));
        String[] head = in.readLine().split(" ");
        GcsUplink u = new GcsUplink(Double.parseDouble(head[1]), Integer.parseInt(head[2]));
        GcsMissions missions = new GcsMissions(1, u);
        GcsDownloads downloads = new GcsDownloads(1, u);
        GcsParamLists params = new GcsParamLists(1);
        StringBuilder out = new StringBuilder();
        String line;
        while ((line = in.readLine()) != null) {
            String[] w = line.split(" ");
            long now = Long.parseLong(w[1]) * 1000L;
            List<byte[]> st = new ArrayList<>();
            List<byte[]> up = new ArrayList<>();
            List<byte[]> first = new ArrayList<>();
            String fwd = "";
            if (w[0].equals("gcs")) {
                int who = Integer.parseInt(w[2]);
                byte[] f = UplinkScript.unhex(w[3]);
                int id = f[7] & 0xFF;
                boolean forward = !(id >= 39 && id <= 51 || id == 73) || downloads.fromGcs(now, f, who, st, first, up);
                for (int i = first.size() - 1; i >= 0; i--) {
                    u.offer(first.get(i), now, true);
                }
                if (forward) {
                    if (id == 21) {
                        params.request(now, who);
                    }
                    up.add(f);
                }
                for (byte[] x : up) {
                    u.offer(x, now);
                }
                if (forward) {
                    missions.fromGcs(now, f, who, st);
                }
                fwd = forward ? "1" : "0";
            } else if (w[0].equals("veh")) {
                byte[] f = UplinkScript.unhex(w[2]);
                int id = f[7] & 0xFF;
                boolean forward = true;
                if (id == 22) {
                    params.value(now, f);
                } else if (id == 39 || id == 40 || id == 44 || id == 47 || id == 51 || id == 73) {
                    int ts = id == 73 || id == 39 ? u8(f, 32) : id == 47 ? u8(f, 0) : u8(f, 2);
                    int tc = id == 73 || id == 39 ? u8(f, 33) : id == 47 ? u8(f, 1) : u8(f, 3);
                    int who = ts > 0 ? ts << 8 | tc : -1;
                    forward = missions.fromVehicle(now, f, who, first, st);
                    for (int i = first.size() - 1; i >= 0; i--) {
                        u.offer(first.get(i), now, true);
                    }
                    List<byte[]> lost = new ArrayList<>();
                    forward = downloads.fromVehicle(now, f, who, lost, up) && forward;
                    for (int i = lost.size() - 1; i >= 0; i--) {
                        u.offer(lost.get(i), now, true);
                    }
                    first.addAll(lost);
                    for (byte[] x : up) {
                        u.offer(x, now);
                    }
                }
                fwd = forward ? "1" : "0";
            } else if (w[0].equals("tick")) {
                missions.tick(now, first);
                for (int i = first.size() - 1; i >= 0; i--) {
                    u.offer(first.get(i), now, true);
                }
                missions.ahead(now, st);
                params.tick(now, up);
                for (byte[] x : up) {
                    u.offer(x, now);
                }
            } else {
                byte[] f = u.pull(now);
                out.append("pull ").append(f == null ? "-" : describe(f)).append('\n');
                continue;
            }
            out.append(fwd).append(" st").append(all(st)).append(" first").append(all(first)).append(" up")
                    .append(all(up)).append('\n');
        }
        out.append("resent ").append(missions.resent()).append(" swallowed ").append(missions.swallowed())
                .append(" answered ").append(downloads.answered()).append(" read ").append(params.read()).append('\n');
        System.out.print(out);
    }
}
