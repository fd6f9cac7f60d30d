# examples/gcs_demo.py
import time

from pymavlink import mavutil

m = mavutil.mavlink
gcs = mavutil.mavlink_connection("udpin:127.0.0.1:14550", source_system=255)
gcs.wait_heartbeat()
print(f"vehicle {gcs.target_system}: {gcs.flightmode}, armed {gcs.motors_armed()}")


def command(cmd, *p):
    gcs.mav.command_long_send(1, 1, cmd, 0, *(list(p) + [0] * (7 - len(p))))
    ack = gcs.recv_match(type="COMMAND_ACK", condition=f"COMMAND_ACK.command=={cmd}", blocking=True, timeout=3)
    print(m.enums["MAV_CMD"][cmd].name, m.enums["MAV_RESULT"][ack.result].name)


def setpoint(vn, ve, vd):  # velocity and yaw, MAVSDK's set_velocity_ned
    gcs.mav.set_position_target_local_ned_send(0, 1, 1, m.MAV_FRAME_LOCAL_NED, 0b100111000111,
                                               0, 0, 0, vn, ve, vd, 0, 0, 0, 1.5708, 0)


command(m.MAV_CMD_DO_SET_MODE, 1, 6, 0)  # OFFBOARD, before any set-point
command(m.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, float("nan"), float("nan"), float("nan"), 295 + 5)  # AMSL
command(m.MAV_CMD_COMPONENT_ARM_DISARM, 1)
gcs.recv_match(type="GLOBAL_POSITION_INT", condition="GLOBAL_POSITION_INT.relative_alt>4900", blocking=True)
for _ in range(5):
    setpoint(0, 1, 0)
    time.sleep(0.05)
command(m.MAV_CMD_DO_SET_MODE, 1, 6, 0)
start = time.monotonic()
while time.monotonic() - start < 2.5:  # 1 m/s east for 10 s of the vehicle's clock (--speed 4)
    setpoint(0, 1, 0)
    time.sleep(0.05)
while gcs.recv_match(blocking=False):  # what came meanwhile
    pass
p = gcs.recv_match(type="LOCAL_POSITION_NED", blocking=True)
print(f"{gcs.flightmode} at {p.x:.1f} N {p.y:.1f} E {-p.z:.1f} m")
time.sleep(1.5)  # the set-points stop: after COM_OF_LOSS_T, PX4 holds
print(gcs.recv_match(type="STATUSTEXT", condition="'lost' in STATUSTEXT.text", blocking=True, timeout=5).text)
gcs.recv_match(type="HEARTBEAT", blocking=True)
print(gcs.flightmode)
command(m.MAV_CMD_DO_SET_MODE, 1, 4, 5)  # AUTO.RTL
