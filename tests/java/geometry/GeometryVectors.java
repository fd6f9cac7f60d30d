package ttctl.ttapi.transfer;

import java.util.Locale;

/**
 * The Java runtime's Geometry as vectors for tests/test_java_geometry.py to hold to ttctl's
 * Python one (proto/transfer.py): one line per (mtu, signed), "G mtu signed fit narrowCap
 * narrowFrame wideFrame s(p)... | loss(x)...", or "REFUSED mtu signed" for a packet too small.
 */
public final class GeometryVectors {
    static final double[] P = {0.0, 0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.9};
    static final double[] X = {0.001, 0.05, 0.1, 0.3, 0.6, 0.95};

    private GeometryVectors() {
    }

    public static void main(String[] args) {
        StringBuilder out = new StringBuilder();
        for (int mtu = 13; mtu <= 300; mtu++) {
            for (int s = 0; s < 2; s++) {
                Geometry g;
                try {
                    g = new Geometry(mtu, s == 1);
                } catch (IllegalArgumentException e) {
                    out.append("REFUSED ").append(mtu).append(' ').append(s).append('\n');
                    continue;
                }
                out.append(String.format(Locale.ROOT, "G %d %d %d %d %d %d", mtu, s, g.fit ? 1 : 0, g.narrowCap,
                        g.narrowFrame, g.wideFrame));
                for (double p : P) {
                    out.append(' ').append(Double.toString(g.survivalWide(p)));
                }
                out.append(" |");
                for (double x : X) {
                    out.append(' ').append(Double.toString(g.packetLossFromWide(x)));
                }
                out.append('\n');
            }
        }
        System.out.print(out);
    }
}
