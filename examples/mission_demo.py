"""Upload a mission with a fence, fly it, pause and continue it, and print what the vehicle says."""
import math, time
from pymavlink import mavutil

conn = mavutil.mavlink_connection("udpin:127.0.0.1:14550", source_system=255, dialect="common")
m = mavutil.mavlink
conn.wait_heartbeat()
lat0, lon0 = 46.0503, 14.4686

def at(n, e):
    return int((lat0 + n / 111319.49) * 1e7), int((lon0 + e / (111319.49 * math.cos(math.radians(lat0)))) * 1e7)

def item(seq, cmd, n=0.0, e=0.0, alt=5.0, p1=0.0, p2=0.0, kind=m.MAV_MISSION_TYPE_MISSION):
    x, y = at(n, e)
    return m.MAVLink_mission_item_int_message(1, 1, seq, m.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, cmd, 0, 1, p1, p2, 0,
                                              math.nan, x, y, alt, kind)

def upload(items, kind=m.MAV_MISSION_TYPE_MISSION):
    conn.mav.mission_count_send(1, 1, len(items), kind)
    while True:
        r = conn.recv_match(type=["MISSION_REQUEST_INT", "MISSION_ACK"], blocking=True, timeout=5)
        if r.get_type() == "MISSION_ACK":
            return mavutil.mavlink.enums["MAV_MISSION_RESULT"][r.type].name
        conn.mav.send(items[r.seq])

def cmd(c, *p):
    p = list(p) + [0.0] * (7 - len(p))
    conn.mav.command_long_send(1, 1, c, 0, *p)
    a = conn.recv_match(type="COMMAND_ACK", blocking=True, timeout=3)
    return mavutil.mavlink.enums["MAV_RESULT"][a.result].name

print("upload [WP, CONDITION_DISTANCE]:", upload([item(0, m.MAV_CMD_NAV_WAYPOINT, 5), item(1, m.MAV_CMD_CONDITION_DISTANCE)]))
print("fence (a 30 m circle):", upload([item(0, m.MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION, p1=30, kind=m.MAV_MISSION_TYPE_FENCE)],
                                       m.MAV_MISSION_TYPE_FENCE))
mission = [item(0, m.MAV_CMD_NAV_TAKEOFF, alt=5), item(1, m.MAV_CMD_NAV_WAYPOINT, 10), item(2, m.MAV_CMD_NAV_WAYPOINT, 10, 10),
           item(3, m.MAV_CMD_DO_JUMP, p1=1, p2=1), item(4, m.MAV_CMD_NAV_RETURN_TO_LAUNCH)]
print("mission [TAKEOFF, WP, WP, DO_JUMP to 1 once, RTL]:", upload(mission))
print("arm:", cmd(m.MAV_CMD_COMPONENT_ARM_DISARM, 1), " start:", cmd(m.MAV_CMD_MISSION_START))
paused = False
while True:
    r = conn.recv_match(type=["MISSION_ITEM_REACHED", "STATUSTEXT", "EXTENDED_SYS_STATE"], blocking=True, timeout=60)
    if r.get_type() == "MISSION_ITEM_REACHED":
        print("reached item", r.seq)
        if r.seq == 2 and not paused:
            paused = True
            print("pause:", cmd(m.MAV_CMD_DO_PAUSE_CONTINUE, 0))
            time.sleep(2)
            print("continue:", cmd(m.MAV_CMD_DO_PAUSE_CONTINUE, 1))
    elif r.get_type() == "STATUSTEXT":
        print("vehicle:", r.text)
        if r.text == "landed":
            break
