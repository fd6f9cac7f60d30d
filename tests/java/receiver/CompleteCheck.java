package ttctl.ttapi.transfer;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;

import ttctl.ttapi.enums.TtFileResult;
import ttctl.ttapi.msg.TtFileOffer;
import ttctl.ttapi.msg.TtFileStatus;
import ttctl.ttapi.runtime.MavlinkMessage;

/**
 * The Java FileReceiver without a network, on a virtual clock (in the transfer package: it is
 * package-private): a 200-byte file is offered into the inbox (argument: its folder), its data
 * arrives at t = 1 s, and the receiver's control() runs every 10 ms until t = 4 s. Prints the
 * times of the COMPLETE statuses it said, as JSON: ttctl's Python receiver says COMPLETE three
 * times, 50 ms apart, so that a lost packet does not leave the sender recording a delivered,
 * verified file as failed.
 */
public final class CompleteCheck {
    private CompleteCheck() {
    }

    public static void main(String[] argv) throws Exception {
        byte[] file = new byte[200];
        new Random(5).nextBytes(file);
        byte[] sha = MessageDigest.getInstance("SHA-256").digest(file);
        byte[] name = "a.bin".getBytes(StandardCharsets.UTF_8);
        byte[] meta = new byte[sha.length + name.length];
        System.arraycopy(sha, 0, meta, 0, sha.length);
        System.arraycopy(name, 0, meta, sha.length, name.length);
        FileReceiver rx = new FileReceiver(new TransferConfig(), 8, null);
        ReceiveDir inbox = new ReceiveDir(new File(argv[0]), 1L << 30, 8L << 30, false);
        inbox.check();
        rx.inbox = inbox;
        long id = 77;
        for (int off = 0; off < meta.length; off += 71) {
            TtFileOffer m = new TtFileOffer();
            m.target_system = 1;
            m.target_component = 240;
            m.transfer_id = id;
            m.size = file.length;
            m.meta_length = meta.length;
            m.meta_offset = off;
            m.meta = new byte[71];
            System.arraycopy(meta, off, m.meta, 0, Math.min(71, meta.length - off));
            rx.onOffer(0.0, 255, 190, m);
        }
        List<String> complete = new ArrayList<>();
        for (int step = 0; step <= 400; step++) {
            double now = step / 100.0;
            if (step == 100) {
                for (int off = 0; off < file.length; off += 80) {
                    byte[] d = new byte[80];
                    System.arraycopy(file, off, d, 0, Math.min(80, file.length - off));
                    rx.onData(now, 255, 190, id, off, d, Geometry.DATA_CAP, Geometry.DATA_FRAME);
                }
            }
            for (MavlinkMessage m : rx.control(now)) {
                if (m instanceof TtFileStatus && ((TtFileStatus) m).result == TtFileResult.TT_FILE_RESULT_COMPLETE) {
                    complete.add(String.format(Locale.ROOT, "%.2f", now));
                }
            }
        }
        boolean there = new File(argv[0], "a.bin").isFile();
        System.out.println("{\"complete\": [" + String.join(", ", complete) + "], \"file\": " + there + "}");
    }
}
