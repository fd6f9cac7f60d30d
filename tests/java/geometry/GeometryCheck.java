import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.security.MessageDigest;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.msg.TtFileData;
import ttctl.ttapi.msg.TtFileDataFit;
import ttctl.ttapi.msg.TtFileDataWide;
import ttctl.ttapi.runtime.Link;
import ttctl.ttapi.runtime.LinkScheduler;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.PacketReceiver;
import ttctl.ttapi.runtime.Signing;
import ttctl.ttapi.transfer.FileTransfers;
import ttctl.ttapi.transfer.Transfer;
import ttctl.ttapi.transfer.TransferConfig;
import ttctl.ttapi.transfer.TransferResult;

/**
 * The Java runtime's file-data frames follow the link's packet size (tests/test_java_geometry.py):
 * two FileTransfers, Java to Java, over an in-memory link of {@code mtu}-byte packets (signed or
 * not, with seeded loss); prints one line per case:
 * {@code CASE mtu=128 signed=0 mode=narrow ok=true sha=1 narrow=TT_FILE_DATA_FIT cap=107 ...}.
 *
 * Arguments: DIR, then cases as mtu:signed:mode:loss (e.g. 128:0:narrow:0.05).
 */
public final class GeometryCheck {
    /** One direction of the wire: packets of at most mtu bytes, lost with probability loss. */
    static final class Wire implements Link {
        final int mtu;
        final double loss;
        final Random random;
        final LinkedBlockingQueue<byte[]> air = new LinkedBlockingQueue<>();
        final AtomicInteger oversize = new AtomicInteger();
        final AtomicLong packets = new AtomicLong();

        Wire(int mtu, double loss, long seed) {
            this.mtu = mtu;
            this.loss = loss;
            this.random = new Random(seed);
        }

        @Override
        public int mtu() {
            return mtu;
        }

        @Override
        public synchronized void send(byte[] packet) {
            packets.incrementAndGet();
            if (packet.length > mtu) {
                oversize.incrementAndGet();
            }
            if (random.nextDouble() >= loss) {
                air.add(packet.clone());
            }
        }

        @Override
        public void close() {
        }
    }

    /** What the receiving end saw of the data frames. */
    static final class Seen {
        final AtomicLong data = new AtomicLong();
        final AtomicLong wide = new AtomicLong();
        final AtomicLong fit = new AtomicLong();
        final AtomicInteger maxFitCount = new AtomicInteger();
        final AtomicInteger minFitCount = new AtomicInteger(Integer.MAX_VALUE);
        final AtomicLong signedFrames = new AtomicLong();
    }

    static Thread deliver(Wire w, PacketReceiver rx, FileTransfers to, Seen seen) {
        Thread t = new Thread(() -> {
            try {
                while (true) {
                    byte[] p = w.air.poll(200, TimeUnit.MILLISECONDS);
                    List<MavlinkMessage> got = p == null ? rx.flush() : rx.feed(p);
                    for (MavlinkMessage m : got) {
                        if (seen != null) {
                            if (m instanceof TtFileData) {
                                seen.data.incrementAndGet();
                            } else if (m instanceof TtFileDataWide) {
                                seen.wide.incrementAndGet();
                            } else if (m instanceof TtFileDataFit) {
                                int c = ((TtFileDataFit) m).count;
                                seen.fit.incrementAndGet();
                                seen.maxFitCount.accumulateAndGet(c, Math::max);
                                seen.minFitCount.accumulateAndGet(c, Math::min);
                            }
                        }
                        to.accept(m);
                    }
                }
            } catch (InterruptedException e) {
                // done
            }
        }, "wire");
        t.setDaemon(true);
        t.start();
        return t;
    }

    public static void main(String[] args) throws Exception {
        File dir = new File(args[0]);
        byte[] key = new byte[32];
        Arrays.fill(key, (byte) 7);
        int n = 0;
        for (String c : Arrays.copyOfRange(args, 1, args.length)) {
            String[] f = c.split(":");
            int mtu = Integer.parseInt(f[0]);
            boolean signed = "1".equals(f[1]);
            String mode = f[2];
            double loss = Double.parseDouble(f[3]);
            n++;
            File src = new File(dir, "src" + n + ".bin");
            byte[] content = new byte[20000 + 37 * n];
            new Random(n).nextBytes(content);
            Files.write(src.toPath(), content);
            File inbox = new File(dir, "inbox" + n);
            Wire ab = new Wire(mtu, loss, 11 * n);
            Wire ba = new Wire(mtu, loss, 13 * n);
            LinkScheduler sa = new LinkScheduler(ab, 40000).start();
            LinkScheduler sb = new LinkScheduler(ba, 40000).start();
            Signing siga = signed ? new Signing(key, 1, false) : null;
            Signing sigb = signed ? new Signing(key, 2, false) : null;
            if (signed) {
                sa.setSigner(siga::sign);
                sb.setSigner(sigb::sign);
            }
            TransferConfig cfg = new TransferConfig();
            cfg.frameMode = mode;
            cfg.giveUpAfter = 20;
            FileTransfers a = new FileTransfers(sa, 255, 190, cfg).setLinkRate(40000).start();
            FileTransfers b = new FileTransfers(sb, 1, 240, cfg).setLinkRate(40000).start();
            b.acceptInto(inbox);
            Seen seen = new Seen();
            Thread t1 = deliver(ab, new PacketReceiver(Ttapi.INSTANCE, signed ? new Signing(key, 9, false) : null), b, seen);
            Thread t2 = deliver(ba, new PacketReceiver(Ttapi.INSTANCE, signed ? new Signing(key, 9, false) : null), a, null);
            long t0 = System.nanoTime();
            Transfer up = a.send(src, src.getName(), 1, 240, false, null);
            TransferResult r = up.await(120, TimeUnit.SECONDS);
            double secs = (System.nanoTime() - t0) / 1e9;
            File got = new File(inbox, src.getName());
            boolean same = got.isFile() && MessageDigest.isEqual(sha(got.toPath()), sha(src.toPath()));
            System.out.println(String.format(java.util.Locale.ROOT,
                    "CASE mtu=%d signed=%d mode=%s ok=%s sha=%d data=%d fit=%d wide=%d fitmax=%d fitmin=%d "
                            + "oversize=%d packets=%d secs=%.2f reason=%s",
                    mtu, signed ? 1 : 0, mode, r != null && r.ok, same ? 1 : 0, seen.data.get(), seen.fit.get(),
                    seen.wide.get(), seen.maxFitCount.get(), seen.fit.get() == 0 ? 0 : seen.minFitCount.get(),
                    ab.oversize.get() + ba.oversize.get(), ab.packets.get(), secs,
                    r == null ? "none" : String.valueOf(r.message).replace(' ', '_')));
            System.out.flush();
            t1.interrupt();
            t2.interrupt();
            a.close();
            b.close();
            sa.close();
            sb.close();
        }
    }

    static byte[] sha(java.nio.file.Path p) throws IOException {
        try {
            return MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(p));
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IOException(e);
        }
    }
}
