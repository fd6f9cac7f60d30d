package ttctl.ttapi.transfer;

import java.io.File;
import java.io.FileOutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import ttctl.ttapi.msg.TtFileData;
import ttctl.ttapi.msg.TtFileStatus;
import ttctl.ttapi.runtime.MavlinkMessage;

/**
 * The Java FileSender under a rate grant on a virtual clock (in the transfer package: it is
 * package-private), on the script tests/test_java_grants.py plays to ttctl's Python sender: an
 * 8000-byte file at 500 B/s, told IN_PROGRESS with grant 50 at t = 0, asked for a frame every
 * 0.1 s until 8.4 s (room for one packet); deadlines at 8.1 s before and after a status at 8 s;
 * a new grant (100) at 8.5 s, then frames asked for every 0.1 s until 12 s. Prints the times
 * frames left, whether all were one-packet frames, and the deadlines, as JSON. Argument: a
 * folder for the file.
 */
public final class PaceCheck {
    private PaceCheck() {
    }

    static String num(double x) {
        return String.format(Locale.ROOT, "%.6f", x);
    }

    public static void main(String[] argv) throws Exception {
        File f = new File(argv[0], "x.bin");
        try (FileOutputStream out = new FileOutputStream(f)) {
            out.write(new byte[8000]);
        }
        TransferConfig cfg = new TransferConfig();
        cfg.frameMode = "auto";
        FileSender s = new FileSender(() -> 5, f, Names.sha256(f, -1), "x.bin", 1, 240, cfg, 0, false, 0.0, null);
        s.byteTime = 1.0 / 500;
        TtFileStatus status = new TtFileStatus();
        status.target_system = 255;
        status.target_component = 190;
        status.transfer_id = s.id;
        status.meta_check = s.check;
        status.rate_grant = 50;
        s.onStatus(0.0, status);
        List<String> sent = new ArrayList<>();
        boolean narrow = true;
        for (int k = 0; k < 85; k++) {
            double now = k / 10.0;
            MavlinkMessage m = s.nextData(now, 100);
            if (m != null) {
                sent.add(num(now));
                narrow &= m instanceof TtFileData;
            }
        }
        double quiet = s.deadline(8.1);
        s.onStatus(8.0, status);
        double heard = s.deadline(8.1);
        status.rate_grant = 100;
        s.onStatus(8.5, status);
        for (int k = 85; k <= 120; k++) {
            double now = k / 10.0;
            MavlinkMessage m = s.nextData(now, 100);
            if (m != null) {
                sent.add(num(now));
                narrow &= m instanceof TtFileData;
            }
        }
        System.out.println("{\"sent\": [" + String.join(", ", sent) + "], \"narrow\": " + narrow + ", \"quiet\": "
                + num(quiet) + ", \"heard\": " + num(heard) + ", \"after\": " + num(s.deadline(12.05)) + "}");
    }
}
