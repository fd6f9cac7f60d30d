import java.io.File;
import java.util.concurrent.TimeUnit;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.runtime.LinkScheduler;
import ttctl.ttapi.runtime.Signing;
import ttctl.ttapi.runtime.UdpLink;
import ttctl.ttapi.transfer.FileTransfers;
import ttctl.ttapi.transfer.Transfer;
import ttctl.ttapi.transfer.TransferConfig;
import ttctl.ttapi.transfer.TransferResult;

/**
 * The Java sender of tests/test_java_geometry.py's cross run: one file over a UdpLink of
 * {@code mtu}-byte packets (signed with a 64-hex-digit key, or "-" for none) to a ttctl
 * recv-file at 1/240. Arguments: PORT MTU KEY RATE FILE. Prints "RESULT ok=... message".
 */
public final class GeometrySender {
    private GeometrySender() {
    }

    public static void main(String[] a) throws Exception {
        int port = Integer.parseInt(a[0]);
        int mtu = Integer.parseInt(a[1]);
        Signing signing = "-".equals(a[2]) ? null : new Signing(unhex(a[2]), 1, false);
        double rate = Double.parseDouble(a[3]);
        File f = new File(a[4]);
        UdpLink udp = UdpLink.open("127.0.0.1", 0, "127.0.0.1", port, Ttapi.INSTANCE);
        if (signing != null) {
            udp.close();
            udp = new UdpLink(new java.net.DatagramSocket(new java.net.InetSocketAddress("127.0.0.1", 0)),
                    new java.net.InetSocketAddress("127.0.0.1", port), Ttapi.INSTANCE, signing);
        }
        udp.setLearnsRemote(false);
        udp.setMtu(mtu);
        LinkScheduler sched = new LinkScheduler(udp, rate).start();
        if (signing != null) {
            sched.setSigner(signing::sign);
        }
        TransferConfig cfg = new TransferConfig();
        cfg.giveUpAfter = 30;
        FileTransfers files = new FileTransfers(sched, 255, 190, cfg).setCompress(false).start();
        udp.addListener(files);
        udp.start();
        Transfer t = files.send(f, f.getName(), 1, 240, false, null);
        TransferResult r = t.await(120, TimeUnit.SECONDS);
        System.out.println("RESULT ok=" + (r != null && r.ok) + " " + (r == null ? "no result" : r.message));
        files.close();
        sched.close();
        udp.close();
    }

    static byte[] unhex(String s) {
        byte[] b = new byte[s.length() / 2];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) Integer.parseInt(s.substring(2 * i, 2 * i + 2), 16);
        }
        return b;
    }
}
