package ttctl.ttapi.transfer;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The Java runtime's rate-grant arithmetic (Sharing: the share of each transfer, the window a
 * transfer stays in the sharing set, a sender's pace under its grant) on the same inputs as
 * tests/test_java_grants.py gives ttctl's Python proto/sharing.py, so that the two can be
 * compared number for number. In the transfer package: Sharing is package-private. Prints one
 * line of JSON.
 */
public final class GrantCheck {
    private GrantCheck() {
    }

    static String num(double x) {
        return String.format(Locale.ROOT, "%.9f", x);
    }

    public static void main(String[] argv) {
        double[] capacities = {0, 1, 3, 99.9, 500, 4000, 6700, 8000, 1e5, 1e6, 2e7};
        List<String> shares = new ArrayList<>();
        for (double c : capacities) {
            for (int n = 0; n <= 9; n++) {
                shares.add("[" + num(c) + ", " + n + ", " + Sharing.share(c, n) + "]");
            }
        }
        List<String> windows = new ArrayList<>();
        for (int g : new int[] {0, 1, 7, 50, 133, 134, 1266, 65535}) {
            windows.add("[" + g + ", " + num(Sharing.window(g)) + "]");
        }
        // a sender's pace: [grant, now, frame bytes] per frame offered; [ready, nextFree] after each
        double[][] frames = {{0, 0.0, 100}, {1266, 0.0, 100}, {1266, 0.01, 100}, {1266, 0.08, 100},
            {1266, 0.5, 267}, {1266, 0.6, 100}, {1900, 0.7, 100}, {0, 0.71, 100}, {0, 0.72, 100}, {633, 0.73, 267},
            {633, 5.0, 100}};
        Sharing.Pacer p = new Sharing.Pacer();
        List<String> pace = new ArrayList<>();
        for (double[] f : frames) {
            p.update((int) f[0]);
            boolean ready = p.ready(f[1]);
            if (ready) {
                p.sent(f[1], (int) f[2]);
            }
            double at = p.readyAt();
            pace.add("[" + ready + ", " + (Double.isNaN(at) ? "null" : num(at)) + "]");
        }
        System.out.println("{\"share\": [" + String.join(", ", shares) + "], \"window\": [" + String.join(", ", windows)
                + "], \"pace\": [" + String.join(", ", pace) + "]}");
    }
}
