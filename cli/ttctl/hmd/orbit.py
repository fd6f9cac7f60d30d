"""The orbit camera: a virtual camera circling the drone, steered by the head.

The user in the headset sees the drone from a camera that orbits it at a distance, always
looking at it. Head yaw turns the camera around the drone's yaw (vertical) axis, head pitch
around its pitch axis: look down and the camera rises to look down on the drone. Roll is
ignored (a tilted horizon in a headset is what makes people sick). The distance grows with
the drone's speed (more context when it moves fast) and shrinks as it slows near a point of
interest. After Hrlec's orbit camera (thesis ch. 4.11-4.12); the placement is the usual
spherical one, position = target + r (cos el cos az, cos el sin az, sin el).

Everything is in the drone's local NED frame (x north, y east, z down; metres from home),
angles in radians. The view yaw is the compass direction the camera looks in (0 north,
clockwise), so with the head straight ahead the camera sits behind the drone looking the way
it points. Head angles come from REP-103 poses (yaw counter-clockwise from the VR world's x,
pitch positive nose-down): turning the head left turns the view left.

Smoothing is first order, x += (x* - x)(1 - exp(-dt / tau)): exact for a target held between
updates, so the camera moves the same whether it is updated at 10 Hz or 1 kHz (frame-rate
independent), and after a step the camera has covered 63 % of it after tau.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .frames import yaw_pitch_roll
from .model import Quat


@dataclass(frozen=True)
class OrbitParams:
    elevation: float = math.radians(20.0)  # the camera's elevation with the head level
    min_elevation: float = math.radians(-60.0)  # clamped away from the poles, where azimuth is undefined
    max_elevation: float = math.radians(80.0)
    min_distance: float = 4.0  # m, the drone hovering
    max_distance: float = 25.0  # m
    distance_per_speed: float = 2.5  # m of distance per m/s of the drone's speed
    tau_angle: float = 0.15  # s, the view's time constant: it follows the head closely
    tau_distance: float = 1.5  # s, the zoom's: slow, so that a gust does not pump it
    hfov: float = math.radians(90.0)  # what a ground station is told the camera sees
    vfov: float = math.radians(60.0)


@dataclass(frozen=True)
class Camera:
    """Where the camera is and how it looks: published to the tablet and ground stations."""

    view_yaw: float  # compass direction of the view, radians (0 north, clockwise)
    elevation: float  # above the drone's horizon, radians
    distance: float  # from the drone, m
    position: tuple[float, float, float]  # NED, m from home
    target: tuple[float, float, float]  # the drone, NED
    orientation: Quat  # x, y, z, w of the camera's FRD body (x along the view) in NED

    @property
    def offset(self) -> tuple[float, float, float]:
        return (self.position[0] - self.target[0], self.position[1] - self.target[1],
                self.position[2] - self.target[2])


def head_angles(q: Quat) -> tuple[float, float]:
    """(yaw, pitch) of a REP-103 head orientation: yaw counter-clockwise, pitch nose-down; roll dropped."""
    yaw, pitch, _roll = yaw_pitch_roll(q)
    return yaw, pitch


def target_view(head_yaw: float, head_pitch: float, drone_yaw: float, p: OrbitParams) -> tuple[float, float]:
    """Where the head asks the camera to be: (view yaw, elevation). The view turns with the
    drone's yaw and against the head's counter-clockwise yaw (left is anti-clockwise from above);
    the elevation is the resting one plus the head's downward pitch, clamped."""
    view_yaw = wrap(drone_yaw - head_yaw)
    elevation = min(p.max_elevation, max(p.min_elevation, p.elevation + head_pitch))
    return view_yaw, elevation


def target_distance(speed: float, p: OrbitParams) -> float:
    """Farther the faster the drone goes, within [min, max]."""
    if not math.isfinite(speed):
        speed = 0.0
    return min(p.max_distance, max(p.min_distance, p.min_distance + p.distance_per_speed * abs(speed)))


def place(view_yaw: float, elevation: float, distance: float, target: tuple[float, float, float]) -> Camera:
    """The camera `distance` from `target`, looking at it along `view_yaw`, from `elevation`
    above its horizon (NED: up is -z)."""
    ce = math.cos(elevation)
    back = (-ce * math.cos(view_yaw), -ce * math.sin(view_yaw), -math.sin(elevation))  # from target to camera
    pos = (target[0] + distance * back[0], target[1] + distance * back[1], target[2] + distance * back[2])
    return Camera(view_yaw, elevation, distance, pos, target, quat_from_yaw_pitch(view_yaw, -elevation))


def quat_from_yaw_pitch(yaw: float, pitch: float) -> Quat:
    """(x, y, z, w) of yaw about z then pitch about y (FRD body in NED: pitch positive nose-up)."""
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    return (-sp * sy, sp * cy, cp * sy, cp * cy)


def wrap(a: float) -> float:
    """An angle in [-pi, pi)."""
    return (a + math.pi) % (2 * math.pi) - math.pi


def approach(current: float, target: float, dt: float, tau: float) -> float:
    """One first-order smoothing step of length dt (any dt: steps compose exactly)."""
    if dt <= 0:
        return current
    return current + (target - current) * (1.0 - math.exp(-dt / tau)) if tau > 0 else target


def approach_angle(current: float, target: float, dt: float, tau: float) -> float:
    """approach() the short way round the circle."""
    return wrap(current + approach(0.0, wrap(target - current), dt, tau))


class OrbitCamera:
    """The camera's smoothed state. Feed it the head (`head`) when a pose arrives and advance it
    (`update`) whenever the drone's state is read; both can come at any rate."""

    def __init__(self, params: OrbitParams | None = None) -> None:
        self.p = params or OrbitParams()
        self.head: tuple[float, float] = (0.0, 0.0)  # yaw, pitch: held until the next pose
        self.heard: float | None = None  # when the last head pose came (the updater's clock)
        self._yaw: float | None = None
        self._elevation = self.p.elevation
        self._distance = self.p.min_distance
        self._time: float | None = None
        self.camera: Camera | None = None

    def set_head(self, q: Quat, now: float) -> None:
        yaw, pitch = head_angles(q)
        if math.isfinite(yaw) and math.isfinite(pitch):
            self.head = (yaw, pitch)
            self.heard = now

    def update(self, now: float, drone: tuple[float, float, float], drone_yaw: float, speed: float) -> Camera:
        """Advance the smoothing to `now` toward what the head and the drone ask, and place the camera."""
        view_yaw, elevation = target_view(self.head[0], self.head[1], drone_yaw, self.p)
        distance = target_distance(speed, self.p)
        if self._yaw is None or self._time is None:  # the first update starts where it is asked to be
            self._yaw, self._elevation, self._distance = view_yaw, elevation, distance
        else:
            dt = now - self._time
            self._yaw = approach_angle(self._yaw, view_yaw, dt, self.p.tau_angle)
            self._elevation = approach(self._elevation, elevation, dt, self.p.tau_angle)
            self._distance = approach(self._distance, distance, dt, self.p.tau_distance)
        self._time = now
        self.camera = place(self._yaw, self._elevation, self._distance, drone)
        return self.camera


__all__ = ["Camera", "OrbitCamera", "OrbitParams", "approach", "approach_angle", "head_angles", "place",
           "target_distance", "target_view", "wrap"]
