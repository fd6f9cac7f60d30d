import java.util.concurrent.TimeUnit;

import ttctl.robolab.Robolab;
import ttctl.robolab.commands.SendKrMotorControl;
import ttctl.robolab.enums.KrVehicleDir;
import ttctl.robolab.msg.KrMotorStatus;
import ttctl.robolab.runtime.Session;
import ttctl.robolab.runtime.UdpLink;

/**
 * A tablet app's few lines, for tests/test_own_dialect.py: the robolab dialect's generated Java
 * runtime on UDP (one Session), sending KR_MOTOR_CONTROL with the generated command skeleton
 * (unchanged) to `ttctl emulate onboard --dialect robolab.xml` and waiting for its
 * KR_MOTOR_STATUS. Arguments: PORT SEQ. Prints "RESULT seq dir speed rpm note" or "FAILED reason".
 */
public final class RobolabTablet {
    public static void main(String[] argv) throws Exception {
        int port = Integer.parseInt(argv[0]);
        int seq = Integer.parseInt(argv[1]);
        UdpLink udp = UdpLink.open("127.0.0.1", 0, "127.0.0.1", port, Robolab.INSTANCE);
        Session.Options options = new Session.Options();
        options.rate = 500;
        Session session = new Session(udp, 255, 190, options).start();
        try {
            KrMotorStatus st = (KrMotorStatus) session.submit(
                    new SendKrMotorControl(1, seq, KrVehicleDir.KR_VEHICLE_DIR_FORWARD, 30)).get(20, TimeUnit.SECONDS);
            System.out.println("RESULT " + st.seq + " " + st.dir + " " + st.speed + " " + st.rpm + " " + st.getNoteString());
        } catch (Exception e) {
            System.out.println("FAILED " + e);
        } finally {
            session.close();
        }
    }
}
