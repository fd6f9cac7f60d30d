"""Missions flown faithfully and safety as PX4 does it, sans-IO: the ground-station side and the
autopilot driven with messages and time steps, every ACCEPTED checked in the vehicle's state."""

from __future__ import annotations

import math
from typing import Any

import pytest

from conftest import shipped
from ttctl.ends.onboard.autopilot import Autopilot
from ttctl.ends.onboard.gcs import GroundStations
from ttctl.ends.onboard.mission_run import ACTIVE, COMPLETE, NOT_STARTED, PAUSED
from ttctl.ends.onboard.params import INT32, Param
from ttctl.ends.onboard.vehicle import EARTH_RADIUS, Home, SimVehicle, State

HOME = Home()
GCS = (255, 190)


def latlon(n: float, e: float) -> tuple[int, int]:
    lat = HOME.lat + math.degrees(n / EARTH_RADIUS)
    lon = HOME.lon + math.degrees(e / (EARTH_RADIUS * math.cos(math.radians(HOME.lat))))
    return round(lat * 1e7), round(lon * 1e7)


class Sim:
    """A vehicle, its autopilot and the ground-station side, and a ground station's view."""

    def __init__(self) -> None:
        self.b = b = shipped()
        self.v = SimVehicle()
        self.said: list[str] = []
        self.ap = Autopilot(b, self.v, say=lambda sev, text: (self.said.append(text), self.gs.say(sev, text)))
        self.gs = GroundStations(b, self.ap, 1)
        self.t = 0.0
        self.got: list[Any] = []
        self.C, self.F = b.MavCmd, b.MavFrame

    def send(self, msg: Any) -> None:
        msg._mav_sysid, msg._mav_compid = GCS
        self.gs.on_message(self.t, msg)
        self.got += [m for m, _ in self.gs.tick(self.t)]

    def run(self, seconds: float, until: Any = None, dt: float = 0.05) -> bool:
        end = self.t + seconds
        while self.t < end:
            self.t += dt
            self.ap.step(self.t, dt)
            self.ap.heard_gcs(GCS[0], self.t)
            self.got += [m for m, _ in self.gs.tick(self.t)]
            if until is not None and until():
                return True
        return until is None

    def command(self, cmd: Any, *p: float) -> int:
        params = list(p) + [0.0] * (7 - len(p))
        self.got.clear()
        self.send(self.b.CommandLong(target_system=1, target_component=1, command=int(cmd), confirmation=0,
                                     param1=params[0], param2=params[1], param3=params[2], param4=params[3],
                                     param5=params[4], param6=params[5], param7=params[6]))
        acks = [m for m in self.got if isinstance(m, self.b.CommandAck) and m.command == int(cmd)]
        assert len(acks) == 1
        return int(acks[0].result)

    def item(self, cmd: Any, n: float = 0.0, e: float = 0.0, alt: float = 0.0, p1: float = 0.0, p2: float = 0.0,
             p3: float = 0.0, p4: float = math.nan, here: bool = False, kind: int = 0) -> Any:
        x, y = (0, 0) if here else latlon(n, e)
        return self.b.MissionItemInt(target_system=1, target_component=1, seq=0, frame=int(
            self.F.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT), command=int(cmd), current=0, autocontinue=1, param1=p1,
            param2=p2, param3=p3, param4=p4, x=x, y=y, z=alt, mission_type=kind)

    def upload(self, items: list[Any], kind: int = 0) -> int:
        self.got.clear()
        self.send(self.b.MissionCount(target_system=1, target_component=1, count=len(items), mission_type=kind))
        for _ in range(len(items) + 1):
            asks = [m for m in self.got if isinstance(m, self.b.MissionRequestInt)]
            acks = [m for m in self.got if isinstance(m, self.b.MissionAck)]
            if acks:
                return int(acks[-1].type)
            self.got.clear()
            it = items[asks[-1].seq]
            it.seq, it.mission_type = asks[-1].seq, kind
            self.send(it)
        raise AssertionError("the upload never ended")

    def texts(self) -> list[str]:
        """STATUSTEXTs as a ground station shows them: chunks with one id joined."""
        out: list[str] = []
        parts: dict[int, list[str]] = {}
        for m in self.got:
            if isinstance(m, self.b.Statustext):
                if m.id == 0:
                    out.append(m.text)
                else:
                    parts.setdefault(m.id, []).append(m.text)
                    if len(m.text.encode()) < 50:
                        out.append("".join(parts.pop(m.id)))
        return out

    def currents(self) -> list[int]:
        return [m.seq for m in self.got if isinstance(m, self.b.MissionCurrent)]

    def reached(self) -> list[int]:
        return [m.seq for m in self.got if isinstance(m, self.b.MissionItemReached)]

    def at(self, n: float, e: float, tol: float = 0.3) -> bool:
        return math.hypot(self.v.pos[0] - n, self.v.pos[1] - e) < tol


def test_a_mission_reports_item_numbers_and_reaches_every_item() -> None:
    s = Sim()
    C = s.C
    items = [s.item(C.MAV_CMD_NAV_TAKEOFF, alt=4, here=True), s.item(C.MAV_CMD_DO_CHANGE_SPEED, p1=1, p2=1.0),
             s.item(C.MAV_CMD_NAV_WAYPOINT, 8, 0, 4), s.item(C.MAV_CMD_NAV_WAYPOINT, 8, 6, 5)]
    assert s.upload(items) == 0
    assert s.ap.runner is not None and s.ap.runner.state == NOT_STARTED
    assert s.command(C.MAV_CMD_MISSION_START) == 2  # DENIED: not armed
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_MISSION_START) == 0
    s.got.clear()
    top = 0.0
    modes: set[tuple[int, int]] = set()

    def done() -> bool:
        nonlocal top
        top = max(top, math.hypot(s.v.vel[0], s.v.vel[1]))
        if s.ap.runner is not None and s.ap.runner.running:
            modes.add(s.ap.flight.current(s.v.state))
        return s.ap.runner is not None and s.ap.runner.state == COMPLETE
    assert s.run(120, done)
    assert modes == {(4, 4)}  # PX4's navigator flies the take-off item too in AUTO MISSION, and says so
    assert s.reached() == [0, 1, 2, 3]
    seen = [c for i, c in enumerate(s.currents()) if i == 0 or c != s.currents()[i - 1]]
    assert seen == [0, 1, 2, 3]  # MISSION_CURRENT is the item number
    assert top <= 1.0 + 1e-6  # DO_CHANGE_SPEED held
    assert s.at(8, 6) and s.v.state is State.HOVERING and abs(-s.v.pos[2] - 5) < 0.2
    mc = s.ap.runner.mission_current()
    assert (mc.seq, mc.total, mc.mission_state) == (3, 4, COMPLETE)


def test_pause_holds_and_continue_resumes_at_the_same_item() -> None:
    s = Sim()
    C = s.C
    items = [s.item(C.MAV_CMD_NAV_WAYPOINT, 0, 0, 4), s.item(C.MAV_CMD_NAV_WAYPOINT, 20, 0, 4),
             s.item(C.MAV_CMD_NAV_RETURN_TO_LAUNCH)]
    assert s.upload(items) == 0
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_MISSION_START) == 0
    assert s.run(60, lambda: s.v.pos[0] > 5)
    assert s.command(C.MAV_CMD_DO_PAUSE_CONTINUE, 0) == 0
    s.run(4)
    assert s.v.state is State.HOVERING and s.ap.runner is not None and s.ap.runner.state == PAUSED
    held = s.v.pos[0]
    s.run(5)
    assert abs(s.v.pos[0] - held) < 0.05  # pausing holds: no return, no landing
    assert s.ap.runner.current == 1
    assert s.command(C.MAV_CMD_DO_PAUSE_CONTINUE, 1) == 0
    s.run(0.1)
    assert s.ap.runner.state == ACTIVE and s.v.state is State.TRAJECTORY
    assert s.run(60, lambda: s.v.state is State.RETURNING)
    assert s.reached()[0] == 1  # item 1 reached after the pause
    assert s.run(120, lambda: s.v.state is State.LANDED)
    assert s.ap.runner.state == COMPLETE and 2 in s.reached() and s.at(0, 0)


def test_a_stored_missions_end_never_fires_outside_the_mission() -> None:
    """A [WP, RTL] mission merely stored: a goto, a hold or a trajectory ending is not the
    mission's end; and a hold during the mission suspends it (no return)."""
    s = Sim()
    C = s.C
    assert s.upload([s.item(C.MAV_CMD_NAV_WAYPOINT, 10, 0, 4), s.item(C.MAV_CMD_NAV_RETURN_TO_LAUNCH)]) == 0
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, 0, 0, 0, 4) == 0
    assert s.run(30, lambda: s.v.state is State.HOVERING)
    from ttctl.ends.onboard.vehicle import Waypoint

    s.ap.fly_trajectory([Waypoint(3, 3, 4)], "a tablet trajectory")
    assert s.run(30, lambda: s.v.state is State.HOVERING)
    s.run(3)
    assert s.v.state is State.HOVERING and s.at(3, 3)  # not returning
    assert s.command(C.MAV_CMD_MISSION_START) == 0
    assert s.run(20, lambda: s.v.pos[0] > 5)
    s.v.hover()  # the tablet's hover during the mission
    s.run(5)
    assert s.v.state is State.HOVERING and s.ap.runner is not None and s.ap.runner.state == PAUSED


def test_set_current_jump_delay_yaw_roi_and_land_start() -> None:
    s = Sim()
    C = s.C
    items = [s.item(C.MAV_CMD_NAV_WAYPOINT, 5, 0, 4),                    # 0
             s.item(C.MAV_CMD_NAV_WAYPOINT, 5, 5, 4),                    # 1
             s.item(C.MAV_CMD_DO_JUMP, p1=0, p2=1),                      # 2: once more round 0, 1
             s.item(C.MAV_CMD_CONDITION_YAW, p1=180, p4=0),              # 3
             s.item(C.MAV_CMD_NAV_DELAY, p1=3),                          # 4
             s.item(C.MAV_CMD_DO_SET_ROI_LOCATION, 0, 20, 0),            # 5: face east
             s.item(C.MAV_CMD_NAV_WAYPOINT, 0, 5, 4),                    # 6
             s.item(C.MAV_CMD_DO_LAND_START),                            # 7
             s.item(C.MAV_CMD_NAV_LAND, 0, 0, 0)]                        # 8
    assert s.upload(items) == 0
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_MISSION_START) == 0
    assert s.run(200, lambda: s.ap.runner is not None and s.ap.runner.current == 4)
    assert s.reached() == [0, 1, 2, 0, 1, 2, 3]  # the jump flew 0 and 1 once more
    assert abs(abs(s.v.yaw) - math.pi) < math.radians(4)  # CONDITION_YAW 180 before going on
    t0 = s.t
    assert s.run(30, lambda: s.ap.runner is not None and s.ap.runner.current == 6)
    assert s.t - t0 >= 3.0  # NAV_DELAY held 3 s
    assert s.run(30, lambda: s.at(0, 5, 1.0))
    assert abs(s.v.yaw - math.pi / 2) < math.radians(10)  # facing the ROI, east
    # MISSION_SET_CURRENT back to item 1: the running mission goes there now
    s.got.clear()
    s.send(s.b.MissionSetCurrent(target_system=1, target_component=1, seq=1))
    assert s.currents() == [1]
    assert s.run(30, lambda: s.at(5, 5, 0.3))
    assert s.command(C.MAV_CMD_DO_PAUSE_CONTINUE, 0) == 0
    # DO_LAND_START: the mission from its landing sequence
    assert s.command(C.MAV_CMD_DO_LAND_START) == 0
    assert s.run(60, lambda: s.v.state is State.LANDED)
    assert s.at(0, 0, 0.5) and 8 in s.reached()  # landed where item 8 says
    assert s.ap.runner is not None and s.ap.runner.state == COMPLETE
    assert s.command(C.MAV_CMD_DO_SET_MISSION_CURRENT, 99) == 2  # DENIED: no such item
    assert s.command(C.MAV_CMD_DO_SET_MISSION_CURRENT, 2) == 0 and s.ap.runner.current == 2


@pytest.mark.parametrize("bad, code", [
    ("cmd", 3), ("jump", 6), ("jump_repeat", 7), ("delay_tod", 3), ("delay_nan", 6), ("loiter_nan", 6),
    ("roi_mode", 3), ("lat", 10)])  # MAV_MISSION_UNSUPPORTED 3, _INVALID_PARAM1 6, _PARAM2 7, _PARAM5_X 10
def test_items_the_vehicle_cannot_fly_are_refused_at_upload_by_name(bad: str, code: int) -> None:
    s = Sim()
    C = s.C
    item = {"cmd": s.item(C.MAV_CMD_CONDITION_DISTANCE, p1=5),
            "jump": s.item(C.MAV_CMD_DO_JUMP, p1=7, p2=1),
            "jump_repeat": s.item(C.MAV_CMD_DO_JUMP, p1=0, p2=math.inf),
            "delay_tod": s.item(C.MAV_CMD_NAV_DELAY, p1=-1, p2=12),
            "delay_nan": s.item(C.MAV_CMD_NAV_DELAY, p1=math.nan),
            "loiter_nan": s.item(C.MAV_CMD_NAV_LOITER_TIME, 1, 1, 4, p1=math.nan),
            "roi_mode": s.item(C.MAV_CMD_DO_SET_ROI, p1=2),
            "lat": s.item(C.MAV_CMD_NAV_WAYPOINT, 5, 5, 4)}[bad]
    if bad == "lat":
        item.x = 91 * 10_000_000
    assert s.upload([s.item(C.MAV_CMD_NAV_WAYPOINT, 5, 0, 4), item]) == code
    assert any(t.startswith("item 1 refused: ") for t in s.texts())
    assert s.ap.missions is not None and s.ap.missions.mission() == []


def test_geofence_breach_acts_by_gf_action_and_sys_status_tells() -> None:
    s = Sim()
    C, b = s.C, s.b
    fence = [s.item(C.MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION, 0, 0, 0, p1=20.0, kind=1),
             s.item(C.MAV_CMD_NAV_FENCE_CIRCLE_EXCLUSION, -10, 0, 0, p1=4.0, kind=1)]
    assert s.upload(fence, kind=1) == 0
    bit = int(b.MavSysStatusSensor.MAV_SYS_STATUS_GEOFENCE)
    st = s.gs.builders[b.SysStatus.MSG_ID](s.v.snapshot())
    assert st.onboard_control_sensors_present & bit and st.onboard_control_sensors_health & bit
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, 0, 0, 0, 4) == 0
    assert s.run(30, lambda: s.v.state is State.HOVERING)
    s.v.goto(40, 0, 4)  # through the fence
    assert s.run(60, lambda: s.ap.breached is not None)
    st = s.gs.builders[b.SysStatus.MSG_ID](s.v.snapshot())
    assert not st.onboard_control_sensors_health & bit
    s.run(5)
    assert s.v.state is State.HOVERING and 19 < s.v.pos[0] <= 20.05  # GF_ACTION 2: hold at the fence, not past it
    # GF_ACTION 3: return
    s.send(b.ParamSet(target_system=1, target_component=1, param_id="GF_ACTION",
                      param_value=Param("GF_ACTION", 3, INT32, 0, 5, "").encoded(), param_type=INT32))
    assert s.ap.params["GF_ACTION"] == 3
    s.v.goto(0, 0, 4)
    assert s.run(60, lambda: s.v.state is State.HOVERING and s.ap.breached is None)
    s.v.goto(-10, 0, 4)  # into the exclusion circle
    assert s.run(60, lambda: s.v.state is State.RETURNING)
    assert any("inside an exclusion fence" in t for t in s.said)


def test_rally_points_home_at_arming_and_do_set_home() -> None:
    s = Sim()
    C = s.C
    assert s.upload([s.item(C.MAV_CMD_NAV_RALLY_POINT, 30, 0, 10, kind=2)], kind=2) == 0
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, 0, 0, 0, 4) == 0
    assert s.run(30, lambda: s.v.state is State.HOVERING)
    s.v.goto(25, 0, 4)
    assert s.run(60, lambda: s.v.state is State.HOVERING)
    assert s.command(C.MAV_CMD_NAV_RETURN_TO_LAUNCH) == 0
    assert s.run(120, lambda: s.v.state is State.LANDED)
    assert s.at(30, 0)  # the rally point was closer than home
    # arming again: home is here
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    s.run(0.2)
    snap = s.v.snapshot()
    assert abs(snap.home.lat - snap.lat) < 1e-9 and s.at(0, 0, 0.01)
    # DO_SET_HOME to a position 10 m west; NaN position refused
    assert s.command(C.MAV_CMD_DO_SET_HOME, 0, 0, 0, 0, math.nan, math.nan, math.nan) == 2
    lat, lon = latlon(30, -10)
    assert s.command(C.MAV_CMD_DO_SET_HOME, 0, 0, 0, 0, lat / 1e7, lon / 1e7, HOME.alt) == 0
    assert s.at(0, 10, 0.05) and abs(s.v.home.lon - lon / 1e7) < 1e-9
    assert s.command(C.MAV_CMD_DO_SET_HOME, 1) == 0 and s.at(0, 0, 0.01)


def test_battery_warns_then_returns_then_lands() -> None:
    s = Sim()
    C = s.C
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, 0, 0, 0, 4) == 0
    assert s.run(30, lambda: s.v.state is State.HOVERING)
    s.v.goto(20, 0, 4)
    s.v.energy_wh = s.v.battery_wh * 0.16
    assert s.run(200, lambda: s.ap.battery_level == 1)
    assert any("battery low" in t for t in s.said) and s.v.state in (State.MOVING, State.HOVERING)
    assert s.run(200, lambda: s.ap.battery_level == 2)
    assert s.v.state is State.RETURNING  # COM_LOW_BAT_ACT 3: return at critical
    st = s.gs.builders[s.b.BatteryStatus.MSG_ID](s.v.snapshot())
    assert st.charge_state == 3  # MAV_BATTERY_CHARGE_STATE_CRITICAL
    s.v.energy_wh = s.v.battery_wh * 0.045
    s.run(0.2)
    assert s.v.state is State.LANDING and any("battery emergency" in t for t in s.said)


def test_link_loss_watches_the_link_that_commands_the_flight() -> None:
    """A tablet heard once, then gone, does not abort a flight flown from a ground station; the
    ground station's own silence does."""
    s = Sim()
    C = s.C
    s.ap.heard_tablet(0.0)
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, 0, 0, 0, 4) == 0
    assert s.run(40, lambda: s.v.state is State.HOVERING)
    assert s.ap.commander == GCS[0]
    s.run(15)  # the tablet has been silent long past COM_DL_LOSS_T
    assert s.v.state is State.HOVERING and not any("link lost" in t for t in s.said)
    dt, t0 = 0.05, s.t
    while s.t < t0 + 12:  # now the ground station falls silent
        s.t += dt
        s.ap.step(s.t, dt)
    assert any("ground station 255 link lost" in t for t in s.said)


def test_hostile_values_in_every_mission_and_safety_input_are_refused_never_a_crash() -> None:
    """NaN, infinities and absurd numbers in every parameter of the mission and safety commands,
    every field of mission, fence and rally items, and MISSION_SET_CURRENT: answered with the
    protocol's own codes; the vehicle's position, home and mission state stay sane."""
    import random

    s = Sim()
    C, b = s.C, s.b
    rng = random.Random(19)
    bad = [math.nan, math.inf, -math.inf, 1e30, -1e30, -1.0, 0.0, 1.0, 3.0, 7.5, 65536.0]
    assert s.upload([s.item(C.MAV_CMD_NAV_WAYPOINT, 5, 0, 4), s.item(C.MAV_CMD_DO_LAND_START),
                     s.item(C.MAV_CMD_NAV_LAND, 5, 5, 0)]) == 0
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, 0, 0, 0, 4) == 0
    assert s.run(30, lambda: s.v.state is State.HOVERING)
    commands = [C.MAV_CMD_DO_SET_HOME, C.MAV_CMD_DO_CHANGE_SPEED, C.MAV_CMD_DO_PAUSE_CONTINUE,
                C.MAV_CMD_DO_SET_MISSION_CURRENT, C.MAV_CMD_DO_LAND_START, C.MAV_CMD_MISSION_START]
    for _ in range(400):
        cmd = rng.choice(commands)
        result = s.command(cmd, *(rng.choice(bad) for _ in range(7)))
        assert result in (0, 1, 2), (cmd, result)  # ACCEPTED, TEMPORARILY_REJECTED or DENIED
        s.run(0.1)
        snap = s.v.snapshot()
        assert all(math.isfinite(x) for x in (snap.n, snap.e, snap.d, snap.home.lat, snap.home.lon, snap.home.alt))
        assert -90 <= snap.home.lat <= 90 and -180 <= snap.home.lon <= 180
        assert s.v.limits.h_speed >= (s.v.speed_cap or 0.0)
    for kind in (0, 1, 2):  # mission, fence, rally items with hostile fields
        for _ in range(60):
            it = s.item(rng.choice(list(C)), 0, 0, rng.choice(bad), rng.choice(bad), rng.choice(bad),
                        rng.choice(bad), rng.choice(bad), kind=kind)
            it.x, it.y = rng.choice([0, 2**31 - 1, -(2**31), 900_000_000, it.x]), rng.choice([0, 2**31 - 1, it.y])
            assert s.upload([it], kind=kind) in range(0, 16)
            s.run(0.1)
    for seq in (-1, 3, 65535, 2):
        s.got.clear()
        s.send(b.MissionSetCurrent(target_system=1, target_component=1, seq=seq & 0xFFFF))
        assert len(s.currents()) == 1  # answered with MISSION_CURRENT, as the protocol says
    s.got.clear()
    s.send(b.MissionCount(target_system=1, target_component=1, count=65535, mission_type=0))
    assert [m.type for m in s.got if isinstance(m, b.MissionAck)] == [4]  # MAV_MISSION_NO_SPACE
    s.run(2)
    assert all(math.isfinite(x) for x in s.v.pos) and s.ap.runner is not None and s.ap.runner.state in range(1, 6)


def test_legacy_mission_item_upload_and_download() -> None:
    """MISSION_ITEM (float degrees) is taken as MISSION_ITEM_INT is; MISSION_REQUEST is answered
    in kind, as PX4 does; a position that is not a number is refused."""
    s = Sim()
    C, F, b = s.C, s.F, s.b
    lat, lon = (v / 1e7 for v in latlon(10, 5))

    def legacy(seq: int, x: float, y: float) -> Any:
        return b.MissionItem(target_system=1, target_component=1, seq=seq, frame=int(F.MAV_FRAME_GLOBAL_RELATIVE_ALT),
                             command=int(C.MAV_CMD_NAV_WAYPOINT), current=0, autocontinue=1, param1=0, param2=0,
                             param3=0, param4=math.nan, x=x, y=y, z=6.0, mission_type=0)

    assert s.upload([legacy(0, lat, lon), legacy(1, lat, lon + 1e-4)]) == 0
    assert s.ap.missions is not None and [i.x for i in s.ap.missions.mission()] == [round(lat * 1e7)] * 2
    s.got.clear()
    s.send(b.MissionRequest(target_system=1, target_component=1, seq=1, mission_type=0))
    out = [m for m in s.got if isinstance(m, (b.MissionItem, b.MissionItemInt))]
    assert len(out) == 1 and isinstance(out[0], b.MissionItem) and abs(out[0].y - (lon + 1e-4)) < 1e-6
    assert s.upload([legacy(0, math.nan, lon)]) == 10  # MAV_MISSION_INVALID_PARAM5_X
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_MISSION_START) == 0
    assert s.run(60, lambda: s.ap.runner is not None and s.ap.runner.current == 1)
    assert s.at(10, 5)


def test_roi_commands_turn_a_holding_vehicle_toward_the_point() -> None:
    s = Sim()
    C = s.C
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, 0, 0, 0, 4) == 0
    assert s.run(30, lambda: s.v.state is State.HOVERING)
    assert s.command(C.MAV_CMD_DO_SET_ROI_LOCATION, 0, 0, 0, 0, math.nan, 14.4686, 0) == 2  # DENIED: no position
    lat, lon = latlon(-20, 0)  # due south
    assert s.command(C.MAV_CMD_DO_SET_ROI_LOCATION, 0, 0, 0, 0, lat / 1e7, lon / 1e7, 0) == 0
    s.run(5)
    assert abs(abs(s.v.yaw) - math.pi) < math.radians(3)
    assert s.command(C.MAV_CMD_DO_SET_ROI_NONE) == 0
    assert s.ap.runner is not None and s.ap.runner.roi is None


def test_fence_polygons_and_distance_limits() -> None:
    from ttctl.ends.onboard import safety

    s = Sim()
    C = s.C
    square = [s.item(C.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION, n, e, p1=4, kind=1)
              for n, e in ((-30, -30), (30, -30), (30, 30), (-30, 30))]
    hole = [s.item(C.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION, n, e, p1=3, kind=1)
            for n, e in ((5, 5), (15, 5), (5, 15))]
    areas = safety.fence_areas(s.b, square + hole)
    assert [a.inclusion for a in areas] == [True, False]

    def why(n: float, e: float, alt: float = 5, hor: float = 0, ver: float = 0) -> str | None:
        return safety.breach(areas, HOME, n, e, alt, hor, ver)
    assert why(0, 0) is None and why(29, -29) is None and why(20, 20) is None
    assert why(31, 0) == "outside the inclusion fence" and why(0, -31) == "outside the inclusion fence"
    assert why(7, 7) == "inside an exclusion fence" and why(14, 14) is None  # beyond the triangle's long side
    assert why(20, 0, hor=15) is not None and why(0, 0, alt=50, ver=40) is not None
    bad = s.item(C.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION, 0, 0, p1=2, kind=1)
    assert s.upload([bad, bad], kind=1) == 6  # two vertices: MAV_MISSION_INVALID_PARAM1
    assert s.upload([s.item(C.MAV_CMD_NAV_WAYPOINT, 1, 1, 5, kind=1)], kind=1) == 3  # not a fence item
    assert s.upload([s.item(C.MAV_CMD_NAV_FENCE_RETURN_POINT, 1, 1, 5, kind=1)], kind=1) == 3  # never used here


def test_mission_start_with_a_first_item() -> None:
    s = Sim()
    C = s.C
    assert s.upload([s.item(C.MAV_CMD_NAV_WAYPOINT, 20, 0, 4), s.item(C.MAV_CMD_NAV_WAYPOINT, 0, 8, 4),
                     s.item(C.MAV_CMD_NAV_WAYPOINT, 8, 8, 4)]) == 0
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_MISSION_START, 5) == 2  # DENIED: no item 5
    assert s.command(C.MAV_CMD_MISSION_START, 1) == 0
    assert s.run(60, lambda: s.ap.runner is not None and s.ap.runner.state == COMPLETE)
    assert s.reached() == [1, 2] and s.at(8, 8) and s.v.pos[0] < 8.5  # item 0, 20 m north, never flown


def test_an_altitude_the_vehicle_cannot_fly_is_refused_at_upload() -> None:
    s = Sim()
    C = s.C
    assert s.upload([s.item(C.MAV_CMD_NAV_WAYPOINT, 5, 0, 4), s.item(C.MAV_CMD_NAV_WAYPOINT, 5, 5, 500)]) == 12
    assert "item 1 refused: NAV_WAYPOINT: altitude 500 m above home is outside 0..120 m" in s.texts()
    high = s.item(C.MAV_CMD_NAV_WAYPOINT, 5, 5, 295 + 30)
    high.frame = int(s.F.MAV_FRAME_GLOBAL_INT)  # above mean sea level: 30 m above home
    assert s.upload([high]) == 0


def test_a_hold_during_the_missions_own_take_off_suspends_the_mission() -> None:
    """A mission started on the ground takes off first; a hold meanwhile (the tablet's hover) is
    still 'hovering' once the climb ends, but the hold is the tablet's, not the mission's: the
    mission is suspended, the vehicle stays put. (Found by tests/test_emulate_promises.py: an
    ACCEPTED hover, then the vehicle flew on to the next waypoint.)"""
    s = Sim()
    C = s.C
    assert s.upload([s.item(C.MAV_CMD_NAV_WAYPOINT, 15, 0, 6), s.item(C.MAV_CMD_NAV_RETURN_TO_LAUNCH)]) == 0
    assert s.command(C.MAV_CMD_COMPONENT_ARM_DISARM, 1) == 0
    assert s.command(C.MAV_CMD_MISSION_START) == 0
    assert s.run(30, lambda: -s.v.pos[2] > 1.0) and s.v.state is State.TAKING_OFF
    s.v.hover()  # the tablet's hover, during the mission's own climb
    s.run(20)
    assert s.ap.runner is not None and s.ap.runner.state == PAUSED
    assert s.v.state is State.HOVERING and s.at(0, 0, 0.5)
