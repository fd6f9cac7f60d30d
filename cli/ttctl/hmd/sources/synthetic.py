"""A synthetic VR user: a standing person turning their head and using two controllers.

It exists so that everything downstream of a headset (recordings, the link, the orbit camera)
can be run and tested without SteamVR, and so the numbers look like a person rather than a
sine wave: recorders, filters and the orbit camera's damping are tuned on what people do.

The motion model:
- Head yaw turns of 20-120 degrees with the minimum-jerk profile of voluntary movements
  (Flash & Hogan 1985, J. Neurosci. 5(7)): x(t) = A (10 s^3 - 15 s^4 + 6 s^5), s = t / D, whose
  peak speed is 1.875 A / D. Peak yaw speeds are drawn from 60-250 deg/s, the ordinary range of
  head turns (vigorous shaking reaches ~780 deg/s, Grossman et al. 1988, Exp. Brain Res. 70),
  with pauses between turns; pitch and a little roll move with each turn. The eyes sit 10 cm
  above and 8 cm in front of a neck pivot at 1.6 m (so ~1.7 m eye height) that sways slowly.
- Every 4-12 s the whole body turns (45-180 degrees, slower): room-scale users turn round, so
  the headset's yaw is unbounded and its quaternion crosses w = 0 (downstream code must cope).
- Hands move with the body; within it, reaches are minimum-jerk moves (peak speed 1.875 A / D,
  at most 1.5 m/s); trigger pulls, pad touches and presses, menu and grip presses come and go.
- Two base stations stand 2 m high in opposite corners of a 3 x 3 m play area, looking at it.

Everything is in OpenVR's standing space (+y up, -z forward, metres) and orientations are
built as OpenVR's 3x4 matrices and turned into quaternions by `frames.quat_from_matrix`, the
same path as a real headset's poses. Velocities are the analytic derivatives of the motion;
angular velocities are in the tracking (world) space. A seed fixes the whole run; motion is
computed from time since the start, so t0 only shifts it.
"""

from __future__ import annotations

import heapq
import math
import random
import time
from collections.abc import Callable, Iterator

from ...errors import Fail
from ..frames import continuous, quat_from_matrix
from ..model import BUTTONS, ControllerSample, Device, PoseSample, Quat, Sample, Vec3

HMD = Device(0, "hmd", serial="LHR-5F3A9C21")
BASE_STATIONS = (Device(1, "base_station", serial="LHB-2A41C7E0"), Device(2, "base_station", serial="LHB-7D93B15F"))
CONTROLLERS = (Device(3, "controller", "left", "LHR-0C8E12A4"), Device(4, "controller", "right", "LHR-6B27F0D9"))

NECK_HEIGHT = 1.6  # m: the pivot the head turns about
EYE_OFFSET = (0.0, 0.10, -0.08)  # m: the headset from the neck pivot, in head axes
MAX_HEAD_YAW = math.radians(120)  # head (and eyes) relative to the body; further is a body turn
MAX_HAND_SPEED = 1.5  # m/s peak of a reach
BASE_PERIOD = 1.0  # s between base-station poses (they do not move)

Vector = list[float]
Plan = Callable[[Vector], tuple[float, float, Vector]]  # current -> (pause, duration, target)


def min_jerk(s: float) -> tuple[float, float]:
    """The minimum-jerk profile at s in 0..1 and its derivative d/ds (Flash & Hogan 1985)."""
    s = min(max(s, 0.0), 1.0)
    return s * s * s * (10 - 15 * s + 6 * s * s), 30 * s * s * (1 - s) * (1 - s)


class _Track:
    """A vector that rests, then moves to a target along a minimum-jerk path, rests, moves...

    `plan` draws the next pause, move duration and target when the current move is over;
    queries must come in non-decreasing time (each track serves one device's stream). The lists
    returned are shared: read them, do not change them."""

    __slots__ = ("_a", "_b", "_d", "_plan", "_rest", "_still", "_t0", "_t1")

    def __init__(self, start: Vector, plan: Plan) -> None:
        self._plan = plan
        self._a = self._b = list(start)
        self._d = [0.0] * len(start)
        self._rest, self._still = list(start), [0.0] * len(start)
        self._t0 = self._t1 = 0.0

    def at(self, t: float) -> tuple[Vector, Vector]:
        """The value and its time derivative at t (seconds since the start)."""
        if t >= self._t1:
            while t >= self._t1:
                pause, duration, target = self._plan(self._b)
                self._a, self._b = self._b, target
                self._t0 = self._t1 + pause
                self._t1 = self._t0 + duration
            self._d = [b - a for a, b in zip(self._a, self._b, strict=True)]
            self._rest = list(self._a)
        t0 = self._t0
        if t <= t0:
            return self._rest, self._still
        d = self._t1 - t0
        s = (t - t0) / d  # in (0, 1]: t0 < t < t1 (min_jerk's clamp, inlined with the rest of it)
        if s > 1.0:
            s = 1.0
        ds = 30 * s * s * (1 - s) * (1 - s)
        s = s * s * s * (10 - 15 * s + 6 * s * s)
        return [a + delta * s for a, delta in zip(self._a, self._d, strict=True)], [delta * ds / d for delta in self._d]


def rotation(yaw: float, pitch: float, roll: float) -> list[list[float]]:
    """R = Ry(yaw) Rx(pitch) Rz(roll) in OpenVR axes: yaw about +y (positive turns left, since
    -z is forward), pitch about +x (positive looks up), roll about +z."""
    ca, sa, cb, sb = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
    cc, sc = math.cos(roll), math.sin(roll)
    return [
        [ca * cc + sa * sb * sc, -ca * sc + sa * sb * cc, sa * cb],
        [cb * sc, cb * cc, -sb],
        [-sa * cc + ca * sb * sc, sa * sc + ca * sb * cc, ca * cb],
    ]


def angular_velocity(yaw: float, pitch: float, rates: Vector) -> Vec3:
    """World-frame angular velocity of rotation(yaw, pitch, roll) for the angle rates:
    yaw' e_y + pitch' Ry e_x + roll' Ry Rx e_z."""
    dy, dp, dr = rates
    ca, sa, cb, sb = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
    return (dp * ca + dr * sa * cb, dy - dr * sb, -dp * sa + dr * ca * cb)


def _turning(yaw: float, pitch: float, roll: float, dy: float, dp: float, dr: float) -> tuple[list[list[float]], Vec3]:
    """rotation(yaw, pitch, roll) and angular_velocity(yaw, pitch, [dy, dp, dr]) in one go, each
    cosine and sine computed once (the same numbers, bit for bit)."""
    ca, sa, cb, sb = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
    cc, sc = math.cos(roll), math.sin(roll)
    return ([[ca * cc + sa * sb * sc, -ca * sc + sa * sb * cc, sa * cb],
             [cb * sc, cb * cc, -sb],
             [-sa * cc + ca * sb * sc, sa * sc + ca * sb * cc, ca * cb]],
            (dp * ca + dr * sa * cb, dy - dr * sb, -dp * sa + dr * ca * cb))


def _mat_vec(m: list[list[float]], v: Vec3) -> Vec3:
    return (m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2])


def _cross(a: Vec3, b: Vec3) -> Vec3:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _pose_matrix(r: list[list[float]], p: Vec3) -> list[list[float]]:
    """OpenVR's HmdMatrix34_t: rotation | translation."""
    return [[*r[0], p[0]], [*r[1], p[1]], [*r[2], p[2]]]


def look_at(eye: Vec3, target: Vec3) -> list[list[float]]:
    """The rotation whose -z axis points from eye at target, +x level (OpenVR body axes)."""
    f = [target[i] - eye[i] for i in range(3)]
    n = math.sqrt(sum(c * c for c in f))
    z = (-f[0] / n, -f[1] / n, -f[2] / n)
    x = _cross((0.0, 1.0, 0.0), z)
    n = math.sqrt(sum(c * c for c in x))
    x = (x[0] / n, x[1] / n, x[2] / n)
    y = _cross(z, x)
    return [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]


def _head_plan(rng: random.Random) -> Plan:
    """Yaw turns of 20-120 deg at 60-300 deg/s peak, with a new pitch and roll, 0.3-2 s apart."""

    def plan(cur: Vector) -> tuple[float, float, Vector]:
        yaw, pitch, _roll = cur
        amp = math.radians(rng.uniform(20, 120))
        sign = rng.choice((-1.0, 1.0))
        if abs(yaw + sign * amp) > MAX_HEAD_YAW:
            sign = -sign
        peak = math.radians(rng.uniform(60, 250))
        duration = max(0.3, 1.875 * amp / peak)
        new_pitch = min(max(pitch + math.radians(rng.uniform(-15, 15)), math.radians(-25)), math.radians(15))
        target = min(max(yaw + sign * amp, -MAX_HEAD_YAW), MAX_HEAD_YAW)
        return rng.uniform(0.3, 2.0), duration, [target, new_pitch, math.radians(rng.uniform(-6, 6))]

    return plan


def _body_plan(rng: random.Random) -> Plan:
    """Turning round: 45-180 deg at 60-150 deg/s peak, every 4-12 s, either way (unbounded)."""

    def plan(cur: Vector) -> tuple[float, float, Vector]:
        amp = math.radians(rng.uniform(45, 180))
        duration = max(1.0, 1.875 * amp / math.radians(rng.uniform(60, 150)))
        return rng.uniform(4.0, 12.0), duration, [cur[0] + rng.choice((-1.0, 1.0)) * amp]

    return plan


def _neck_plan(rng: random.Random) -> Plan:
    """Slow shifts of weight: the neck pivot wanders within +-25 cm, over 0.8-2 s."""

    def plan(cur: Vector) -> tuple[float, float, Vector]:
        x = min(max(cur[0] + rng.uniform(-0.1, 0.1), -0.25), 0.25)
        z = min(max(cur[2] + rng.uniform(-0.1, 0.1), -0.25), 0.25)
        return rng.uniform(0.5, 3.0), rng.uniform(0.8, 2.0), [x, NECK_HEIGHT + rng.uniform(-0.02, 0.02), z]

    return plan


def _hand_rest(side: float) -> Vector:
    """Holding a controller at the waist, pointing forward and a little down."""
    return [side * 0.2, 1.0, -0.3, 0.0, math.radians(-20), 0.0]


def _hand_plan(rng: random.Random, side: float) -> Plan:
    """Reaches within arm's length on the hand's side (or back to rest), peak speed <= 1.5 m/s."""

    def plan(cur: Vector) -> tuple[float, float, Vector]:
        if rng.random() < 0.35:
            target = _hand_rest(side)
        else:
            target = [side * rng.uniform(0.1, 0.5), rng.uniform(0.85, 1.5), rng.uniform(-0.6, -0.2),
                      math.radians(rng.uniform(-30, 30)), math.radians(rng.uniform(-40, 10)),
                      math.radians(rng.uniform(-30, 30))]
        amp = math.dist(cur[:3], target[:3])
        duration = max(rng.uniform(0.5, 1.2), 1.875 * amp / MAX_HAND_SPEED)
        return rng.uniform(0.3, 2.5), duration, target

    return plan


_IDLE = (0.0, 0.0, 0.0, (False, False, False, False, False))


class _Buttons:
    """A controller's inputs over time: gestures (trigger pull, pad touch with perhaps a press,
    menu or grip press) separated by idle gaps, drawn lazily; queried in non-decreasing time."""

    def __init__(self, rng: random.Random) -> None:
        self._rng = rng
        self._start = self._end = 0.0
        self._kind = "idle"
        self._p: dict[str, float] = {}

    def _next(self) -> None:
        r = self._rng
        self._start = self._end + r.uniform(0.4, 2.5)
        self._kind = r.choices(("trigger", "pad", "menu", "grip"), weights=(45, 35, 8, 12))[0]
        if self._kind == "trigger":
            up, hold, down = r.uniform(0.08, 0.2), r.uniform(0.05, 0.6), r.uniform(0.08, 0.2)
            self._p = {"up": up, "hold": hold, "down": down, "peak": 1.0 if r.random() < 0.75 else r.uniform(0.3, 0.8)}
            length = up + hold + down
        elif self._kind == "pad":
            length = r.uniform(0.3, 1.5)
            radius, angle = 0.9 * math.sqrt(r.random()), r.uniform(0, 2 * math.pi)
            press = r.random() < 0.5
            self._p = {"x": radius * math.cos(angle), "y": radius * math.sin(angle),
                       "p0": 0.1 if press else length, "p1": min(0.1 + r.uniform(0.1, 0.3), length - 0.05)}
        else:
            length = r.uniform(0.1, 0.3) if self._kind == "menu" else r.uniform(0.2, 1.0)
        self._end = self._start + length

    def at(self, t: float) -> tuple[float, float, float, tuple[bool, ...]]:
        """(trigger, pad_x, pad_y, buttons in BUTTONS order) at t; trigger in 1/255 steps as
        a real trigger's ADC reports it, and trigger_click exactly when it reads 1.0."""
        while t >= self._end:
            self._next()
        if t < self._start:
            return _IDLE  # between gestures (most of the time): what the code below gives, made once
        trigger = pad_x = pad_y = 0.0
        touched = pressed = menu = grip = False
        if t >= self._start:
            u = t - self._start
            p = self._p
            if self._kind == "trigger":
                if u < p["up"]:
                    trigger = p["peak"] * min_jerk(u / p["up"])[0]
                elif u < p["up"] + p["hold"]:
                    trigger = p["peak"]
                else:
                    trigger = p["peak"] * (1 - min_jerk((u - p["up"] - p["hold"]) / p["down"])[0])
            elif self._kind == "pad":
                touched, pad_x, pad_y = True, round(p["x"], 3), round(p["y"], 3)
                pressed = p["p0"] <= u < p["p1"]
            elif self._kind == "menu":
                menu = True
            else:
                grip = True
        trigger = round(trigger * 255) / 255
        return trigger, pad_x, pad_y, (trigger >= 1.0, touched, pressed, menu, grip)


class _Hand:
    """One controller's own state in the controllers' stream: its reach track, inputs, dropouts."""

    __slots__ = ("buttons", "dev", "drop_at", "drop_end", "drops", "frame", "held", "last", "order", "packet",
                 "state", "track")

    def __init__(self, source: SyntheticSource, k: int, dev: Device) -> None:
        side = -1.0 if dev.role == "left" else 1.0
        self.dev, self.frame, self.order = dev, dev.frame, 2 + k
        self.track = _Track(_hand_rest(side), _hand_plan(source._rng(f"hand-{dev.role}"), side))
        self.buttons = _Buttons(source._rng(f"buttons-{dev.role}"))
        self.drops = source._rng(f"dropouts-{dev.role}")
        self.drop_at = self.drops.uniform(1.0, 4.0) if source.dropouts else math.inf
        self.drop_end = self.drop_at + self.drops.uniform(0.1, 0.4)
        self.last: Quat | None = None
        self.held: tuple[Vec3, Quat] = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
        self.state: tuple[float, float, float, tuple[bool, ...]] | None = None
        self.packet = 0


class SyntheticSource:
    """A synthetic user's headset, two controllers and two base stations, deterministic per seed.

    Samples come on exact grids (sample n at t0 + n / rate: no accumulated float error), merged
    in time order: the hmd at rate_hmd, each controller's pose at rate_controllers and a
    ControllerSample whenever its inputs change (packet + 1, like OpenVR's unPacketNum), the base
    stations once at the start and then once a second. With `dropouts`, each controller now and
    then loses tracking for 0.1-0.4 s (valid False, its last pose, zero velocity)."""

    frame = "openvr"
    paced = False

    def __init__(self, seed: int = 0, rate_hmd: float = 90, rate_controllers: float = 250,
                 duration: float | None = None, t0: float | None = None, dropouts: bool = False) -> None:
        for name, rate in (("rate_hmd", rate_hmd), ("rate_controllers", rate_controllers)):
            if not (math.isfinite(rate) and rate > 0):
                raise Fail(f"{name} must be a positive number of samples per second, not {rate}")
        if duration is not None and not (duration >= 0):
            raise Fail(f"duration must be >= 0 seconds, not {duration}")
        self.seed = seed
        self.rate_hmd = float(rate_hmd)
        self.rate_controllers = float(rate_controllers)
        self.duration = duration
        self.t0 = time.time() if t0 is None else float(t0)
        self.dropouts = dropouts
        self.counts: dict[str, int] = {}

    def _rng(self, name: str) -> random.Random:
        """An independent random stream per part, so e.g. a rate change does not alter the motion."""
        return random.Random(f"ttctl-synthetic:{self.seed}:{name}")

    def _grid(self, period: float) -> Iterator[float]:
        """Seconds since the start of each sample: n * period while below the duration."""
        n = 0
        while self.duration is None or n * period < self.duration:
            yield n * period
            n += 1

    def _body(self) -> tuple[_Track, _Track]:
        """The body's yaw and the neck pivot: each stream gets its own copies of the same
        (seeded) tracks, as tracks are queried in time order by one stream each."""
        return (_Track([0.0], _body_plan(self._rng("body"))),
                _Track([0.0, NECK_HEIGHT, 0.0], _neck_plan(self._rng("neck"))))

    def _hmd(self) -> Iterator[tuple[float, int, Sample, str]]:
        head = _Track([0.0, 0.0, 0.0], _head_plan(self._rng("head")))
        body, neck = self._body()
        last: Quat | None = None
        t0, frame = self.t0, HMD.frame
        for u in self._grid(1.0 / self.rate_hmd):
            (yaw, pitch, roll), rates = head.at(u)
            (turn,), (dturn,) = body.at(u)
            yaw = yaw + turn
            pivot, dpivot = neck.at(u)
            r, w = _turning(yaw, pitch, roll, rates[0] + dturn, rates[1], rates[2])
            eye = _mat_vec(r, EYE_OFFSET)
            spin = _cross(w, eye)
            pos = (pivot[0] + eye[0], pivot[1] + eye[1], pivot[2] + eye[2])
            vel = (dpivot[0] + spin[0], dpivot[1] + spin[1], dpivot[2] + spin[2])
            last = continuous(quat_from_matrix(r), last)  # the matrix's rotation part is all it reads
            yield t0 + u, 1, PoseSample(t0 + u, HMD, True, True, pos, last, vel, w), frame

    def _controllers(self) -> Iterator[tuple[float, int, Sample, str]]:
        """Both hands, on one grid: the body and neck they move with are computed once per
        instant (the hmd has its own copies). At each instant: left pose, left inputs (if they
        changed), right pose, right inputs, as the merge orders them."""
        hands = [_Hand(self, k, dev) for k, dev in enumerate(CONTROLLERS)]
        body, neck = self._body()
        t0 = self.t0
        for u in self._grid(1.0 / self.rate_controllers):
            t = t0 + u
            (turn,), (dturn,) = body.at(u)
            pivot, dpivot = neck.at(u)
            c, s = math.cos(turn), math.sin(turn)
            for h in hands:
                v, dv = h.track.at(u)  # in the body's frame: x right, y up from the floor, -z ahead
                while u >= h.drop_end:
                    h.drop_at = h.drop_end + h.drops.uniform(3.0, 8.0)
                    h.drop_end = h.drop_at + h.drops.uniform(0.1, 0.4)
                if h.drop_at <= u and h.last is not None:
                    yield t, h.order, PoseSample(t, h.dev, False, True, h.held[0], h.held[1]), h.frame
                else:
                    # arm = Ry(turn) v, darm likewise, spin = (0, dturn, 0) x arm: _cross's very
                    # expressions, spelt out (no tuples), so the numbers are the same to the bit
                    v0, v2, dv0, dv2 = v[0], v[2], dv[0], dv[2]
                    arm0, arm1, arm2 = c * v0 + s * v2, v[1], -s * v0 + c * v2
                    pos = (pivot[0] + arm0, arm1, pivot[2] + arm2)
                    vel = (dpivot[0] + (dturn * arm2 - 0.0 * arm1) + (c * dv0 + s * dv2),
                           (0.0 * arm0 - 0.0 * arm2) + dv[1],
                           dpivot[2] + (0.0 * arm1 - dturn * arm0) + (-s * dv0 + c * dv2))
                    # Ry(turn) Ry(yaw) = Ry(turn + yaw)
                    r, w = _turning(turn + v[3], v[4], v[5], dturn + dv[3], dv[4], dv[5])
                    last = h.last = continuous(quat_from_matrix(r), h.last)
                    h.held = (pos, last)
                    yield t, h.order, PoseSample(t, h.dev, True, True, pos, last, vel, w), h.frame
                now = h.buttons.at(u)
                if now != h.state:
                    h.state = now
                    h.packet += 1
                    trigger, pad_x, pad_y, pressed = now
                    yield t, h.order, ControllerSample(t, h.dev, h.packet, trigger, pad_x, pad_y,
                                                       dict(zip(BUTTONS, pressed, strict=True))), h.frame

    def _base_stations(self) -> Iterator[tuple[float, int, Sample, str]]:
        poses = []
        for dev, corner in zip(BASE_STATIONS, ((-1.5, 2.0, -1.5), (1.5, 2.0, 1.5)), strict=True):
            r = look_at(corner, (0.0, 1.0, 0.0))
            poses.append((dev, corner, quat_from_matrix(_pose_matrix(r, corner)), dev.frame))
        for u in self._grid(BASE_PERIOD):
            for dev, pos, q, frame in poses:
                yield self.t0 + u, 0, PoseSample(self.t0 + u, dev, True, True, pos, q), frame

    def samples(self) -> Iterator[Sample]:
        """All devices' samples merged in time order (ties: base stations, hmd, left, right).
        Entries are (t, order, sample, frame): (t, order) is unique across streams, so the
        merge never compares samples and needs no key function."""
        counts = self.counts
        for _t, _order, s, frame in heapq.merge(self._base_stations(), self._hmd(), self._controllers()):
            counts[frame] = counts.get(frame, 0) + 1
            yield s

    def close(self) -> None:
        """Nothing to release."""


__all__ = ["BASE_STATIONS", "CONTROLLERS", "HMD", "SyntheticSource", "angular_velocity", "look_at", "min_jerk",
           "rotation"]
