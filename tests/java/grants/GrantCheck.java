package ttctl.ttapi.transfer;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import ttctl.ttapi.msg.TtFileData;
import ttctl.ttapi.msg.TtFileDataWide;
import ttctl.ttapi.msg.TtFileStatus;

/**
 * The Java runtime's rate-grant arithmetic (Sharing: the share of each transfer with the other
 * traffic measured, when a new share is told, the stagger of the statuses that tell it, the other
 * traffic meter, the window a transfer stays in the sharing set, a sender's pace under its
 * grant, re-anchored by a new one) on the same inputs as
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
        double[] others = {0, 7.5, 40, 100, 333.3, 1e4};
        for (double c : capacities) {
            for (int n = 0; n <= 9; n++) {
                for (double o : others) {
                    shares.add("[" + num(c) + ", " + n + ", " + num(o) + ", " + Sharing.share(c, n, o) + "]");
                }
            }
        }
        // re-grant: [old, new, kept]; stagger: [grant, n, step]
        List<String> keeps = new ArrayList<>();
        int[] grants = {0, 1, 9, 10, 11, 100, 109, 110, 111, 633, 1266, 65535};
        for (int a : grants) {
            for (int b : grants) {
                keeps.add("[" + a + ", " + b + ", " + Sharing.keeps(a, b) + "]");
            }
        }
        List<String> steps = new ArrayList<>();
        for (int g : grants) {
            for (int n = 2; n <= 5; n++) {
                steps.add("[" + g + ", " + n + ", " + num(Sharing.step(g, n, Geometry.DTT_MTU)) + "]");
            }
        }
        // the other-traffic meter: [time, bytes (+ packet, - data frame)]; other B/s after each
        double[][] traffic = {{0.0, 100}, {0.0, -100}, {0.5, 40}, {1.0, 267}, {1.0, -267}, {2.0, 21}, {4.9, 35},
            {5.0, 100}, {5.6, 12}, {7.0, 100}, {7.0, -100}, {9.99, 0}, {12.5, 30}, {20.0, 0}};
        Sharing.Load load = new Sharing.Load();
        List<String> loads = new ArrayList<>();
        for (double[] e : traffic) {
            if (e[1] >= 0) {
                load.packet(e[0], (int) e[1]);
            } else {
                load.data(e[0], (int) -e[1]);
            }
            loads.add(num(load.other(e[0])));
        }
        List<String> windows = new ArrayList<>();
        for (int g : new int[] {0, 1, 7, 50, 133, 134, 1266, 65535}) {
            windows.add("[" + g + ", " + num(Sharing.window(g, Geometry.DTT_MTU)) + "]");
        }
        // a sender's pace: [grant, now, frame bytes] per frame offered; [ready, nextFree] after each
        double[][] frames = {{0, 0.0, 100}, {1266, 0.0, 100}, {1266, 0.01, 100}, {1266, 0.08, 100},
            {1266, 0.5, 267}, {1266, 0.6, 100}, {1900, 0.7, 100}, {0, 0.71, 100}, {0, 0.72, 100}, {633, 0.73, 267},
            {633, 5.0, 100}};
        Sharing.Pacer p = new Sharing.Pacer();
        List<String> pace = new ArrayList<>();
        for (double[] f : frames) {
            p.update((int) f[0], f[1]);
            boolean ready = p.ready(f[1]);
            if (ready) {
                p.sent(f[1], (int) f[2]);
            }
            double at = p.readyAt();
            pace.add("[" + ready + ", " + (Double.isNaN(at) ? "null" : num(at)) + "]");
        }
        // what the router counts of each frame coming in: [narrow, wide, a short status, a signed narrow]
        byte[] full = new byte[255];
        Arrays.fill(full, (byte) 7);
        TtFileStatus status = new TtFileStatus();
        status.transfer_id = 9;
        TtFileData signed = new TtFileData(9, 80, Arrays.copyOf(full, 80));
        signed.setHeader(0, 1, 1, true);
        String wire = "[" + TransferRouter.wireLength(new TtFileData(9, 0, Arrays.copyOf(full, 80))) + ", "
                + TransferRouter.wireLength(new TtFileDataWide(9, 0, full)) + ", " + TransferRouter.wireLength(status)
                + ", " + TransferRouter.wireLength(signed) + "]";
        System.out.println("{\"wire\": " + wire + ", \"share\": [" + String.join(", ", shares) + "], \"window\": [" + String.join(", ", windows)
                + "], \"pace\": [" + String.join(", ", pace) + "], \"keeps\": [" + String.join(", ", keeps)
                + "], \"step\": [" + String.join(", ", steps) + "], \"load\": [" + String.join(", ", loads) + "]}");
    }
}
