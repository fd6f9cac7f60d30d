import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.runtime.DjiLink;
import ttctl.ttapi.runtime.UdpForward;

/**
 * The tablet's side of a real-link measurement, with the SDK replaced by a UDP socket to
 * `ttctl link relay` (the emulated radio): sendDataToOnboardSDKDevice sends one datagram and
 * completes, setOnboardSDKDeviceDataCallback is what that socket receives. A UdpForward on the
 * DjiLink listens on an ephemeral port, printed as "ready PORT"; it runs until stdin closes.
 */
public final class ForwardDriver {
    public static void main(String[] args) throws Exception {
        final InetSocketAddress relay = new InetSocketAddress("127.0.0.1", Integer.parseInt(args[0]));
        final DatagramSocket radio = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        final DjiLink link = new DjiLink((packet, done) -> {
            radio.send(new DatagramPacket(packet, packet.length, relay));
            done.done(null);
        }, Ttapi.INSTANCE);
        Thread rx = new Thread(() -> {
            byte[] buf = new byte[2048];
            while (!radio.isClosed()) {
                DatagramPacket p = new DatagramPacket(buf, buf.length);
                try {
                    radio.receive(p);
                } catch (java.io.IOException e) {
                    return;
                }
                byte[] data = java.util.Arrays.copyOf(p.getData(), p.getLength());
                link.onDataFromOnboard(data);
            }
        }, "radio-rx");
        rx.setDaemon(true);
        rx.start();
        try (UdpForward fwd = new UdpForward(link, new InetSocketAddress("127.0.0.1", 0))) {
            System.out.println("ready " + fwd.port());
            System.out.flush();
            while (System.in.read() >= 0) {
                // until stdin closes
            }
            System.out.println("up " + fwd.forwardedUp() + " down " + fwd.forwardedDown() + " dropped "
                               + fwd.dropped());
        }
        radio.close();
        link.close();
    }
}
