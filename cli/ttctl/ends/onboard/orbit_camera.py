"""The orbit camera, built into the onboard end: the head pose streamed from the tablet
(TT_VR_POSE of the headset, `ttctl hmd dump --to`) steers a virtual camera around the drone
(the maths: ttctl.hmd.orbit). While head poses arrive it is published at `rate` Hz:

- to the tablet as DJI_POSE_STAMPED with topic DJI_TOPIC_NAME_ORBIT_CAMERA (local NED position,
  FRD orientation in NED, the sample's stamp);
- to ground stations as CAMERA_FOV_STATUS (camera and image centre as lat/lon/alt, the view's
  quaternion w, x, y, z, field of view), which QGroundControl's MAVLink Inspector and
  MAVProxy show;
- to other plugins as ctx.shared["orbit_camera"] (a ttctl.hmd.orbit.Camera).

Head poses older than `stale` seconds stop the publishing: the camera holds its last place.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from typing import Any

from ...hmd.orbit import Camera, OrbitCamera, OrbitParams
from ...wire.bindings import Bindings
from ...wire.contract import TtVrDevice, TtVrPoseFlags
from ..plugins import Context, Plugin, handles
from .vehicle import EARTH_RADIUS

HMD = int(TtVrDevice.TT_VR_DEVICE_HMD)
VALID = int(TtVrPoseFlags.TT_VR_POSE_FLAGS_VALID)


class OrbitCameraPlugin(Plugin):
    """`rate`: publications per second of the end's clock; `boot_ms`: CAMERA_FOV_STATUS's
    time_boot_ms (the ground stations' clock; None: the end's)."""

    def __init__(self, rate: float = 10.0, stale: float = 2.0, params: OrbitParams | None = None,
                 boot_ms: Callable[[], int] | None = None) -> None:
        self.rate = rate
        self.stale = stale
        self.boot_ms = boot_ms
        self.orbit = OrbitCamera(params)
        self.ctx: Context | None = None
        self.published = 0
        self.following = False

    def start(self, ctx: Context) -> None:
        self.ctx = ctx
        ctx.every(1.0 / self.rate, self.publish)

    def _clock(self) -> float:
        v = self.ctx.vehicle if self.ctx is not None else None
        return float(v.snapshot().time) if v is not None else time.monotonic()

    def _advance(self, now: float) -> Camera | None:
        """Smooth up to now with the head held since the last pose, from the drone's state."""
        v = self.ctx.vehicle if self.ctx is not None else None
        if v is None:
            return None
        s = v.snapshot()
        speed = math.sqrt(s.vn * s.vn + s.ve * s.ve + s.vd * s.vd)
        return self.orbit.update(now, (s.n, s.e, s.d), s.yaw, speed)

    @handles("TT_VR_POSE")
    def on_pose(self, msg: Any, ctx: Context) -> None:
        if msg.device != HMD or not msg.flags & VALID:
            return
        q = tuple(float(c) for c in msg.orientation)
        if len(q) != 4 or not all(math.isfinite(c) for c in q):
            return
        now = self._clock()
        if self.orbit.heard is not None:
            self._advance(now)
        elif not self.following:
            ctx.log("orbit camera: following the head poses from the tablet")
        self.following = True
        self.orbit.set_head((q[0], q[1], q[2], q[3]), now)

    def publish(self) -> None:
        ctx = self.ctx
        if ctx is None or self.orbit.heard is None:
            return
        now = self._clock()
        if now - self.orbit.heard > self.stale:
            return
        cam = self._advance(now)
        if cam is None:
            return
        ctx.shared["orbit_camera"] = cam
        unix = time.time()
        x, y, z, w = cam.orientation
        b = ctx.dialect
        ctx.send(b.DjiPoseStamped(target_system=255, sec=int(unix), nsec=int((unix % 1) * 1e9),
                                  topic_name=int(b.DjiTopicName.DJI_TOPIC_NAME_ORBIT_CAMERA),
                                  position=list(cam.position), orientation=[x, y, z, w]))
        if ctx.vehicle is not None:
            boot_ms = self.boot_ms() if self.boot_ms is not None else int(now * 1000)
            ctx.send_gcs(fov_status(b, cam, ctx.vehicle.snapshot().home, boot_ms, self.orbit.p))
        self.published += 1


def geodetic(home: Any, ned: tuple[float, float, float]) -> tuple[int, int, int]:
    """(lat degE7, lon degE7, alt mm MSL) of a local NED point (the vehicle's flat-earth model)."""
    lat = home.lat + math.degrees(ned[0] / EARTH_RADIUS)
    lon = home.lon + math.degrees(ned[1] / (EARTH_RADIUS * math.cos(math.radians(home.lat))))
    return round(lat * 1e7), round(lon * 1e7), round((home.alt - ned[2]) * 1000)


def fov_status(b: Bindings, cam: Camera, home: Any, boot_ms: int, p: OrbitParams) -> Any:
    lat_c, lon_c, alt_c = geodetic(home, cam.position)
    lat_i, lon_i, alt_i = geodetic(home, cam.target)
    x, y, z, w = cam.orientation
    return b.CameraFovStatus(time_boot_ms=boot_ms & 0xFFFFFFFF, lat_camera=lat_c, lon_camera=lon_c,
                             alt_camera=alt_c, lat_image=lat_i, lon_image=lon_i, alt_image=alt_i,
                             q=[w, x, y, z], hfov=math.degrees(p.hfov), vfov=math.degrees(p.vfov),
                             camera_device_id=0)


__all__ = ["OrbitCameraPlugin", "fov_status", "geodetic"]
