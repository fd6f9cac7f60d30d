import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.msg.CommandAck;
import ttctl.ttapi.msg.FlightInformation;
import ttctl.ttapi.runtime.GcsBridge;
import ttctl.ttapi.runtime.Link;
import ttctl.ttapi.runtime.LinkScheduler;
import ttctl.ttapi.runtime.MavlinkMessage;
import ttctl.ttapi.runtime.Parser;

/**
 * A GcsBridge on a recording link and a MAVLink 1 ground station (a UDP socket sending the
 * pymavlink frames it is given as hex) for tests/test_java_bridge_mavlink1.py. Arguments:
 * HEARTBEAT_V1_HEX UNKNOWN_V1_HEX. Prints "UPLINK hex" for every frame the bridge put on the
 * link, "STATION hex" for every datagram the station got, "PROBLEM words" for each onProblem,
 * and "DONE v1up=.. v1down=.. v1dropped=..".
 */
public final class V1BridgeCheck {
    private V1BridgeCheck() {
    }

    public static void main(String[] args) throws Exception {
        List<byte[]> onLink = Collections.synchronizedList(new ArrayList<>());
        Link link = new Link() {
            @Override
            public void send(byte[] packet) {
                onLink.add(packet.clone());
            }

            @Override
            public void close() {
            }
        };
        LinkScheduler sched = new LinkScheduler(link, 0).start();
        DatagramSocket station = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        station.setSoTimeout(200);
        List<String> problems = Collections.synchronizedList(new ArrayList<>());
        GcsBridge bridge = GcsBridge.start(link, sched, new GcsBridge.Config()
                .sendTo("127.0.0.1", station.getLocalPort()).onProblem(problems::add));
        InetSocketAddress to = new InetSocketAddress("127.0.0.1", bridge.port());
        byte[] hb = unhex(args[0]);
        station.send(new DatagramPacket(hb, hb.length, to));
        long end = System.nanoTime() + 10_000_000_000L;
        // until the HEARTBEAT is on the link, as a vehicle's answer can come only after that: the
        // count goes up as the datagram is read, the station's route only as its frame is queued
        while ((bridge.v1Up() < 1 || onLink.isEmpty()) && System.nanoTime() < end) {
            Thread.sleep(10);
        }
        byte[] unknown = unhex(args[1]);
        station.send(new DatagramPacket(unknown, unknown.length, to));
        // the vehicle answers: a COMMAND_ACK (MAVLink 1 has it) and a FLIGHT_INFORMATION (id 264: it has not)
        bridge.accept(fromVehicle(new CommandAck(400, 0, 0, 0, 246, 190), 7));
        bridge.accept(fromVehicle(new FlightInformation(), 8));
        List<String> got = new ArrayList<>();
        end = System.nanoTime() + 2_500_000_000L; // a RADIO_STATUS comes within this too
        byte[] buf = new byte[2048];
        while (System.nanoTime() < end) {
            DatagramPacket p = new DatagramPacket(buf, buf.length);
            try {
                station.receive(p);
            } catch (SocketTimeoutException e) {
                continue;
            } catch (IOException e) {
                break;
            }
            got.add(hex(java.util.Arrays.copyOf(p.getData(), p.getLength())));
        }
        Thread.sleep(300);
        for (byte[] f : onLink) {
            System.out.println("UPLINK " + hex(f));
        }
        for (String g : got) {
            System.out.println("STATION " + g);
        }
        for (String p : problems) {
            System.out.println("PROBLEM " + p);
        }
        System.out.println("DONE v1up=" + bridge.v1Up() + " v1down=" + bridge.v1Down() + " v1dropped="
                + bridge.v1Dropped());
        bridge.close();
        sched.close();
        station.close();
    }

    /** {@code m} as the vehicle (1/1) sent it, parsed from its frame as a link would deliver it. */
    static MavlinkMessage fromVehicle(MavlinkMessage m, int seq) {
        byte[] f = m.pack(seq, 1, 1);
        List<MavlinkMessage> out = new ArrayList<>();
        Parser p = new Parser(Ttapi.INSTANCE);
        p.feed(f, 0, f.length, out::add);
        p.flush(out::add);
        return out.get(0);
    }

    static byte[] unhex(String s) {
        byte[] b = new byte[s.length() / 2];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) Integer.parseInt(s.substring(2 * i, 2 * i + 2), 16);
        }
        return b;
    }

    static String hex(byte[] b) {
        StringBuilder s = new StringBuilder();
        for (byte x : b) {
            s.append(String.format("%02x", x & 0xFF));
        }
        return s.toString();
    }
}
