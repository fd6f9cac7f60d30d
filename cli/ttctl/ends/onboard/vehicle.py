"""The vehicle the onboard end flies: a small interface (`Vehicle`) and a kinematic simulation
of a multicopter behind it (`SimVehicle`), so that a bridge to a real autopilot can take its
place.

The simulation is a point mass with a velocity that follows the commanded one within an
acceleration limit, horizontal and vertical speed limits, a yaw-rate limit, attitude tilted
along the acceleration (as a multicopter must tilt to accelerate), and a battery that drains
with time aloft and speed. Positions are local north-east-down metres from home; latitude and
longitude follow from home by an equirectangular projection (exact enough over kilometres).
Everything is a function of the commands and the time steps: the same inputs give the same
flight, at any speed of the clock.
"""

from __future__ import annotations

import enum
import functools
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Protocol

EARTH_RADIUS = 6_378_137.0  # WGS84 semi-major axis, metres
MIN_ALT = 0.5  # m: set-points lower than this are refused (landing is its own command)
GRAVITY = 9.80665


class State(enum.Enum):
    LANDED = "landed"
    TAKING_OFF = "taking off"
    HOVERING = "hovering"
    MOVING = "moving to setpoint"
    TRAJECTORY = "flying trajectory"
    LANDING = "landing"
    RETURNING = "returning"
    MANUAL = "manual control"  # flown by a ground station's sticks (MANUAL_CONTROL)
    OFFBOARD = "offboard control"  # flown by a ground station's set-points (SET_POSITION_TARGET_*)

    @property
    def airborne(self) -> bool:
        return self is not State.LANDED


@dataclass
class Home:
    lat: float = 46.0503  # Ljubljana, where the thesis flew its drone
    lon: float = 14.4686
    alt: float = 295.0  # metres above mean sea level


@dataclass
class Limits:
    h_speed: float = 1.5  # m/s
    v_speed: float = 1.0  # m/s
    accel: float = 2.0  # m/s^2
    yaw_rate: float = math.radians(60.0)  # rad/s
    takeoff_alt: float = 2.0  # m above home, when a take-off does not say
    return_alt: float = 10.0  # m above home, when a return does not say
    max_alt: float = 120.0  # m above home: setpoints above are refused
    max_dist: float = 1000.0  # m from home, horizontally: set-points and waypoints beyond are refused (TT_MAX_DIST)


@dataclass
class Waypoint:
    n: float
    e: float
    alt: float  # m above home
    yaw: float | None = None  # rad, None: face the direction of travel
    speed: float | None = None  # m/s, None: the horizontal limit
    hold: float = 0.0  # s


@dataclass
class Refused(Exception):
    """A command the vehicle will not take now; `temporary` when it may later (busy)."""

    reason: str
    temporary: bool = False

    def __str__(self) -> str:
        return self.reason


class Vehicle(Protocol):
    """What the onboard end needs of a vehicle, simulated or real."""

    state: State
    armed: bool
    home: Home

    def arm(self) -> None: ...
    def disarm(self) -> None: ...
    def takeoff(self, alt: float | None = None) -> None: ...
    def takeoff_in_air(self, alt: float) -> bool: ...
    def land(self) -> None: ...
    def hover(self) -> None: ...
    def goto(self, n: float, e: float, alt: float, yaw: float | None = None) -> None: ...
    def fly(self, waypoints: list[Waypoint]) -> None: ...
    def return_home(self, alt: float | None = None) -> None: ...
    def steer(self, state: State, vel: tuple[float, float, float] | None = None,
              pos: tuple[float, float, float] | None = None, yaw: float | None = None,
              yaw_rate: float | None = None) -> None: ...
    def step(self, dt: float) -> None: ...
    def snapshot(self) -> Snapshot: ...


@dataclass(frozen=True)
class Snapshot:
    """Everything telemetry reports, taken at one instant: every message built from one
    snapshot agrees with every other."""

    time: float
    state: State
    armed: bool
    n: float
    e: float
    d: float
    vn: float
    ve: float
    vd: float
    roll: float
    pitch: float
    yaw: float
    yaw_rate: float
    lat: float
    lon: float
    alt_msl: float
    home: Home
    battery_pct: float
    battery_v: float
    current_a: float
    waypoint: int  # index of the trajectory waypoint being flown to, -1 if none

    @property
    def alt_rel(self) -> float:
        return -self.d

    @property
    def ground_speed(self) -> float:
        return math.hypot(self.vn, self.ve)

    @property
    def heading_deg(self) -> float:
        return math.degrees(self.yaw) % 360.0


def _order(method: Callable[..., Any]) -> Callable[..., Any]:
    """A command that, carried out (not refused), changes what the vehicle does: counted in
    `orders`, so that a mission can tell its own leg from something else taking over (a hold
    during a mission's take-off is still 'hovering', yet no longer the mission's)."""

    @functools.wraps(method)
    def run(self: SimVehicle, *args: Any, **kw: Any) -> Any:
        out = method(self, *args, **kw)
        self.orders += 1
        return out

    return run


@dataclass
class SimVehicle:
    home: Home = field(default_factory=Home)
    limits: Limits = field(default_factory=Limits)
    battery_wh: float = 60.0
    state: State = State.LANDED
    armed: bool = False
    time: float = 0.0
    pos: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])  # n, e, d
    vel: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    yaw: float = 0.0
    yaw_rate: float = 0.0
    roll: float = 0.0
    pitch: float = 0.0
    energy_wh: float = -1.0  # what is left; -1: full
    target: tuple[float, float, float] | None = None  # n, e, d being flown to
    target_yaw: float | None = None
    route: list[Waypoint] = field(default_factory=list)
    rally: list[tuple[float, float]] = field(default_factory=list)  # n, e: a return may land at one
    leg: int = -1
    hold_until: float | None = None
    speed_cap: float | None = None
    landed_after_return: bool = False
    vel_cmd: tuple[float, float, float] | None = None  # n, e, d m/s being flown (manual, offboard)
    yaw_rate_cmd: float | None = None  # rad/s, when steered by rate
    ground_since: float | None = None  # steered and touching the ground since (the land detector)
    orders: int = 0  # counts the commands that changed what the vehicle does (who flies it can tell a takeover)

    def __post_init__(self) -> None:
        if self.energy_wh < 0:
            self.energy_wh = self.battery_wh

    # -- commands ---------------------------------------------------------------------------
    def arm(self) -> None:
        if self.armed:
            return
        if self.state is not State.LANDED:
            raise Refused("already flying")
        if self.battery_pct < 10.0:
            raise Refused(f"battery at {self.battery_pct:.0f} %")
        self.armed = True

    def disarm(self) -> None:
        if self.state is not State.LANDED:
            raise Refused("cannot disarm in the air")
        self.armed = False

    @_order
    def takeoff(self, alt: float | None = None) -> None:
        if alt is not None and alt < 0:
            raise Refused(f"take-off altitude {alt:g} m is below 0 (0: the vehicle's default)")
        alt = self._alt(alt if alt is not None and alt > 0 else self.limits.takeoff_alt)
        if not self.armed:
            raise Refused("not armed")
        if self.state is not State.LANDED:
            raise Refused(f"cannot take off while {self.state.value}")
        self.state = State.TAKING_OFF
        self._fly_to(self.pos[0], self.pos[1], -alt, None)

    @_order
    def takeoff_in_air(self, alt: float) -> bool:
        """PX4's take-off mode selected in the air: climb to `alt` over the current position, or
        hold there when already higher (False: "Already higher than takeoff altitude")."""
        if self.state is State.LANDED:
            raise Refused("on the ground")
        self.route, self.leg = [], -1
        if -self.pos[2] >= alt - 0.1:
            self.state = State.HOVERING
            self._fly_to(self.pos[0], self.pos[1], self.pos[2], None)
            return False
        self.state = State.TAKING_OFF
        self._fly_to(self.pos[0], self.pos[1], -alt, None)
        return True

    @_order
    def land(self) -> None:
        if self.state is State.LANDED:
            raise Refused("already landed")
        self.state = State.LANDING
        self.route, self.leg = [], -1
        self._unsteer()
        self.target = (self.pos[0], self.pos[1], 0.0)
        self.target_yaw = None

    @_order
    def hover(self) -> None:
        if self.state is State.LANDED:
            raise Refused("on the ground")
        self.state = State.HOVERING
        self.route, self.leg = [], -1
        self._unsteer()
        self.target = (self.pos[0], self.pos[1], self.pos[2])
        self.target_yaw = None

    @_order
    def goto(self, n: float, e: float, alt: float, yaw: float | None = None) -> None:
        self._finite(n, e, alt, yaw)
        alt = self._alt(alt)
        self._dist(n, e)
        if alt < MIN_ALT:
            raise Refused(f"altitude {alt:g} m is below {MIN_ALT:g} m: land instead")
        if self.state is State.LANDED:
            raise Refused("on the ground: take off first")
        if self.state is State.LANDING:
            raise Refused(f"busy {self.state.value}", temporary=True)
        self.state = State.MOVING
        self.route, self.leg = [], -1
        self._fly_to(n, e, -alt, yaw)

    @_order
    def fly(self, waypoints: list[Waypoint]) -> None:
        if not waypoints:
            raise Refused("the trajectory has no waypoints")
        for w in waypoints:
            self._finite(w.n, w.e, w.alt, w.yaw, w.speed, w.hold)
            self._alt(w.alt)
            self._dist(w.n, w.e)
            if w.speed is not None and w.speed <= 0:
                raise Refused("a waypoint's speed must be positive")
            if w.hold < 0:
                raise Refused("a waypoint's hold time must not be negative")
        if self.state is State.LANDED:
            raise Refused("on the ground: take off first")
        if self.state is State.LANDING:
            raise Refused(f"busy {self.state.value}", temporary=True)
        self.state = State.TRAJECTORY
        self.route, self.leg = list(waypoints), 0
        self._start_leg()

    @_order
    def return_home(self, alt: float | None = None) -> None:
        if self.state is State.LANDED:
            raise Refused("on the ground")
        alt = self._alt(alt if alt is not None and alt > 0 else self.limits.return_alt)
        self.state = State.RETURNING
        self.route, self.leg = [], -1
        # climb (never descend) to the return altitude first, then home (or the closest rally
        # point), then land
        dest = min([(0.0, 0.0), *self.rally], key=lambda p: math.hypot(p[0] - self.pos[0], p[1] - self.pos[1]))
        self.route = [Waypoint(self.pos[0], self.pos[1], max(alt, -self.pos[2])),
                      Waypoint(dest[0], dest[1], max(alt, -self.pos[2]))]
        self.leg = 0
        self._start_leg()

    def _alt(self, alt: float) -> float:
        if not math.isfinite(alt):
            raise Refused("altitude is not a number")
        if alt < 0 or alt > self.limits.max_alt:
            raise Refused(f"altitude {alt:g} m is outside 0..{self.limits.max_alt:g} m")
        return alt

    def _dist(self, n: float, e: float) -> None:
        far = math.hypot(n, e)
        if far > self.limits.max_dist:
            say = f"{far / 1000:.0f} km" if far >= 10_000 else f"{far:.0f} m"
            raise Refused(f"{say} from home is beyond the {self.limits.max_dist:g} m limit (TT_MAX_DIST)")

    @staticmethod
    def _finite(*values: float | None) -> None:
        if any(v is not None and not math.isfinite(v) for v in values):
            raise Refused("a value is not a finite number")

    @_order
    def steer(self, state: State, vel: tuple[float, float, float] | None = None,
              pos: tuple[float, float, float] | None = None, yaw: float | None = None,
              yaw_rate: float | None = None) -> None:
        """Manual or offboard control (`state` MANUAL or OFFBOARD): fly the velocity `vel` (n, e,
        d m/s, held within the limits) or to the position `pos` (n, e, d m from home), facing
        `yaw` (rad) or turning at `yaw_rate` (rad/s). From the ground only when armed, and the
        vehicle leaves it only when told to climb; steered down onto the ground it lands and
        disarms after 2 s there, as PX4's land detector does."""
        if state not in (State.MANUAL, State.OFFBOARD):
            raise ValueError(state)
        self._finite(yaw, yaw_rate, *(vel or ()), *(pos or ()))
        if (vel is None) == (pos is None):
            raise Refused("a velocity or a position, one of them")
        if pos is not None:
            self._alt(max(0.0, -pos[2]))
        if self.state is State.LANDED:
            if not self.armed:
                raise Refused("not armed")
            climbing = (vel[2] < -0.1) if vel is not None else (pos is not None and -pos[2] >= MIN_ALT)
            if not climbing:
                return  # armed on the ground, and staying there
            self.ground_since = None
        elif self.state is not state:
            self.ground_since = None
        self.state = state
        self.route, self.leg, self.speed_cap, self.hold_until = [], -1, None, None
        self.yaw_rate_cmd = yaw_rate
        if vel is not None:
            self.vel_cmd = vel
            self.target = None
            self.target_yaw = yaw
        else:
            assert pos is not None
            self.vel_cmd = None
            self.target = (pos[0], pos[1], min(0.0, pos[2]))
            self.target_yaw = yaw

    def _unsteer(self) -> None:
        self.vel_cmd, self.yaw_rate_cmd, self.ground_since = None, None, None

    def _fly_to(self, n: float, e: float, d: float, yaw: float | None) -> None:
        self._unsteer()
        self.target = (n, e, d)
        self.target_yaw = yaw
        self.hold_until = None

    def _start_leg(self) -> None:
        w = self.route[self.leg]
        self.speed_cap = w.speed
        self._fly_to(w.n, w.e, -w.alt, w.yaw)

    # -- physics ----------------------------------------------------------------------------
    def step(self, dt: float) -> None:
        """Advance by dt seconds (any size: long steps are cut into short ones)."""
        while dt > 1e-9:
            h = min(dt, 0.05)
            self._step(h)
            dt -= h

    def _step(self, dt: float) -> None:
        self.time += dt
        lim = self.limits
        want = [0.0, 0.0, 0.0]
        if self.vel_cmd is not None and self.state.airborne:
            vn, ve, vd = self.vel_cmd
            h = math.hypot(vn, ve)
            k = min(1.0, lim.h_speed / h) if h > 1e-9 else 1.0
            want = [vn * k, ve * k, max(-lim.v_speed, min(lim.v_speed, vd))]
        elif self.target is not None and self.state.airborne:
            dn, de, dd = (self.target[i] - self.pos[i] for i in range(3))
            hdist = math.hypot(dn, de)
            hs = min(self.speed_cap or lim.h_speed, lim.h_speed)
            # slow down to arrive: v = sqrt(2 a d) caps the speed near the target
            hv = min(hs, math.sqrt(2 * lim.accel * hdist) * 0.9) if hdist > 1e-6 else 0.0
            vv = min(lim.v_speed, math.sqrt(2 * lim.accel * abs(dd)) * 0.9) if abs(dd) > 1e-6 else 0.0
            if self.state is State.LANDING and -self.pos[2] < 1.0:
                vv = min(vv, 0.4)  # the last metre slowly
            if hdist > 1e-6:
                want[0], want[1] = hv * dn / hdist, hv * de / hdist
            want[2] = math.copysign(vv, dd) if abs(dd) > 1e-6 else 0.0
        # velocity follows within the acceleration limit
        acc = [0.0, 0.0, 0.0]
        for i in range(3):
            dv = want[i] - self.vel[i]
            step = max(-lim.accel * dt, min(lim.accel * dt, dv))
            acc[i] = step / dt
            self.vel[i] += step
            self.pos[i] += self.vel[i] * dt
        if self.pos[2] > 0.0:  # the ground
            self.pos[2] = 0.0
            self.vel[2] = min(self.vel[2], 0.0)
        # yaw: toward the target yaw, or the direction of travel when moving
        yaw_goal = self.target_yaw
        if yaw_goal is None and math.hypot(self.vel[0], self.vel[1]) > 0.3 and self.state in (
                State.MOVING, State.TRAJECTORY, State.RETURNING):
            yaw_goal = math.atan2(self.vel[1], self.vel[0])
        if self.yaw_rate_cmd is not None and self.state.airborne and self.pos[2] < -0.05:
            self.yaw_rate = max(-lim.yaw_rate, min(lim.yaw_rate, self.yaw_rate_cmd))
        elif yaw_goal is not None and self.state.airborne:
            err = (yaw_goal - self.yaw + math.pi) % (2 * math.pi) - math.pi
            self.yaw_rate = max(-lim.yaw_rate, min(lim.yaw_rate, err / max(dt, 0.2)))
        else:
            self.yaw_rate = 0.0
        self.yaw = (self.yaw + self.yaw_rate * dt + math.pi) % (2 * math.pi) - math.pi
        # attitude: tilt along the horizontal acceleration, in the body frame
        an, ae = acc[0], acc[1]
        fwd = an * math.cos(self.yaw) + ae * math.sin(self.yaw)
        right = -an * math.sin(self.yaw) + ae * math.cos(self.yaw)
        self.pitch = -math.atan2(fwd, GRAVITY) if self.state.airborne else 0.0
        self.roll = math.atan2(right, GRAVITY) if self.state.airborne else 0.0
        self._battery(dt)
        self._progress()

    def _battery(self, dt: float) -> None:
        if not self.armed:
            return
        speed = math.sqrt(sum(v * v for v in self.vel))
        watts = (180.0 + 15.0 * speed) if self.state.airborne else 5.0
        self.energy_wh = max(0.0, self.energy_wh - watts * dt / 3600.0)

    def _arrived(self) -> bool:
        if self.target is None:
            return True
        err = math.sqrt(sum((self.target[i] - self.pos[i]) ** 2 for i in range(3)))
        return err < 0.15 and math.sqrt(sum(v * v for v in self.vel)) < 0.15

    def _progress(self) -> None:
        s = self.state
        if (s is State.TAKING_OFF and self._arrived()) or (s is State.MOVING and self._arrived()):
            self.state = State.HOVERING
        elif s in (State.MANUAL, State.OFFBOARD):
            down = self.vel_cmd[2] >= 0 if self.vel_cmd is not None else (self.target or (0, 0, 0))[2] >= -0.01
            if self.pos[2] >= -0.01 and down:
                self.ground_since = self.time if self.ground_since is None else self.ground_since
                if self.time - self.ground_since >= 2.0:  # PX4's COM_DISARM_LAND
                    self.state, self.armed = State.LANDED, False
                    self.pos[2], self.vel = 0.0, [0.0, 0.0, 0.0]
                    self.target = None
                    self._unsteer()
            else:
                self.ground_since = None
        elif s is State.LANDING and self.pos[2] >= -0.01 and abs(self.vel[2]) < 0.05:
            self.state = State.LANDED
            self.pos[2], self.vel = 0.0, [0.0, 0.0, 0.0]
            self.target = None
            self.armed = False  # autopilots disarm on landing
        elif s in (State.TRAJECTORY, State.RETURNING) and self._arrived():
            w = self.route[self.leg]
            if w.hold > 0 and self.hold_until is None:
                self.hold_until = self.time + w.hold
            if self.hold_until is not None and self.time < self.hold_until:
                return
            self.hold_until = None
            self.leg += 1
            if self.leg < len(self.route):
                self._start_leg()
            elif s is State.RETURNING:
                self.land()
                self.orders -= 1  # the return's own landing, not a new order
            else:
                self.route, self.leg, self.speed_cap = [], -1, None
                self.state = State.HOVERING

    # -- what telemetry reads ---------------------------------------------------------------
    @property
    def battery_pct(self) -> float:
        return 100.0 * self.energy_wh / self.battery_wh

    def snapshot(self) -> Snapshot:
        n, e, d = self.pos
        lat = self.home.lat + math.degrees(n / EARTH_RADIUS)
        lon = self.home.lon + math.degrees(e / (EARTH_RADIUS * math.cos(math.radians(self.home.lat))))
        pct = self.battery_pct
        volts = 4 * (3.3 + 0.9 * pct / 100.0)  # a 4-cell pack, 13.2 V empty to 16.8 V full
        speed = math.sqrt(sum(v * v for v in self.vel))
        amps = ((180.0 + 15.0 * speed) if self.state.airborne else (0.3 if self.armed else 0.1)) / volts
        return Snapshot(self.time, self.state, self.armed, n, e, d, self.vel[0], self.vel[1], self.vel[2],
                        self.roll, self.pitch, self.yaw, self.yaw_rate, lat, lon, self.home.alt - d, self.home,
                        pct, volts, amps, self.leg if self.state is State.TRAJECTORY else -1)


__all__ = ["Home", "Limits", "Refused", "SimVehicle", "Snapshot", "State", "Vehicle", "Waypoint"]
