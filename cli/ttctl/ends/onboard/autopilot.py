"""The vehicle's brain, shared by every link that commands it: the tablet over DTT and any
number of ground stations. It owns the vehicle, its parameters, its mission (flown by
mission_run.MissionRunner) and its safety (safety.py: geofence, rally points, home, battery and
link-loss failsafes), applies the parameters to the vehicle, and watches the link that commands
the flight: silent for COM_DL_LOSS_T seconds (of the wall clock, as the links run, whatever
--speed is), the vehicle hovers (or lands, or returns, by NAV_DLL_ACT); silent COM_RTL_AFTER_T
more, it returns home and lands, as PX4's data-link-loss failsafe does. Everything it does is
told through `say` (STATUSTEXT and TT_LOG, in the node).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable
from typing import Any

from ...wire.bindings import Bindings
from . import safety
from .flight import FlightModes
from .mission_run import MissionRunner
from .missions import Missions
from .params import Param, Parameters, default_params
from .vehicle import Home, Refused, SimVehicle, Snapshot, State, Vehicle

Say = Callable[[int, str], None]  # (MAV_SEVERITY, text)
INFO, WARNING, CRITICAL = 6, 4, 2
TABLET = "tablet"
STEERING = ("SetPositionTargetLocalNed", "SetPositionTargetGlobalInt", "ManualControl")  # set-point streams


class Autopilot:
    def __init__(self, bindings: Bindings, vehicle: Vehicle, sysid: int = 1, say: Say | None = None,
                 params: list[Param] | None = None) -> None:
        self.b = bindings
        self.vehicle = vehicle
        self.sysid = sysid
        self.say = say or (lambda severity, text: None)
        self.params = Parameters(bindings, params or default_params() + safety.safety_params(),
                                 on_change=self._param_changed)
        self.params.params[self.params.index["MAV_SYS_ID"]].value = float(sysid)
        self.missions: Missions | None = None  # set by the ground-station side, which speaks the protocol
        self.flight = FlightModes(self)  # PX4's modes: what HEARTBEAT says, DO_SET_MODE, sticks, offboard
        self.runner: MissionRunner | None = None
        self._builders: dict[int, Callable[[Snapshot], Any]] = {}
        C = bindings.MavCmd
        self.flight_commands = {int(c) for c in (
            C.MAV_CMD_COMPONENT_ARM_DISARM, C.MAV_CMD_NAV_TAKEOFF, C.MAV_CMD_NAV_LAND, C.MAV_CMD_NAV_RETURN_TO_LAUNCH,
            C.MAV_CMD_DO_SET_MODE, C.MAV_CMD_DO_REPOSITION, C.MAV_CMD_MISSION_START, C.MAV_CMD_DO_PAUSE_CONTINUE,
            C.MAV_CMD_DO_SET_MISSION_CURRENT, C.MAV_CMD_DO_LAND_START, C.MAV_CMD_DO_CHANGE_SPEED, C.MAV_CMD_DO_ORBIT)}
        self.commander: Hashable = None  # TABLET or a ground station's system id: the link watched
        self.heard: dict[Hashable, float] = {}
        # the links' clock: the wall clock in the node (links keep real time whatever --speed is,
        # and so do their timeouts); None: the times the callers give (sans-IO use)
        self.clock: Callable[[], float] | None = None
        self.link_lost_at: float | None = None
        self.failsafe = ""  # "", "hover", "return", "land"
        self.fence: list[safety.Area] = []
        self.breached: str | None = None
        self.rally: list[tuple[float, float]] = []  # lat, lon
        self.battery_level = 0  # 0 fine, 1 low, 2 critical, 3 emergency
        self._last_state = vehicle.state
        self._was_armed = vehicle.armed
        for p in self.params.params:
            self._param_changed(p)

    @property
    def tablet_heard(self) -> float | None:
        return self.heard.get(TABLET)

    def attach_missions(self, missions: Missions, emit: Callable[[Any], None],
                        warn: Callable[[str], None] | None = None) -> None:
        """The ground-station side's mission protocol, how to tell every ground station, and how
        to tell them why an item was refused."""
        self.missions = missions
        missions.on_plan = self._plan_changed
        if warn is not None:
            missions.warn = warn
        missions.altitude_problem = self._altitude_problem
        self.runner = MissionRunner(self.b, self.vehicle, missions.mission, emit, self.say)

    # -- parameters -----------------------------------------------------------------------------
    def _param_changed(self, p: Param) -> None:
        v = self.vehicle
        if not isinstance(v, SimVehicle):
            return
        lim = v.limits
        if p.name == "MPC_XY_VEL_MAX":
            lim.h_speed = p.value
        elif p.name == "MPC_Z_VEL_MAX_UP":
            lim.v_speed = p.value
        elif p.name == "MIS_TAKEOFF_ALT":
            lim.takeoff_alt = p.value
        elif p.name == "RTL_RETURN_ALT":
            lim.return_alt = p.value
        elif p.name == "TT_MAX_DIST":
            lim.max_dist = p.value

    # -- plans ------------------------------------------------------------------------------------
    def _plan_changed(self, mission_type: int) -> None:
        T = self.b.MavMissionType
        assert self.missions is not None
        if mission_type == int(T.MAV_MISSION_TYPE_MISSION) and self.runner is not None:
            self.runner.new_plan()
        elif mission_type == int(T.MAV_MISSION_TYPE_FENCE):
            self.fence = safety.fence_areas(self.b, self.missions.fence())
            self.breached = None
            self.say(INFO, f"geofence: {len(self.fence)} areas" if self.fence else "geofence cleared")
        elif mission_type == int(T.MAV_MISSION_TYPE_RALLY):
            self.rally = safety.rally_points(self.missions.rally())
            self._place_rally()
            self.say(INFO, f"rally points: {len(self.rally)}")

    def _altitude_problem(self, item: Any) -> str | None:
        """Why a mission item's altitude cannot be flown (above home, within the vehicle's limits)."""
        F, v = self.b.MavFrame, self.vehicle
        alt = float(item.z)
        if item.frame in (int(F.MAV_FRAME_GLOBAL), int(F.MAV_FRAME_GLOBAL_INT)):
            alt -= v.home.alt
        top = v.limits.max_alt if isinstance(v, SimVehicle) else math.inf
        if not 0 <= alt <= top:
            return f"altitude {alt:g} m above home is outside 0..{top:g} m"
        return None

    def _place_rally(self) -> None:
        if isinstance(self.vehicle, SimVehicle):
            self.vehicle.rally = [safety.local(self.vehicle.home, lat, lon) for lat, lon in self.rally]

    def fence_active(self) -> bool:
        return bool(self.fence) or self.params["GF_MAX_HOR_DIST"] > 0 or self.params["GF_MAX_VER_DIST"] > 0

    # -- actions (Refused says why not) ---------------------------------------------------------
    def start_mission(self, first: int | None = None) -> None:
        if self.runner is None:
            raise Refused("no mission uploaded")
        self.runner.start(first)

    def fly_trajectory(self, route: list, name: str = "trajectory") -> None:  # type: ignore[type-arg]
        self.vehicle.fly(route)
        self.say(INFO, f"flying {name}: {len(route)} waypoints")

    def set_home(self, lat: float, lon: float, alt: float) -> None:
        if not (-90 <= lat <= 90 and -180 <= lon <= 180 and math.isfinite(alt)):
            raise Refused("home position out of range")
        if isinstance(self.vehicle, SimVehicle):
            safety.move_home(self.vehicle, Home(lat, lon, alt))
            self._place_rally()
        else:
            raise Refused("this vehicle's home cannot be moved")
        self.say(INFO, f"home set: {lat:.6f}, {lon:.6f}, {alt:.1f} m")
        home = self._builders.get(self.b.HomePosition.MSG_ID)
        if home is not None and self.runner is not None:
            self.runner.emit(home(self.vehicle.snapshot()))  # ground stations learn it at once, as from PX4

    def mission_command(self, cmd: int, p: list[float], position: tuple[float, float, float]) -> int | None:
        """The mission and safety commands (COMMAND_LONG/INT): a MAV_RESULT, None if not one of
        them; Refused says why not. `p`: params 1-4, `position`: lat, lon, alt (params 5-7)."""
        C, A = self.b.MavCmd, self.b.MavResult
        runner = self.runner
        if cmd == int(C.MAV_CMD_DO_SET_HOME):
            s = self.vehicle.snapshot()
            if _finite(p[0], 0) >= 0.5:
                self.set_home(s.lat, s.lon, s.home.alt)  # the ground under the vehicle
            else:
                lat, lon, alt = position
                if not all(math.isfinite(x) for x in position):
                    raise Refused("DO_SET_HOME needs a position (or param1 = 1 for here)")
                self.set_home(lat, lon, alt)
            return int(A.MAV_RESULT_ACCEPTED)
        if cmd == int(C.MAV_CMD_DO_CHANGE_SPEED):
            speed = -1.0 if p[1] is None or math.isnan(p[1]) else float(p[1])  # NaN: unused, as -1
            limit = self.params["MPC_XY_VEL_MAX"]
            if speed == -1.0:
                return int(A.MAV_RESULT_ACCEPTED)  # -1: no change, as MAVLink defines
            if not 0 < speed <= limit:
                raise Refused(f"speed {speed:g} m/s is outside 0..{limit:g} m/s (MPC_XY_VEL_MAX)")
            if runner is None:
                raise Refused("no speed to change")
            runner.change_speed(speed)
            self.say(INFO, f"speed {speed:g} m/s")
            return int(A.MAV_RESULT_ACCEPTED)
        if runner is None:
            return None
        if cmd == int(C.MAV_CMD_DO_PAUSE_CONTINUE):
            if _finite(p[0], -1) == 0:
                if runner.running:
                    runner.pause()
                elif self.vehicle.state.airborne:
                    self.vehicle.hover()
                else:
                    raise Refused("on the ground: nothing to pause")
                return int(A.MAV_RESULT_ACCEPTED)
            if _finite(p[0], -1) == 1:
                if runner.running:
                    return int(A.MAV_RESULT_ACCEPTED)
                if runner.state not in (3, 4):  # ACTIVE, PAUSED
                    raise Refused("no paused mission to continue")
                if not self.vehicle.state.airborne:
                    raise Refused("on the ground: start the mission instead")
                runner.start()
                return int(A.MAV_RESULT_ACCEPTED)
            raise Refused("DO_PAUSE_CONTINUE param1 must be 0 (pause) or 1 (continue)")
        if cmd == int(C.MAV_CMD_DO_SET_MISSION_CURRENT):
            if p[0] is not None and math.isinf(p[0]):
                raise Refused("mission item inf?")
            seq = _finite(p[0], -1)
            if seq != -1:
                if seq != int(seq):
                    raise Refused(f"mission item {seq:g}?")
                runner.set_current(int(seq))
            if _finite(p[1], 0) == 1:
                runner.jumps = {}
                if not runner.running:
                    runner.state = 2 if runner.items() else 1  # NOT_STARTED
                runner._tell_current()
            return int(A.MAV_RESULT_ACCEPTED)
        if cmd == int(C.MAV_CMD_DO_LAND_START):
            runner.land_start()
            return int(A.MAV_RESULT_ACCEPTED)
        if cmd == int(C.MAV_CMD_DO_SET_ROI_LOCATION):
            lat, lon, _ = position
            if not (math.isfinite(lat) and math.isfinite(lon) and -90 <= lat <= 90 and -180 <= lon <= 180):
                raise Refused("DO_SET_ROI_LOCATION needs a position")
            runner.roi = (lat, lon)
            self.say(INFO, f"facing {lat:.6f}, {lon:.6f}")
            return int(A.MAV_RESULT_ACCEPTED)
        if cmd == int(C.MAV_CMD_DO_SET_ROI_NONE):
            runner.roi = None
            return int(A.MAV_RESULT_ACCEPTED)
        return None

    def set_current(self, seq: int) -> None:
        """MISSION_SET_CURRENT: the answer is MISSION_CURRENT (the old item, if refused)."""
        if self.runner is None:
            return
        try:
            self.runner.set_current(seq)
        except Refused as e:
            self.say(WARNING, f"MISSION_SET_CURRENT refused: {e}")
            self.runner._tell_current()

    # -- links ------------------------------------------------------------------------------------
    def heard_tablet(self, now: float) -> None:
        self._heard(TABLET, now)

    def heard_gcs(self, sysid: int, now: float, msg: Any = None) -> None:
        """A ground station's HEARTBEAT keeps its link alive (as PX4 watches a GCS's heartbeats:
        a peer that sends none is never watched); a set-point stream commands the flight."""
        if msg is None or isinstance(msg, self.b.Heartbeat):
            self._heard(sysid, now)
        if msg is not None and type(msg).__name__ in STEERING:
            self.commanded_by(sysid, now)

    def _link_time(self, now: float) -> float:
        return self.clock() if self.clock is not None else now

    def _heard(self, who: Hashable, now: float) -> None:
        now = self._link_time(now)
        self.heard[who] = now
        if who == self.commander and self.link_lost_at is not None:
            self.say(INFO, f"{self._link_name(who)} link back after {now - self.link_lost_at:.1f} s")
            self.link_lost_at = None
            self.failsafe = ""

    def commanded_by(self, who: Hashable, now: float) -> None:
        """The tablet (TABLET) or a ground station (its system id) gave a flight command: from
        now on its link is the one watched (once it has been heard)."""
        if who != self.commander:
            self.commander = who
            self.link_lost_at = None
            self.failsafe = ""

    @staticmethod
    def _link_name(who: Hashable) -> str:
        return "tablet" if who == TABLET else f"ground station {who}"

    # -- time ---------------------------------------------------------------------------------------
    def step(self, now: float, dt: float) -> None:
        v = self.vehicle
        v.step(dt)
        self._home_at_arming()
        if self.runner is not None:
            self.runner.step(now)
        self._watch_fence()
        self._watch_battery()
        self._watch_link(now)
        state = v.state
        if state is not self._last_state:
            self.say(INFO, f"{state.value}")
            self._last_state = state

    def _home_at_arming(self) -> None:
        v = self.vehicle
        armed = v.armed
        if armed and not self._was_armed and isinstance(v, SimVehicle) and v.state is State.LANDED \
                and math.hypot(v.pos[0], v.pos[1]) > 0.01:
            s = v.snapshot()
            self.set_home(s.lat, s.lon, s.home.alt)
        self._was_armed = armed

    def _watch_fence(self) -> None:
        v = self.vehicle
        if not self.fence_active() or not v.state.airborne or not isinstance(v, SimVehicle):
            self.breached = None if not v.state.airborne else self.breached
            return
        n, e, alt = safety.braking_point(v.pos, v.vel, v.limits.accel)  # PX4 tests where a stop would end
        why = safety.breach(self.fence, v.home, n, e, alt, self.params["GF_MAX_HOR_DIST"],
                            self.params["GF_MAX_VER_DIST"])
        if why is None:
            if self.breached is not None:
                self.say(INFO, "geofence: back inside")
            self.breached = None
            return
        if self.breached is not None:
            return
        self.breached = why
        action = safety.GF_ACTIONS.get(int(self.params["GF_ACTION"]), "hold")
        self.say(CRITICAL, f"geofence breached: {why}" + (f": {action}" if action else ""))
        if action in ("hold", "return", "land"):
            self._act("hover" if action == "hold" else action)

    def _watch_battery(self) -> None:
        v = self.vehicle
        if not v.armed:
            self.battery_level = 0
            return
        charge = v.snapshot().battery_pct / 100.0
        level = 3 if charge <= self.params["BAT_EMERGEN_THR"] else 2 if charge <= self.params["BAT_CRIT_THR"] \
            else 1 if charge <= self.params["BAT_LOW_THR"] else 0
        if level <= self.battery_level:
            return
        self.battery_level = level
        act = int(self.params["COM_LOW_BAT_ACT"])
        name = {1: "low", 2: "critical", 3: "emergency"}[level]
        action = ""
        if v.state.airborne and level >= 2 and act in (2, 3):
            action = "land" if act == 2 or level == 3 else "return"
        self.say(CRITICAL if level >= 2 else WARNING, f"battery {name}: {charge * 100:.0f} %"
                 + (f": {'returning' if action == 'return' else 'landing'}" if action else ""))
        if action:
            self._act(action)

    def _watch_link(self, now: float) -> None:
        now = self._link_time(now)
        who = self.commander
        if who is None or not self.vehicle.state.airborne or who not in self.heard:
            return
        silent = now - self.heard[who]
        limit = self.params["COM_DL_LOSS_T"]
        if silent < limit:
            return
        if self.link_lost_at is None:
            self.link_lost_at = now
            action = {0: "", 1: "hover", 2: "hover", 3: "land"}.get(int(self.params["NAV_DLL_ACT"]), "hover")
            self.say(CRITICAL, f"{self._link_name(who)} link lost ({silent:.0f} s silent): {action or 'no action'}")
            self._failsafe(action)
        elif self.failsafe == "hover" and int(self.params["NAV_DLL_ACT"]) == 2 \
                and now - self.link_lost_at >= self.params["COM_RTL_AFTER_T"]:
            self.say(CRITICAL, f"{self._link_name(who)} link still lost: returning home")
            self._failsafe("return")

    def _failsafe(self, action: str) -> None:
        self.failsafe = action
        self._act(action)

    def _act(self, action: str) -> None:
        try:
            if action == "hover" and self.vehicle.state not in (State.LANDING, State.RETURNING):
                self.vehicle.hover()
            elif action == "land" and self.vehicle.state is not State.LANDING:
                self.vehicle.land()
            elif action == "return" and self.vehicle.state not in (State.LANDING, State.RETURNING):
                self.vehicle.return_home()
        except Refused:
            pass

    # -- what ground stations see ---------------------------------------------------------------
    def wrap_telemetry(self, builders: dict[int, Callable[[Snapshot], Any]]) -> None:
        """SYS_STATUS's geofence bits, BATTERY_STATUS's charge state and MISSION_CURRENT from the
        autopilot's own state (the ground-station side's builders, changed in place)."""
        b = self.b
        self._builders = builders
        sys_status, battery = builders.get(b.SysStatus.MSG_ID), builders.get(b.BatteryStatus.MSG_ID)
        fence_bit = int(b.MavSysStatusSensor.MAV_SYS_STATUS_GEOFENCE)

        def sys_status_msg(s: Snapshot) -> Any:
            assert sys_status is not None
            m = sys_status(s)
            if self.fence_active():
                m.onboard_control_sensors_present |= fence_bit
                m.onboard_control_sensors_enabled |= fence_bit
                if self.breached is not None:
                    m.onboard_control_sensors_health &= ~fence_bit
                else:
                    m.onboard_control_sensors_health |= fence_bit
            return m

        def battery_msg(s: Snapshot) -> Any:
            assert battery is not None
            m = battery(s)
            m.charge_state = 1 + self.battery_level  # MAV_BATTERY_CHARGE_STATE_OK .. _EMERGENCY
            return m

        if sys_status is not None:
            builders[b.SysStatus.MSG_ID] = sys_status_msg
        if battery is not None:
            builders[b.BatteryStatus.MSG_ID] = battery_msg
        if self.runner is not None:
            runner = self.runner
            builders[b.MissionCurrent.MSG_ID] = lambda s: runner.mission_current()

    def snapshot(self) -> Snapshot:
        return self.vehicle.snapshot()


def _finite(x: float | None, default: float) -> float:
    return default if x is None or not math.isfinite(x) else float(x)
