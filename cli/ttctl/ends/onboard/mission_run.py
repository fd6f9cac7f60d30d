"""Mission execution, sans-IO: the stored mission flown item by item, as PX4's navigator does.

The runner owns the mission's place (`current`, the item number ground stations see in
MISSION_CURRENT) and its state (MAVLink MISSION_STATE: no mission, not started, active, paused,
complete). It flies one item at a time through the vehicle's commands and watches the vehicle:
an item is reached when the vehicle arrives (and has held for the item's time), then
MISSION_ITEM_REACHED and MISSION_CURRENT go to every ground station. DO items take effect
between positions: DO_CHANGE_SPEED, DO_JUMP (with its repeat count), DO_SET_ROI_LOCATION /
DO_SET_ROI / DO_SET_ROI_NONE (the vehicle faces the point), CONDITION_YAW (turn, then go on),
DO_LAND_START (a marker, where a landing sequence starts). Anything else that commands the
vehicle (a hold, a landing, a tablet's set-point or trajectory, a failsafe) suspends the mission
where it is (PAUSED): its remaining items and its end never run unless the mission is started
again, which continues from the current item, as PX4's mission mode does after a hold.

`step(now)` advances; `emit(msg)` sends to every ground station; `say(severity, text)` tells.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ...wire.bindings import Bindings
from .vehicle import EARTH_RADIUS, MIN_ALT, Home, Refused, State, Waypoint

# MAVLink MISSION_STATE (common.xml)
NO_MISSION, NOT_STARTED, ACTIVE, PAUSED, COMPLETE = 1, 2, 3, 4, 5
FOREVER = 1e9  # s: a hold the runner ends itself
YAW_DONE = math.radians(3.0)  # CONDITION_YAW is reached within this
INFO, WARNING = 6, 4


@dataclass
class _Leg:
    """What the vehicle was told for the current item, to tell arrival from interruption."""

    kind: str  # "fly", "takeoff", "land", "return", "yaw"
    route: Any = None  # the vehicle's route list while flying this leg
    hold: float = 0.0  # s to wait at the position once arrived (FOREVER: unlimited)
    arrived_at: float | None = None
    then_land: bool = False  # a landing item with a position: fly there, then land
    yaw: float | None = None
    orders: int = -1  # the vehicle's order count once this leg was given: another order is a takeover


class MissionRunner:
    def __init__(self, bindings: Bindings, vehicle: Any, items: Callable[[], list[Any]],
                 emit: Callable[[Any], None], say: Callable[[int, str], None]) -> None:
        self.b = bindings
        self.vehicle = vehicle
        self.items = items
        self.emit = emit
        self.say = say
        C = bindings.MavCmd
        self.NAV = {int(C.MAV_CMD_NAV_WAYPOINT), int(C.MAV_CMD_NAV_TAKEOFF), int(C.MAV_CMD_NAV_LOITER_TIME),
                    int(C.MAV_CMD_NAV_LOITER_UNLIM), int(C.MAV_CMD_NAV_LAND), int(C.MAV_CMD_NAV_RETURN_TO_LAUNCH),
                    int(C.MAV_CMD_NAV_DELAY), int(C.MAV_CMD_CONDITION_YAW)}
        self.current = 0
        self.state = NO_MISSION
        self.running = False
        self.leg: _Leg | None = None
        self.jumps: dict[int, int] = {}  # DO_JUMP item -> jumps done
        self.speed: float | None = None  # m/s from DO_CHANGE_SPEED
        self.roi: tuple[float, float] | None = None  # lat, lon the vehicle faces
        self.fixed_yaw: float | None = None  # rad from CONDITION_YAW
        self.takeoff_first = False

    # -- what ground stations see -------------------------------------------------------------
    def mission_current(self) -> Any:
        n = len(self.items())
        state = NO_MISSION if n == 0 else self.state
        return self.b.MissionCurrent(seq=min(self.current, max(0, n - 1)), total=n, mission_state=state,
                                     mission_mode=1 if self.running else 2)

    def _tell_current(self) -> None:
        self.emit(self.mission_current())

    # -- the plan changes -----------------------------------------------------------------------
    def new_plan(self) -> None:
        """A mission was uploaded or cleared: it starts from its first item when started."""
        was = self.running
        self._stop(PAUSED)
        self.current, self.jumps = 0, {}
        self.state = NOT_STARTED if self.items() else NO_MISSION
        self.speed, self.roi, self.fixed_yaw = None, None, None
        if was:
            self.say(WARNING, "mission replaced in flight: holding")
            with contextlib.suppress(Refused):
                self.vehicle.hover()
        self._tell_current()

    # -- commands -------------------------------------------------------------------------------
    def start(self, first: int | None = None) -> None:
        """MISSION_START, mode AUTO.MISSION, DO_PAUSE_CONTINUE(continue): fly from the current
        item (from `first` if given; from the start if the mission was complete)."""
        items = self.items()
        if not items:
            raise Refused("no mission uploaded")
        if first is not None and not 0 <= first < len(items):
            raise Refused(f"the mission has no item {first}")
        v = self.vehicle
        if v.state is State.LANDED and not v.armed:
            raise Refused("not armed")
        if v.state is State.LANDING:
            raise Refused("busy landing", temporary=True)
        if first is not None:
            self.current = first
        elif self.state == COMPLETE:
            self.current, self.jumps = 0, {}
        self.running, self.state = True, ACTIVE
        self.leg = None
        self.takeoff_first = v.state is State.LANDED
        self._tell_current()
        self.say(INFO, f"mission {'resumed' if self.current else 'started'} at item {self.current}")

    def pause(self) -> None:
        """DO_PAUSE_CONTINUE(pause): hold where the vehicle is; the mission stays at its item."""
        if not self.running:
            raise Refused("no mission is running")
        self.vehicle.hover()
        self._stop(PAUSED)
        self._tell_current()
        self.say(INFO, f"mission paused at item {self.current}")

    def set_current(self, seq: int) -> None:
        """MISSION_SET_CURRENT / DO_SET_MISSION_CURRENT: the next item to fly; a running
        mission goes there now."""
        items = self.items()
        if not 0 <= seq < len(items):
            raise Refused(f"the mission has no item {seq}")
        self.current = seq
        if self.state == COMPLETE:
            self.state = PAUSED
        if self.running:
            self.leg = None
        self._tell_current()

    def land_start(self) -> None:
        """DO_LAND_START: fly the mission from its landing sequence."""
        C = self.b.MavCmd
        for i, item in enumerate(self.items()):
            if item.command == int(C.MAV_CMD_DO_LAND_START):
                if self.vehicle.state is State.LANDED:
                    raise Refused("on the ground")
                self.start(i)
                return
        raise Refused("the mission has no landing sequence (DO_LAND_START)")

    def change_speed(self, speed: float) -> None:
        """DO_CHANGE_SPEED as a command: the speed from now on (in the mission, too)."""
        self.speed = speed
        if self.vehicle.state.airborne:
            self.vehicle.speed_cap = speed

    def reset(self) -> None:
        self.current, self.jumps = 0, {}
        self.state = NOT_STARTED if self.items() else NO_MISSION
        self._tell_current()

    # -- running --------------------------------------------------------------------------------
    def _stop(self, state: int) -> None:
        self.running = False
        self.leg = None
        self.state = state if self.items() else NO_MISSION

    def _interrupted(self) -> bool:
        """Did something else take the vehicle over since the runner gave it this leg?"""
        leg, v = self.leg, self.vehicle
        assert leg is not None
        if leg.orders >= 0 and getattr(v, "orders", leg.orders) != leg.orders:
            return True  # told something else since (a hold, a goto, a return...), whatever its state
        if leg.kind in ("fly", "yaw"):
            return v.state is not State.TRAJECTORY or v.route is not leg.route
        if leg.kind in ("takeoff", "pretakeoff"):
            return v.state not in (State.TAKING_OFF, State.HOVERING)
        if leg.kind == "land":
            return v.state not in (State.LANDING, State.LANDED)
        return v.state not in (State.RETURNING, State.LANDING, State.LANDED)

    def flying(self) -> bool:
        """The vehicle flies this mission's items (a take-off item, a landing, a hold between legs):
        PX4 reports MISSION through all of them."""
        return self.running and (self.leg is None or not self._interrupted())

    def step(self, now: float) -> None:
        if not self.running:
            if self.roi is not None and self.vehicle.state is State.HOVERING:
                self._face_roi()  # a hold faces the region of interest too
            return
        for _ in range(len(self.items()) + 2):  # DO items take no time; a jump loop waits a step
            if not self.running:
                return
            if self.leg is not None:
                if self._interrupted():
                    self._stop(PAUSED)
                    self._tell_current()
                    self.say(INFO, f"mission suspended at item {self.current}")
                    return
                if not self._leg_done(now):
                    self._face_roi()
                    return
                if self.leg.kind == "pretakeoff":
                    self.leg = None
                    continue
                self._reached()
                continue
            self._begin(now)
            if self.leg is not None:
                self.leg.orders = getattr(self.vehicle, "orders", -1)
                return

    def _leg_done(self, now: float) -> bool:
        leg, v = self.leg, self.vehicle
        assert leg is not None
        if leg.kind in ("takeoff", "pretakeoff"):
            return v.state is State.HOVERING
        if leg.kind in ("land", "return"):
            return v.state is State.LANDED
        if v.hold_until is None:  # not there yet
            return False
        if leg.kind == "yaw" and abs(((leg.yaw or 0.0) - v.yaw + math.pi) % (2 * math.pi) - math.pi) > YAW_DONE:
            return False
        if leg.arrived_at is None:
            leg.arrived_at = now
        if leg.then_land:
            v.land()
            leg.kind, leg.then_land = "land", False
            leg.orders = getattr(v, "orders", -1)
            return False
        return leg.hold < FOREVER and now - leg.arrived_at >= leg.hold

    def _reached(self) -> None:
        self.emit(self.b.MissionItemReached(seq=self.current))
        ended = self.leg is not None and self.leg.kind in ("land", "return")
        self.leg = None
        self._advance(self.current + 1, ended)

    def _advance(self, seq: int, ended: bool = False) -> None:
        if ended or seq >= len(self.items()):
            self._stop(COMPLETE)
            self.current = max(0, len(self.items()) - 1)
            self._tell_current()
            self.say(INFO, "mission complete")
            if self.vehicle.state is State.TRAJECTORY:
                self.vehicle.hover()  # PX4 holds after the last item
            return
        self.current = seq
        self._tell_current()

    def _begin(self, now: float) -> None:
        """Start the current item: DO items act and advance; a position item becomes a leg."""
        C, v = self.b.MavCmd, self.vehicle
        items = self.items()
        item = items[self.current]
        cmd = item.command
        try:
            if self.takeoff_first:
                self.takeoff_first = False
                if cmd != int(C.MAV_CMD_NAV_TAKEOFF):
                    alt = next((self._position(i)[2] for i in items[self.current:] if i.command in self.NAV
                                and i.command != int(C.MAV_CMD_CONDITION_YAW)), v.limits.takeoff_alt)
                    v.takeoff(max(MIN_ALT, alt) if alt > 0 else None)
                    self.say(INFO, "mission: taking off first")
                    self.leg = _Leg("pretakeoff")
                    return
            if cmd not in self.NAV:
                self._do(item)
                return
            if cmd == int(C.MAV_CMD_NAV_TAKEOFF) and v.state is State.LANDED:
                v.takeoff(self._position(item)[2])
                self.leg = _Leg("takeoff")
            elif cmd == int(C.MAV_CMD_NAV_RETURN_TO_LAUNCH):
                v.return_home()
                self.leg = _Leg("return")
            elif cmd == int(C.MAV_CMD_NAV_LAND) and item.x == 0 and item.y == 0:
                v.land()
                self.leg = _Leg("land")
            elif cmd == int(C.MAV_CMD_CONDITION_YAW):
                goal = math.radians(float(item.param1))
                if item.param4 >= 0.5:  # relative to the current heading
                    goal = v.yaw + goal * (-1.0 if item.param3 < 0 else 1.0)
                self.fixed_yaw = goal
                self._fly(Waypoint(v.pos[0], v.pos[1], max(MIN_ALT, -v.pos[2]), yaw=goal, hold=FOREVER), "yaw")
                assert self.leg is not None
                self.leg.yaw = goal
            elif cmd == int(C.MAV_CMD_NAV_DELAY):
                self._fly(Waypoint(v.pos[0], v.pos[1], max(MIN_ALT, -v.pos[2]), yaw=self._yaw(item, None),
                                   hold=FOREVER), "fly", float(item.param1))
            else:
                n, e, alt = self._position(item)
                hold = 0.0
                if cmd == int(C.MAV_CMD_NAV_LOITER_UNLIM):
                    hold = FOREVER
                elif cmd in (int(C.MAV_CMD_NAV_WAYPOINT), int(C.MAV_CMD_NAV_LOITER_TIME)) \
                        and math.isfinite(item.param1):
                    hold = max(0.0, float(item.param1))
                yaw_param = None if cmd in (int(C.MAV_CMD_NAV_TAKEOFF), int(C.MAV_CMD_NAV_LAND)) else item.param4
                self._fly(Waypoint(n, e, max(MIN_ALT, alt), yaw=self._yaw(item, yaw_param), speed=self.speed,
                                   hold=FOREVER), "fly", hold)
                if cmd == int(C.MAV_CMD_NAV_LAND):
                    assert self.leg is not None
                    self.leg.then_land = True
        except Refused as e:  # the vehicle cannot fly this item now: hold, never skip it
            self.say(WARNING, f"mission item {self.current} not flown: {e}")
            self._stop(PAUSED)
            self._tell_current()
            if v.state is State.TRAJECTORY:
                v.hover()

    def _fly(self, w: Waypoint, kind: str, hold: float = 0.0) -> None:
        self.vehicle.fly([w])
        self.leg = _Leg(kind, route=self.vehicle.route, hold=hold)

    def _do(self, item: Any) -> None:
        C = self.b.MavCmd
        cmd = item.command
        nxt = self.current + 1
        if cmd == int(C.MAV_CMD_DO_CHANGE_SPEED):
            if math.isfinite(item.param2) and item.param2 > 0:
                self.speed = float(item.param2)
        elif cmd == int(C.MAV_CMD_DO_JUMP):
            target, repeat = int(item.param1), int(item.param2)
            done = self.jumps.get(self.current, 0)
            if done < repeat:
                self.jumps[self.current] = done + 1
                nxt = target
        elif cmd == int(C.MAV_CMD_DO_SET_ROI_LOCATION) or (
                cmd == int(C.MAV_CMD_DO_SET_ROI) and int(item.param1) == 3):  # MAV_ROI_LOCATION
            self.roi = (item.x / 1e7, item.y / 1e7)
        elif cmd == int(C.MAV_CMD_DO_SET_ROI_NONE) or cmd == int(C.MAV_CMD_DO_SET_ROI):
            self.roi = None
        # DO_LAND_START: only a marker
        self.emit(self.b.MissionItemReached(seq=self.current))
        self._advance(nxt)

    def _yaw(self, item: Any, param4: float | None) -> float | None:
        if param4 is not None and math.isfinite(param4):
            return math.radians(float(param4))
        if self.roi is not None:
            return None  # faced each step
        return self.fixed_yaw

    def _face_roi(self) -> None:
        v = self.vehicle
        if self.roi is None or (self.running and (self.leg is None or self.leg.kind != "fly")):
            return
        home: Home = v.home
        rn = math.radians(self.roi[0] - home.lat) * EARTH_RADIUS
        re = math.radians(self.roi[1] - home.lon) * EARTH_RADIUS * math.cos(math.radians(home.lat))
        if math.hypot(rn - v.pos[0], re - v.pos[1]) > 0.5:
            v.target_yaw = math.atan2(re - v.pos[1], rn - v.pos[0])

    def _position(self, item: Any) -> tuple[float, float, float]:
        """An item's position in metres from home (north, east, altitude); latitude and
        longitude 0/0 mean 'here'."""
        F, v = self.b.MavFrame, self.vehicle
        home: Home = v.home
        n, e = v.pos[0], v.pos[1]
        if item.x != 0 or item.y != 0:
            n = math.radians(item.x / 1e7 - home.lat) * EARTH_RADIUS
            e = math.radians(item.y / 1e7 - home.lon) * EARTH_RADIUS * math.cos(math.radians(home.lat))
        z = float(item.z)
        if not math.isfinite(z):
            z = -v.pos[2]
        elif item.frame in (int(F.MAV_FRAME_GLOBAL), int(F.MAV_FRAME_GLOBAL_INT)):
            z -= home.alt  # above mean sea level to above home
        return n, e, z
