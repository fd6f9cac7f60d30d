package ttctl.ttapi.transfer;

import java.io.File;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import ttctl.ttapi.msg.TtFileOffer;
import ttctl.ttapi.msg.TtFileStatus;
import ttctl.ttapi.runtime.MavlinkMessage;

/**
 * The Java FileReceiver's rate grants on a virtual clock (in the transfer package: it is
 * package-private), on the script tests/test_java_grants.py plays to ttctl's Python receiver:
 * inbound capacity 500 B/s, four 4000-byte files offered at t = 0 from 255/190 (transfer ids
 * 34, 31, 33, 32: the statuses telling a grant go in key order), their data one 80-byte frame
 * each every 0.8 s (transfer 34's stops at 3 s: it leaves the sharing set), a 41-byte packet
 * of other traffic every 0.1 s from 5 s to 9 s, control() every 10 ms until 14 s. Prints every
 * status said as [time, transfer id, result, rate_grant], as JSON. Argument: the inbox folder.
 */
public final class ShareCheck {
    private ShareCheck() {
    }

    public static void main(String[] argv) throws Exception {
        FileReceiver rx = new FileReceiver(new TransferConfig(), 8, null);
        ReceiveDir inbox = new ReceiveDir(new File(argv[0]), 1L << 30, 8L << 30, false);
        inbox.check();
        rx.inbox = inbox;
        rx.statuses.inbound = 500;
        long[] ids = {34, 31, 33, 32};
        for (long id : ids) {
            byte[] file = new byte[4000];
            Arrays.fill(file, (byte) id);
            byte[] sha = MessageDigest.getInstance("SHA-256").digest(file);
            byte[] name = ("f" + id + ".bin").getBytes("UTF-8");
            byte[] meta = new byte[sha.length + name.length];
            System.arraycopy(sha, 0, meta, 0, sha.length);
            System.arraycopy(name, 0, meta, sha.length, name.length);
            TtFileOffer m = new TtFileOffer();
            m.target_system = 1;
            m.target_component = 240;
            m.transfer_id = id;
            m.size = file.length;
            m.meta_length = meta.length;
            m.meta_offset = 0;
            m.meta = Arrays.copyOf(meta, 71);
            rx.onOffer(0.0, 255, 190, m);
        }
        List<String> said = new ArrayList<>();
        for (int step = 0; step <= 1400; step++) {
            double now = step / 100.0;
            for (int k = 0; k < ids.length; k++) {
                long id = ids[k];
                if (step % 80 == 20 * k && step > 0 && !(id == 34 && step > 300)) {
                    long off = (step / 80) * 80L;
                    byte[] d = new byte[80];
                    Arrays.fill(d, (byte) id);
                    rx.statuses.load.packet(now, 100);
                    rx.onData(now, 255, 190, id, off, d, Geometry.DATA_CAP, Geometry.DATA_FRAME);
                }
            }
            if (step >= 500 && step <= 900 && step % 10 == 0) {
                rx.statuses.load.packet(now, 41);
            }
            for (MavlinkMessage m : rx.control(now)) {
                if (m instanceof TtFileStatus) {
                    TtFileStatus s = (TtFileStatus) m;
                    said.add(String.format(Locale.ROOT, "[%.2f, %d, %d, %d]", now, s.transfer_id, s.result,
                            s.rate_grant));
                }
            }
        }
        System.out.println("{\"statuses\": [" + String.join(", ", said) + "]}");
    }
}
