"""The vehicle's brain, shared by every link that commands it: the tablet over DTT and any
number of ground stations. It owns the vehicle, its parameters and its mission, applies the
parameters to the vehicle, starts missions (taking off first when on the ground), and watches
the tablet's link: silent for COM_DL_LOSS_T seconds, the vehicle hovers (or lands, or returns,
by NAV_DLL_ACT); silent COM_RTL_AFTER_T more, it returns home and lands, as autopilots' GCS
failsafes do. Everything it does is told through `say` (STATUSTEXT and TT_LOG, in the node).
"""

from __future__ import annotations

from collections.abc import Callable

from ...wire.bindings import Bindings
from .flight import FlightModes
from .missions import Missions
from .params import Param, Parameters, default_params
from .vehicle import Refused, SimVehicle, Snapshot, State, Vehicle

Say = Callable[[int, str], None]  # (MAV_SEVERITY, text)
INFO, WARNING, CRITICAL = 6, 4, 2


class Autopilot:
    def __init__(self, bindings: Bindings, vehicle: Vehicle, sysid: int = 1, say: Say | None = None,
                 params: list[Param] | None = None) -> None:
        self.b = bindings
        self.vehicle = vehicle
        self.sysid = sysid
        self.say = say or (lambda severity, text: None)
        self.params = Parameters(bindings, params or default_params(), on_change=self._param_changed)
        self.params.params[self.params.index["MAV_SYS_ID"]].value = float(sysid)
        self.missions: Missions | None = None  # set by the ground-station side, which speaks the protocol
        self.flight = FlightModes(self)  # PX4's modes: what HEARTBEAT says, DO_SET_MODE, sticks, offboard
        self._mission_after_takeoff = False
        self.tablet_heard: float | None = None  # the link-loss watch starts once the tablet was heard
        self.link_lost_at: float | None = None
        self.failsafe = ""  # "", "hover", "return", "land"
        self._last_state = vehicle.state
        for p in self.params.params:
            self._param_changed(p)

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

    # -- actions (Refused says why not) ---------------------------------------------------------
    def start_mission(self) -> None:
        items = self.missions.mission() if self.missions is not None else []
        if not items:
            raise Refused("no mission uploaded")
        s = self.vehicle.snapshot()
        assert self.missions is not None
        route = self.missions.waypoints(items, s.home, (s.n, s.e, s.alt_rel))
        if not route:
            raise Refused("the mission has no waypoint to fly")
        if self.vehicle.state is State.LANDED:
            if not self.vehicle.armed:
                raise Refused("not armed")
            self.vehicle.takeoff(route[0].alt)
            self._mission_after_takeoff = True
            self.say(INFO, "mission: taking off first")
            return
        self.vehicle.fly(route)
        self.say(INFO, f"mission started: {len(route)} waypoints")

    def fly_trajectory(self, route: list, name: str = "trajectory") -> None:  # type: ignore[type-arg]
        self.vehicle.fly(route)
        self.say(INFO, f"flying {name}: {len(route)} waypoints")

    # -- time ---------------------------------------------------------------------------------------
    def heard_tablet(self, now: float) -> None:
        self.tablet_heard = now
        if self.link_lost_at is not None:
            self.say(INFO, f"tablet link back after {now - self.link_lost_at:.1f} s")
            self.link_lost_at = None
            self.failsafe = ""

    def step(self, now: float, dt: float) -> None:
        self.vehicle.step(dt)
        self._watch_link(now)
        state = self.vehicle.state
        if state is not self._last_state:
            if self._mission_after_takeoff and self._last_state is State.TAKING_OFF and state is State.HOVERING:
                self._mission_after_takeoff = False
                try:
                    self.start_mission()
                except Refused as e:
                    self.say(WARNING, f"mission not started: {e}")
            if state is State.HOVERING and self._last_state is State.TRAJECTORY:
                self._mission_done()
            self.say(INFO, f"{state.value}")
            self._last_state = state

    def _mission_done(self) -> None:
        end = self.missions.ends_with(self.missions.mission()) if self.missions is not None else None
        try:
            if end == "land":
                self.vehicle.land()
            elif end == "return":
                self.vehicle.return_home()
        except Refused:
            pass

    def _watch_link(self, now: float) -> None:
        if self.tablet_heard is None or not self.vehicle.state.airborne:
            return
        silent = now - self.tablet_heard
        limit = self.params["COM_DL_LOSS_T"]
        if silent < limit:
            return
        if self.link_lost_at is None:
            self.link_lost_at = now
            action = {0: "", 1: "hover", 2: "hover", 3: "land"}.get(int(self.params["NAV_DLL_ACT"]), "hover")
            self.say(CRITICAL, f"tablet link lost ({silent:.0f} s silent): {action or 'no action'}")
            self._failsafe(action)
        elif self.failsafe == "hover" and int(self.params["NAV_DLL_ACT"]) == 2 \
                and now - self.link_lost_at >= self.params["COM_RTL_AFTER_T"]:
            self.say(CRITICAL, "tablet link still lost: returning home")
            self._failsafe("return")

    def _failsafe(self, action: str) -> None:
        self.failsafe = action
        try:
            if action == "hover" and self.vehicle.state not in (State.LANDING, State.RETURNING):
                self.vehicle.hover()
            elif action == "land":
                self.vehicle.land()
            elif action == "return":
                self.vehicle.return_home()
        except Refused:
            pass

    def snapshot(self) -> Snapshot:
        return self.vehicle.snapshot()
