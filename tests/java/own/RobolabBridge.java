import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;

import ttctl.robolab.Robolab;
import ttctl.robolab.runtime.GcsBridge;
import ttctl.robolab.runtime.Session;
import ttctl.robolab.runtime.UdpLink;

/**
 * The tablet app of tests/test_java_bridge_dialect.py: the robolab dialect's generated runtime,
 * a Session on a UdpLink to the vehicle (through `ttctl link relay`) and a GcsBridge listening
 * for ground stations on 127.0.0.1:LISTEN_PORT. Arguments: LINK_PORT LISTEN_PORT RATE. Prints
 * "ready"; each line read prints "STATS {bridge}"; end of input closes both and prints "closed".
 */
public final class RobolabBridge {
    private RobolabBridge() {
    }

    public static void main(String[] argv) throws Exception {
        UdpLink link = new UdpLink(new DatagramSocket(new InetSocketAddress("127.0.0.1", 0)),
                new InetSocketAddress("127.0.0.1", Integer.parseInt(argv[0])), Robolab.INSTANCE);
        Session.Options o = new Session.Options();
        o.rate = Double.parseDouble(argv[2]);
        Session session = new Session(link, 255, 190, o).start();
        GcsBridge bridge = GcsBridge.start(session, new GcsBridge.Config().listen("127.0.0.1",
                Integer.parseInt(argv[1])).onProblem(p -> System.out.println("PROBLEM " + p)));
        System.out.println("ready");
        System.out.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, "UTF-8"));
        while (in.readLine() != null) {
            System.out.println("STATS " + bridge + " notCarried " + bridge.notCarried() + " unknown "
                    + bridge.unknown() + " unknownCarried " + bridge.unknownCarried() + " fromVehicle " + bridge.fromVehicle());
            System.out.flush();
        }
        bridge.close();
        session.close();
        System.out.println("closed");
        System.out.flush();
    }
}
