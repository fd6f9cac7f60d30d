import java.io.BufferedReader;
import java.io.InputStreamReader;

import ttctl.ttapi.runtime.GcsQuality;

/**
 * The Java GcsQuality given a script on stdin (tests/test_java_bridge.py plays the same one to the
 * Python bridge's Routes): "frame MICROS COMPID SEQ" (a frame of the vehicle, system 1, arrived),
 * "rssi MICROS" (RADIO_STATUS is due: prints the rssi), "txbuf BYTES" (prints txbuf); at the end
 * "lost N received N".
 */
public final class QualityScript {
    private QualityScript() {
    }

    public static void main(String[] argv) throws Exception {
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, "US-ASCII"));
        GcsQuality q = new GcsQuality();
        StringBuilder out = new StringBuilder();
        String line;
        while ((line = in.readLine()) != null) {
            String[] w = line.split(" ");
            if (w[0].equals("frame")) {
                q.frame(1, Integer.parseInt(w[2]), Integer.parseInt(w[3]), Long.parseLong(w[1]) * 1000L);
            } else if (w[0].equals("rssi")) {
                out.append(q.rssi(Long.parseLong(w[1]) * 1000L)).append('\n');
            } else {
                out.append(GcsQuality.txbuf(Integer.parseInt(w[1]))).append('\n');
            }
        }
        out.append("lost ").append(q.lost()).append(" received ").append(q.received()).append('\n');
        System.out.print(out);
    }
}
