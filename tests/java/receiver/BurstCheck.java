package ttctl.ttapi.transfer;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.function.UnaryOperator;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.enums.TtFileFlags;
import ttctl.ttapi.msg.TtFileMap;
import ttctl.ttapi.msg.TtFileOffer;
import ttctl.ttapi.msg.TtFileStatus;
import ttctl.ttapi.runtime.LinkScheduler;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.Signing;
import ttctl.ttapi.runtime.UdpLink;

/**
 * The statuses a tablet's FileTransfers receiver says when the gaps are many, on a virtual clock
 * (in the transfer package: its receiver is package-private). Arguments: the inbox folder, the
 * link's packet size, "signed" or "unsigned", the number of gaps and optionally the link's rate
 * (B/s; it prints the receiver's status intervals first). A FileTransfers on a
 * LinkScheduler of that packet size over a UdpLink on 127.0.0.1 (signed like a Session: the signer
 * set first) takes an offer of a file whose first 16 MiB are lost and then every other 80-byte
 * frame (as many gaps in all as the argument says), and its
 * receiver's control() runs every 10 ms until t = 2 s. Prints each control() call that says
 * anything, as JSON lines: the time and per status the whole frame's length as the scheduler
 * places it in a packet (packed, then signed), range_count, region_start, received_end and the
 * ranges it lists. A sixth argument "map" sets TT_FILE_FLAGS_MAP on the offer (the sender reads
 * TT_FILE_MAP) and has the frames arrive from offset 0 (every other one): each TT_FILE_MAP is
 * printed too, with its region, chunk, flags and map in hex.
 */
public final class BurstCheck {
    private BurstCheck() {
    }

    public static void main(String[] argv) throws Exception {
        int mtu = Integer.parseInt(argv[1]);
        boolean signed = argv[2].equals("signed");
        int gaps = Integer.parseInt(argv[3]);
        // the data arrives past 16 MiB, every other frame: gaps [0, BASE) then one a frame wide between
        // frames, their offsets 4 bytes each on the wire (a status is longest when no zero byte truncates)
        boolean map = argv.length > 5 && argv[5].equals("map");
        long base = map ? 0 : 1L << 24; // (maps: from the first frame, so that their bits alternate)
        int frames = 2 * gaps - 1;
        long size = base + 80L * frames;
        byte[] meta = new byte[32 + "burst.bin".length()];
        new Random(7).nextBytes(meta);
        System.arraycopy("burst.bin".getBytes(StandardCharsets.US_ASCII), 0, meta, 32, "burst.bin".length());

        UdpLink udp = UdpLink.open("127.0.0.1", 0, "127.0.0.1", 9, Ttapi.INSTANCE);
        LinkScheduler sched = new LinkScheduler(udp, mtu, 0);
        if (signed) {
            final Signing signing = new Signing(new byte[32], 1, false);
            sched.setSigner(new UnaryOperator<byte[]>() {
                @Override
                public byte[] apply(byte[] frame) {
                    return signing.sign(frame);
                }
            });
        }
        FileTransfers ft = new FileTransfers(sched, 1, 240);
        if (argv.length > 4) { // the link's rate: how often statuses may go
            ft.setLinkRate(Double.parseDouble(argv[4]));
        }
        TransferConfig c = ft.receiver.cfg;
        System.out.println(String.format(Locale.ROOT, "{\"min\": %s, \"tail\": %s}",
                Double.toString(c.statusMinInterval), Double.toString(c.statusTailInterval)));
        ReceiveDir inbox = new ReceiveDir(new File(argv[0]), 1L << 30, 8L << 30, false);
        inbox.check();
        FileReceiver rx = ft.receiver;
        rx.inbox = inbox;
        long id = 99;
        for (int off = 0; off < meta.length; off += 71) {
            TtFileOffer m = new TtFileOffer();
            m.target_system = 1;
            m.target_component = 240;
            m.transfer_id = id;
            m.size = size;
            m.meta_length = meta.length;
            m.meta_offset = off;
            m.flags = map ? TtFileFlags.TT_FILE_FLAGS_MAP : 0;
            m.meta = new byte[71];
            System.arraycopy(meta, off, m.meta, 0, Math.min(71, meta.length - off));
            rx.onOffer(0.0, 255, 190, m);
        }
        for (int step = 0; step <= 200; step++) {
            double now = step / 100.0;
            if (step == 100) {
                for (int k = 0; k < frames; k += 2) {
                    rx.onData(now, 255, 190, id, base + 80L * k, new byte[80], Geometry.DATA_CAP, Geometry.DATA_FRAME);
                }
            }
            List<String> said = new ArrayList<>();
            for (MavlinkMessage m : rx.control(now)) {
                if (!(m instanceof TtFileMap) && !(m instanceof TtFileStatus)) {
                    continue;
                }
                byte[] frame = ft.encode(m);
                UnaryOperator<byte[]> sign = sched.signer();
                if (sign != null) {
                    frame = sign.apply(frame); // as the scheduler places it in a packet: packed, then signed
                }
                if (m instanceof TtFileMap) {
                    TtFileMap x = (TtFileMap) m;
                    StringBuilder bits = new StringBuilder();
                    for (byte b : x.map) {
                        bits.append(String.format(Locale.ROOT, "%02x", b & 0xFF));
                    }
                    said.add(String.format(Locale.ROOT, "{\"len\": %d, \"map\": \"%s\", \"region_start\": %d, "
                            + "\"received_end\": %d, \"received_contiguous\": %d, \"chunk\": %d, \"flags\": %d}",
                            frame.length, bits, x.region_start, x.received_end, x.received_contiguous, x.chunk, x.flags));
                    continue;
                }
                TtFileStatus s = (TtFileStatus) m;
                StringBuilder ranges = new StringBuilder();
                for (int i = 0; i < s.ranges.length; i++) {
                    ranges.append(i == 0 ? "" : ", ").append(s.ranges[i]);
                }
                said.add(String.format(Locale.ROOT, "{\"len\": %d, \"range_count\": %d, \"region_start\": %d, "
                        + "\"received_end\": %d, \"ranges\": [%s]}", frame.length, s.range_count, s.region_start,
                        s.received_end, ranges));
            }
            if (!said.isEmpty()) {
                System.out.println(String.format(Locale.ROOT, "{\"t\": %.2f, \"statuses\": [%s]}", now,
                        String.join(", ", said)));
            }
        }
        udp.close();
    }
}
