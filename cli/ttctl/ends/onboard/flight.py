"""Flight modes as a PX4 vehicle has them, sans-IO: which mode the vehicle is in (what HEARTBEAT
reports), DO_SET_MODE (every mode it reports can be entered, the rest refused with the reason),
and the two ways a ground station flies it directly:

- MANUAL, ALTCTL and POSCTL follow the sticks of MANUAL_CONTROL (x forward, y right, r yaw, -1000..1000;
  z throttle 0..1000, 500 holds the altitude). POSCTL: the sticks command velocity and centred sticks
  hold the position; ALTCTL: they tilt the vehicle, which keeps drifting when they are centred, and
  the throttle commands the climb rate; MANUAL: the throttle accelerates up or down too. Entered only
  while MANUAL_CONTROL arrives; silent COM_RC_LOSS_T seconds, NAV_RCL_ACT (1 hold, 2 return, 3 land).
- OFFBOARD follows SET_POSITION_TARGET_LOCAL_NED and SET_POSITION_TARGET_GLOBAL_INT (position, or
  velocity, with yaw or yaw rate), reported back as POSITION_TARGET_LOCAL_NED / _GLOBAL_INT. Entered
  only while set-points arrive; silent COM_OF_LOSS_T seconds, COM_OBL_RC_ACT (0 position, 1
  altitude, 2 manual when sticks are there, else hold; 3 return, 4 land, 5 hold), as PX4's
  commander does.

Times given to this module are the ground stations' (the wall clock), whatever the vehicle's clock
does: a set-point stream at 20 Hz is a stream at any --speed.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from . import modes
from .modes import ALTCTL, AUTO, LAND, LOITER, MANUAL, MISSION, OFFBOARD, POSCTL, RTL, STABILIZED, TAKEOFF
from .vehicle import EARTH_RADIUS, MIN_ALT, Refused, Snapshot, State

if TYPE_CHECKING:
    from .autopilot import Autopilot

INFO, WARNING, CRITICAL = 6, 4, 2
FEEDBACK = 0.25  # s between POSITION_TARGET_* reports in offboard (4 Hz)
COMPLAIN = 2.0  # s between two STATUSTEXTs about refused set-points
INT32_MAX = 2**31 - 1

# SET_POSITION_TARGET_* type_mask bits (POSITION_TARGET_TYPEMASK)
_POS, _VEL, _ACC, _YAW, _YAW_RATE = 0b111, 0b111000, 0b111000000, 1024, 2048
# MAV_FRAME values (common.xml)
_LOCAL_NED, _LOCAL_OFFSET_NED, _BODY_NED, _BODY_OFFSET_NED, _BODY_FRD = 1, 7, 8, 9, 12
_GLOBAL, _GLOBAL_REL, _GLOBAL_INT, _GLOBAL_REL_INT = 0, 3, 5, 6
_TERRAIN, _TERRAIN_INT = 10, 11  # above the ground: the simulated world is flat at home's altitude

_BY_STATE = {
    State.TAKING_OFF: (AUTO, TAKEOFF), State.HOVERING: (AUTO, LOITER), State.TRAJECTORY: (AUTO, MISSION),
    State.LANDING: (AUTO, LAND), State.RETURNING: (AUTO, RTL), State.OFFBOARD: (OFFBOARD, 0),
}
_MANUAL_MODES = (MANUAL, ALTCTL, POSCTL)


@dataclass
class Setpoint:
    pos: tuple[float, float, float] | None  # n, e, d m from home
    vel: tuple[float, float, float] | None  # n, e, d m/s
    yaw: float | None  # rad
    yaw_rate: float | None  # rad/s
    global_frame: int | None  # the MAV_FRAME of a global set-point, None for a local one
    mask: int


class FlightModes:
    def __init__(self, ap: Autopilot) -> None:
        self.ap = ap
        self.ground: tuple[int, int] = (AUTO, LOITER)  # the mode selected on the ground (Hold)
        self.manual_main = POSCTL  # which stick mode MANUAL state flies
        self.moving: tuple[int, int] = (OFFBOARD, 0)  # MOVING: the tablet's set-points; DO_REPOSITION: Hold
        self.takeoff_alt: float | None = None  # m above home, for a TAKEOFF selected on the ground
        self.sticks: tuple[float, float, float, float] | None = None  # x, y, z, r
        self.sticks_at: float | None = None
        self.setpoint: Setpoint | None = None
        self.setpoint_at: float | None = None
        self.now = 0.0
        self._complained = -math.inf
        self._feedback_due = 0.0
        self._last_state = ap.vehicle.state
        self._last_vtime: float | None = None

    @property
    def say(self) -> Callable[[int, str], None]:
        return self.ap.say

    def _param(self, name: str) -> float:
        return self.ap.params[name]

    # -- what HEARTBEAT says ----------------------------------------------------------------------
    def current(self, state: State) -> tuple[int, int]:
        if state is State.LANDED:
            return self.ground
        runner = self.ap.runner
        if runner is not None and runner.flying():  # PX4's navigator flies every item in MISSION
            return AUTO, MISSION
        if state is State.MANUAL:
            return self.manual_main, 0
        if state is State.MOVING:
            return self.moving
        return _BY_STATE[state]

    def custom_mode(self, s: Snapshot) -> int:
        main, sub = self.current(s.state)
        return (main << 16) | (sub << 24)

    # -- inputs -------------------------------------------------------------------------------------
    def sticks_alive(self, now: float) -> bool:
        return self.sticks_at is not None and now - self.sticks_at <= self._param("COM_RC_LOSS_T")

    def setpoints_alive(self, now: float) -> bool:
        return self.setpoint_at is not None and now - self.setpoint_at <= self._param("COM_OF_LOSS_T")

    def manual_control(self, now: float, msg: Any) -> None:
        def clamp(v: float, lo: float, hi: float) -> float:
            return max(lo, min(hi, float(v)))

        self.now = now
        self.sticks = (clamp(msg.x, -1000, 1000), clamp(msg.y, -1000, 1000), clamp(msg.z, 0, 1000),
                       clamp(msg.r, -1000, 1000))
        self.sticks_at = now

    def set_position_target(self, now: float, msg: Any) -> None:
        self.now = now
        try:
            sp = self._parse(msg)
        except Refused as e:
            self.complain(now, str(e))
            return
        self.setpoint, self.setpoint_at = sp, now

    def complain(self, now: float, reason: str) -> None:
        """A set-point that is not flown: said, at most every COMPLAIN seconds (a stream of them
        is no flood of STATUSTEXT)."""
        if now - self._complained >= COMPLAIN:
            self._complained = now
            self.say(WARNING, f"set-point ignored: {reason}")

    def _parse(self, msg: Any) -> Setpoint:
        b = self.ap.b
        mask = int(msg.type_mask)
        use_pos, use_vel = not mask & _POS, not mask & _VEL
        if mask & _POS not in (0, _POS) or mask & _VEL not in (0, _VEL):
            raise Refused("partial axes are not flown")
        if not use_pos and not use_vel:
            raise Refused("no position or velocity")
        yaw = None if mask & _YAW else float(msg.yaw)
        yaw_rate = None if mask & _YAW_RATE else float(msg.yaw_rate)
        vel = (float(msg.vx), float(msg.vy), float(msg.vz)) if use_vel else None
        s = self.ap.vehicle.snapshot()
        frame = int(msg.coordinate_frame)
        pos: tuple[float, float, float] | None = None
        values = [yaw, yaw_rate, *(vel or ())]
        if isinstance(msg, b.SetPositionTargetGlobalInt):
            if frame not in (_GLOBAL, _GLOBAL_REL, _GLOBAL_INT, _GLOBAL_REL_INT, _TERRAIN, _TERRAIN_INT):
                raise Refused(f"frame {frame} is not flown")
            if use_pos:
                if not (abs(msg.lat_int) <= 900_000_000 and abs(msg.lon_int) <= 1_800_000_000):
                    raise Refused("lat/lon out of range")
                values.append(float(msg.alt))
                lat, lon = msg.lat_int / 1e7, msg.lon_int / 1e7
                n = math.radians(lat - s.home.lat) * EARTH_RADIUS
                e = math.radians(lon - s.home.lon) * EARTH_RADIUS * math.cos(math.radians(s.home.lat))
                alt = float(msg.alt) - (s.home.alt if frame in (_GLOBAL, _GLOBAL_INT) else 0.0)
                pos = (n, e, -alt)
            global_frame: int | None = frame
        else:
            global_frame = None
            if frame not in (_LOCAL_NED, _LOCAL_OFFSET_NED, _BODY_NED, _BODY_OFFSET_NED, _BODY_FRD):
                raise Refused(f"frame {frame} is not flown")
            if use_pos:
                values += [float(msg.x), float(msg.y), float(msg.z)]
                x, y, z = float(msg.x), float(msg.y), float(msg.z)
                if frame in (_BODY_NED, _BODY_OFFSET_NED, _BODY_FRD):
                    x, y = self._rotate(x, y, s.yaw)
                pos = (x, y, z) if frame == _LOCAL_NED else (s.n + x, s.e + y, s.d + z)
            if vel is not None and frame in (_BODY_NED, _BODY_OFFSET_NED, _BODY_FRD):
                vel = (*self._rotate(vel[0], vel[1], s.yaw), vel[2])
        if any(v is not None and not math.isfinite(v) for v in values):
            raise Refused("a value is not a finite number")
        if pos is not None:
            limits = getattr(self.ap.vehicle, "limits", None)
            if limits is not None and -pos[2] > limits.max_alt:
                raise Refused(f"altitude {-pos[2]:.0f} m above {limits.max_alt:g} m")
            if abs(pos[0]) > 1e6 or abs(pos[1]) > 1e6:
                raise Refused("position more than 1000 km away")
        return Setpoint(pos, None if pos is not None else vel, yaw, yaw_rate, global_frame, mask)

    @staticmethod
    def _rotate(fwd: float, right: float, yaw: float) -> tuple[float, float]:
        return fwd * math.cos(yaw) - right * math.sin(yaw), fwd * math.sin(yaw) + right * math.cos(yaw)

    # -- DO_SET_MODE --------------------------------------------------------------------------------
    def set_mode(self, now: float, base: int, main: int, sub: int) -> None:
        """Enter PX4 mode (main, sub) or raise Refused saying why not (temporary: it may work later)."""
        self.now = now
        v = self.ap.vehicle
        F = self.ap.b.MavModeFlag
        if not base & int(F.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED):  # PX4 reads the base mode's flags
            if base & int(F.MAV_MODE_FLAG_AUTO_ENABLED):
                main, sub = AUTO, MISSION
            elif base & int(F.MAV_MODE_FLAG_MANUAL_INPUT_ENABLED):
                main = POSCTL if base & int(F.MAV_MODE_FLAG_GUIDED_ENABLED) else (
                    STABILIZED if base & int(F.MAV_MODE_FLAG_STABILIZE_ENABLED) else MANUAL)
            else:
                raise Refused(f"base mode {base} names no mode")
        if main != AUTO:
            sub = 0
        elif sub == 0:
            sub = MISSION  # PX4: AUTO without a sub mode is MISSION
        name = modes.NAMES.get((main, sub))
        if name is None:
            raise Refused(f"{modes.name((main << 16) | (sub << 24))}: not a mode flown here")
        landed = v.state is State.LANDED
        if main in _MANUAL_MODES:
            if not self.sticks_alive(now):
                raise Refused(f"{name}: no MANUAL_CONTROL input", temporary=True)
            self.manual_main = main
            if landed:
                self.ground = (main, 0)
            else:
                self._steer_manual(now, State.MANUAL)
        elif main == OFFBOARD:
            if not self.setpoints_alive(now) or self.setpoint is None:
                raise Refused("OFFBOARD: no set-point stream", temporary=True)
            if landed:
                self.ground = (OFFBOARD, 0)
                if v.armed:
                    self._steer_offboard()
            else:
                self._steer_offboard()
        elif sub == LOITER:
            if landed:
                self.ground = (AUTO, LOITER)
            else:
                v.hover()
        elif sub == TAKEOFF:
            if not landed:  # PX4: take-off mode in the air climbs to MIS_TAKEOFF_ALT or holds above it
                if not v.takeoff_in_air(self._param("MIS_TAKEOFF_ALT")):
                    self.say(INFO, "Already higher than takeoff altitude")
            elif v.armed:
                v.takeoff()
            else:
                self.ground, self.takeoff_alt = (AUTO, TAKEOFF), None  # it takes off when armed, as PX4 does
        elif sub == MISSION:
            if self.ap.missions is None or not self.ap.missions.mission():
                raise Refused("MISSION: no mission uploaded", temporary=True)
            if landed and not v.armed:
                self.ground = (AUTO, MISSION)  # flown when armed
            else:
                self.ap.start_mission()
        elif sub == RTL:
            if landed:
                raise Refused("RTL: on the ground", temporary=True)
            v.return_home()
        elif sub == LAND:
            if landed:
                raise Refused("LAND: already landed", temporary=True)
            v.land()

    def takeoff(self, amsl: float | None) -> None:
        """MAV_CMD_NAV_TAKEOFF as PX4 takes it: param7 an altitude above mean sea level, raised to
        home + MIS_TAKEOFF_ALT if lower ("Using minimum takeoff altitude"), that altitude when
        none; armed it climbs, disarmed it selects TAKEOFF and climbs when armed (QGroundControl
        sends the take-off first, then arms)."""
        v = self.ap.vehicle
        s = v.snapshot()
        minimum = self._param("MIS_TAKEOFF_ALT")
        alt = minimum if amsl is None else amsl - s.home.alt
        if alt < minimum:
            self.say(WARNING, f"Using minimum takeoff altitude: {minimum:.2f} m")
            alt = minimum
        limits = getattr(v, "limits", None)
        if limits is not None and alt > limits.max_alt:
            raise Refused(f"takeoff altitude {alt:.0f} m above {limits.max_alt:g} m")
        if v.state is not State.LANDED:  # PX4 takes it in the air too: take-off mode, climbing or holding
            if not v.takeoff_in_air(alt):
                self.say(INFO, "Already higher than takeoff altitude")
        elif v.armed:
            v.takeoff(alt)
        else:
            self.ground, self.takeoff_alt = (AUTO, TAKEOFF), alt

    def armed(self) -> None:
        """After an accepted arming: TAKEOFF and MISSION selected on the ground start now."""
        try:
            if self.ground == (AUTO, TAKEOFF):
                alt, self.takeoff_alt = self.takeoff_alt, None
                self.ap.vehicle.takeoff(alt)
            elif self.ground == (AUTO, MISSION):
                self.ap.start_mission()
        except Refused as e:
            self.say(WARNING, f"{modes.NAMES[self.ground]} not started: {e}")
            self.ground = (AUTO, LOITER)

    # -- flying -------------------------------------------------------------------------------------
    def _steer_manual(self, now: float, state: State) -> None:
        assert self.sticks is not None
        v = self.ap.vehicle
        s = v.snapshot()
        x, y, z, r = (c / 1000.0 for c in self.sticks)
        climb = (z - 0.5) / 0.5
        if abs(climb) < 0.05:
            climb = 0.0
        lim = v.limits  # type: ignore[attr-defined]
        dt = 0.0 if self._last_vtime is None else max(0.0, min(0.5, s.time - self._last_vtime))
        fwd_n, fwd_e = math.cos(s.yaw), math.sin(s.yaw)
        if self.manual_main == POSCTL:
            vn = (x * fwd_n - y * fwd_e) * lim.h_speed
            ve = (x * fwd_e + y * fwd_n) * lim.h_speed
        else:  # the sticks tilt: they accelerate, and the air slows the vehicle a little
            an = (x * fwd_n - y * fwd_e) * lim.accel
            ae = (x * fwd_e + y * fwd_n) * lim.accel
            drag = max(0.0, 1.0 - 0.2 * dt)
            vn, ve = (s.vn + an * dt) * drag, (s.ve + ae * dt) * drag
        # MANUAL has no altitude hold: the throttle accelerates; the others command the climb rate
        vd = s.vd - climb * lim.accel * dt if self.manual_main == MANUAL else -climb * lim.v_speed
        if s.state is State.LANDED:  # on the ground the throttle lifts it off, or it stays
            vd = -climb * lim.v_speed
            if vd >= -0.1:
                return
        v.steer(state, vel=(vn, ve, vd), yaw_rate=r * lim.yaw_rate)

    def _steer_offboard(self) -> None:
        sp = self.setpoint
        assert sp is not None
        v = self.ap.vehicle
        try:
            if sp.pos is not None:
                v.steer(State.OFFBOARD, pos=sp.pos, yaw=sp.yaw, yaw_rate=sp.yaw_rate)
            else:
                v.steer(State.OFFBOARD, vel=sp.vel, yaw=sp.yaw, yaw_rate=sp.yaw_rate)
        except Refused as e:
            if self.now - self._complained >= COMPLAIN:
                self._complained = self.now
                self.say(WARNING, f"set-point not flown: {e}")

    def tick(self, now: float) -> list[Any]:
        """Apply the sticks and set-points, watch their streams; the POSITION_TARGET_* to send."""
        self.now = now
        v = self.ap.vehicle
        state = v.state
        if state is not self._last_state:
            if state is State.LANDED:
                was = self._last_state
                if was is State.MANUAL:
                    self.ground = (self.manual_main, 0)
                elif was is State.OFFBOARD and self.setpoints_alive(now):
                    self.ground = (OFFBOARD, 0)
                else:
                    self.ground = (AUTO, LOITER)
            if self._last_state is State.MOVING:
                self.moving = (OFFBOARD, 0)
            self._last_state = state
        out: list[Any] = []
        landed_in = self.ground[0] if state is State.LANDED and v.armed else None
        if state is State.MANUAL or landed_in in _MANUAL_MODES:
            if self.sticks_alive(now):
                self._steer_manual(now, State.MANUAL)
            elif state is State.MANUAL:
                self._lost_sticks()
        elif state is State.OFFBOARD or (state is State.LANDED and self.ground == (OFFBOARD, 0)):
            if self.setpoints_alive(now):
                if state is State.OFFBOARD or v.armed:
                    self._steer_offboard()
                if state is State.OFFBOARD and now >= self._feedback_due:
                    self._feedback_due = now + FEEDBACK
                    out.extend(self.feedback())
            elif state is State.OFFBOARD:
                self._lost_setpoints(now)
            else:
                self.ground = (AUTO, LOITER)
        self._last_vtime = v.snapshot().time
        return out

    def _lost_sticks(self) -> None:
        action = {1: "hold", 2: "return", 3: "land"}.get(int(self._param("NAV_RCL_ACT")), "hold")
        self.say(CRITICAL, f"manual control lost: {action}")
        self._act(action)

    def _lost_setpoints(self, now: float) -> None:
        act = int(self._param("COM_OBL_RC_ACT"))
        if act in (0, 1, 2) and self.sticks_alive(now):
            self.manual_main = {0: POSCTL, 1: ALTCTL, 2: MANUAL}[act]
            self.say(CRITICAL, f"offboard set-points lost: {modes.NAMES[(self.manual_main, 0)]}")
            self._steer_manual(now, State.MANUAL)
            return
        action = {3: "return", 4: "land"}.get(act, "hold")
        self.say(CRITICAL, f"offboard set-points lost: {action}")
        self._act(action)

    def _act(self, action: str) -> None:
        v = self.ap.vehicle
        try:
            if action == "return":
                v.return_home()
            elif action == "land":
                v.land()
            elif v.snapshot().alt_rel < MIN_ALT:
                v.land()  # nothing to hold at on the ground
            else:
                v.hover()
        except Refused:
            pass

    def feedback(self) -> list[Any]:
        """POSITION_TARGET_LOCAL_NED (and _GLOBAL_INT for a global set-point): what is flown."""
        b, sp = self.ap.b, self.setpoint
        if sp is None:
            return []
        s = self.ap.vehicle.snapshot()
        boot_ms = int(self.now * 1000) & 0xFFFFFFFF
        pos = sp.pos or (0.0, 0.0, 0.0)
        vel = sp.vel or (0.0, 0.0, 0.0)
        mask = (_POS if sp.pos is None else 0) | (_VEL if sp.vel is None else 0) | _ACC \
            | (_YAW if sp.yaw is None else 0) | (_YAW_RATE if sp.yaw_rate is None else 0)
        out = [b.PositionTargetLocalNed(time_boot_ms=boot_ms, coordinate_frame=_LOCAL_NED, type_mask=mask,
                                        x=pos[0], y=pos[1], z=pos[2], vx=vel[0], vy=vel[1], vz=vel[2],
                                        afx=0.0, afy=0.0, afz=0.0, yaw=sp.yaw or 0.0, yaw_rate=sp.yaw_rate or 0.0)]
        if sp.global_frame is not None:
            lat = s.home.lat + math.degrees(pos[0] / EARTH_RADIUS)
            lon = s.home.lon + math.degrees(pos[1] / (EARTH_RADIUS * math.cos(math.radians(s.home.lat))))
            relative = sp.global_frame not in (_GLOBAL, _GLOBAL_INT)
            alt = -pos[2] + (0.0 if relative else s.home.alt)
            out.append(b.PositionTargetGlobalInt(
                time_boot_ms=boot_ms, coordinate_frame=_GLOBAL_REL_INT if relative else _GLOBAL_INT, type_mask=mask,
                lat_int=round(lat * 1e7), lon_int=round(lon * 1e7), alt=alt, vx=vel[0], vy=vel[1], vz=vel[2],
                afx=0.0, afy=0.0, afz=0.0, yaw=sp.yaw or 0.0, yaw_rate=sp.yaw_rate or 0.0))
        return out

    def wakeup(self) -> float | None:
        """When tick must run next: streams are watched and fed at 20 Hz while they matter."""
        v = self.ap.vehicle
        if v.state in (State.MANUAL, State.OFFBOARD) or (v.state is State.LANDED and self.ground[0] != AUTO):
            return self.now + 0.05
        return None
