"""The orbit camera's maths (ttctl.hmd.orbit): placement, head steering, clamping, speed zoom,
frame-rate-independent smoothing."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import shipped
from ttctl.hmd.frames import matrix_from_quat
from ttctl.hmd.orbit import (
    OrbitCamera,
    OrbitParams,
    approach_angle,
    head_angles,
    place,
    target_distance,
    target_view,
    wrap,
)

P = OrbitParams()


def yaw_pitch_quat(yaw: float, pitch: float) -> tuple[float, float, float, float]:
    """A REP-103 head orientation: yaw (counter-clockwise about z), then pitch (nose-down about y)."""
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    return (-sp * sy, sp * cy, cp * sy, cp * cy)


def forward(q: tuple[float, float, float, float]) -> list[float]:
    m = matrix_from_quat(q)
    return [m[0][0], m[1][0], m[2][0]]


@given(st.floats(-math.pi, math.pi), st.floats(-1.0, 1.3), st.floats(0.5, 50.0),
       st.tuples(st.floats(-100, 100), st.floats(-100, 100), st.floats(-50, 0)))
@settings(max_examples=200, deadline=None)
def test_the_camera_looks_at_the_drone_from_where_it_is(view_yaw: float, el: float, r: float,
                                                         target: tuple[float, float, float]) -> None:
    cam = place(view_yaw, el, r, target)
    off = cam.offset
    assert math.dist(cam.position, target) == pytest.approx(r, rel=1e-9)
    f = forward(cam.orientation)
    assert f == pytest.approx([-c / r for c in off], abs=1e-9)  # its x axis points at the drone
    assert -off[2] / r == pytest.approx(math.sin(el), abs=1e-9)  # NED: above means -z
    assert sum(c * c for c in cam.orientation) == pytest.approx(1.0)
    m = matrix_from_quat(cam.orientation)  # no roll: the camera's y axis stays horizontal
    assert m[2][1] == pytest.approx(0.0, abs=1e-9)


def test_level_head_puts_the_camera_behind_the_drone_looking_its_way() -> None:
    for drone_yaw in (0.0, math.pi / 2, -2.0):
        yaw, el = target_view(0.0, 0.0, drone_yaw, P)
        cam = place(yaw, el, 10.0, (0.0, 0.0, -20.0))
        assert yaw == pytest.approx(wrap(drone_yaw))
        n, e = cam.offset[0], cam.offset[1]
        assert n == pytest.approx(-10 * math.cos(P.elevation) * math.cos(drone_yaw))
        assert e == pytest.approx(-10 * math.cos(P.elevation) * math.sin(drone_yaw))


def test_head_left_turns_the_view_left_and_looking_down_raises_the_camera() -> None:
    yaw, _ = target_view(math.radians(30), 0.0, 0.0, P)  # head turned left (counter-clockwise)
    assert yaw == pytest.approx(math.radians(-30))  # the view turns left: west of north
    _, el_down = target_view(0.0, math.radians(20), 0.0, P)  # nose down (REP-103 pitch > 0)
    assert el_down == pytest.approx(P.elevation + math.radians(20))
    q = yaw_pitch_quat(math.radians(30), math.radians(10))
    assert head_angles(q) == pytest.approx((math.radians(30), math.radians(10)))


def test_roll_is_ignored() -> None:
    q = yaw_pitch_quat(0.4, 0.2)
    x, y, z, w = q  # then roll 25 degrees about the head's own x
    cr, sr = math.cos(math.radians(12.5)), math.sin(math.radians(12.5))
    rolled = (w * sr + x * cr, y * cr + z * sr, z * cr - y * sr, w * cr - x * sr)
    assert head_angles(rolled) == pytest.approx(head_angles(q), abs=1e-9)


def test_elevation_is_clamped_away_from_the_poles() -> None:
    for pitch in (-3.0, -1.5, 1.5, 3.0):
        _, el = target_view(0.0, pitch, 0.0, P)
        assert P.min_elevation <= el <= P.max_elevation
        assert abs(el) < math.radians(85)


def test_distance_grows_with_speed_within_limits() -> None:
    ds = [target_distance(v, P) for v in (0.0, 1.0, 3.0, 6.0, 100.0)]
    assert ds[0] == P.min_distance
    assert ds == sorted(ds) and ds[1] > ds[0]
    assert ds[-1] == P.max_distance
    assert target_distance(float("nan"), P) == P.min_distance


def test_smoothing_is_frame_rate_independent_and_tau_is_63_percent() -> None:
    def run(hz: float) -> OrbitCamera:
        cam = OrbitCamera()
        cam.update(0.0, (0, 0, -10), 0.0, 0.0)
        cam.set_head(yaw_pitch_quat(math.radians(-90), 0.0), 0.0)  # a step: head 90 degrees right
        t = 0.0
        while t < P.tau_angle - 1e-12:
            t = min(P.tau_angle, t + 1.0 / hz)
            cam.update(t, (0, 0, -10), 0.0, 0.0)
        return cam

    views = [run(hz).camera.view_yaw for hz in (7.0, 30.0, 90.0, 1000.0)]  # type: ignore[union-attr]
    assert max(views) - min(views) < 1e-9
    assert views[0] == pytest.approx(math.radians(90) * (1 - math.exp(-1)), rel=1e-9)


def test_angles_take_the_short_way_round() -> None:
    a = approach_angle(math.radians(170), math.radians(-170), 10.0, 0.15)
    assert a == pytest.approx(math.radians(-170))
    mid = approach_angle(math.radians(170), math.radians(-170), 0.15 * math.log(2), 0.15)
    assert abs(wrap(mid - math.pi)) < math.radians(0.01)  # half way: through 180, not through 0


def test_zoom_follows_speed_slowly() -> None:
    cam = OrbitCamera()
    cam.update(0.0, (0, 0, -10), 0.0, 0.0)
    c = cam.update(P.tau_distance, (0, 0, -10), 0.0, 8.0)
    want = target_distance(8.0, P)
    assert c.distance == pytest.approx(P.min_distance + (want - P.min_distance) * (1 - math.exp(-1)))


# -- the onboard end's built-in plugin ----------------------------------------------------------

def test_the_plugin_publishes_to_the_tablet_ground_stations_and_plugins() -> None:
    import ttapi
    from ttctl.ends.onboard.orbit_camera import OrbitCameraPlugin
    from ttctl.ends.onboard.vehicle import EARTH_RADIUS, SimVehicle
    from ttctl.ends.plugins import Context

    v = SimVehicle()
    tablet: list[object] = []
    gcs: list[object] = []
    timers: list[tuple[float, object]] = []
    ctx = Context(send=lambda m, urgent=False: tablet.append(m), send_gcs=gcs.append, vehicle=v,
                  every=lambda s, fn: timers.append((s, fn)), dialect=shipped())
    plugin = OrbitCameraPlugin(rate=10.0)
    plugin.start(ctx)
    assert timers and timers[0][0] == pytest.approx(0.1)
    plugin.publish()
    assert not tablet and not gcs  # no head yet: nothing to say
    hq = yaw_pitch_quat(0.0, 0.0)
    pose = ttapi.TtVrPose(time_usec=1, device=int(ttapi.TtVrDevice.TT_VR_DEVICE_HMD), role=0, index=0,
                          flags=int(ttapi.TtVrPoseFlags.TT_VR_POSE_FLAGS_VALID), position=[0, 0, 1.7],
                          orientation=list(hq), velocity=[0, 0, 0], angular_velocity=[0, 0, 0])
    plugin.on_pose(pose, ctx)
    plugin.publish()
    (msg,) = tablet
    assert isinstance(msg, ttapi.DjiPoseStamped)
    assert msg.topic_name == ttapi.DjiTopicName.DJI_TOPIC_NAME_ORBIT_CAMERA
    cam = ctx.shared["orbit_camera"]
    assert list(msg.position) == pytest.approx(list(cam.position))
    (fov,) = gcs
    assert isinstance(fov, ttapi.CameraFovStatus)
    home = v.snapshot().home
    # the image centre is the drone (at home, on the ground), the camera behind it (south, heading 0) and above
    assert fov.lat_image == round(home.lat * 1e7) and fov.lon_image == round(home.lon * 1e7)
    north = math.radians((fov.lat_camera - fov.lat_image) / 1e7) * EARTH_RADIUS
    assert north == pytest.approx(cam.offset[0], abs=0.02) and north < 0
    assert (fov.alt_camera - fov.alt_image) / 1000 == pytest.approx(-cam.offset[2], abs=0.002)
    assert list(fov.q) == pytest.approx([cam.orientation[3], *cam.orientation[:3]])  # w first, as MAVLink says
    # an invalid pose, another device, or NaN does not move it
    for bad in (dict(flags=0), dict(device=int(ttapi.TtVrDevice.TT_VR_DEVICE_CONTROLLER)),
                dict(orientation=[math.nan, 0, 0, 1])):
        m = ttapi.TtVrPose(**{**{f: getattr(pose, f) for f in pose.FIELDS}, **bad,
                              "orientation": bad.get("orientation", list(yaw_pitch_quat(1.0, 0.0)))})
        plugin.on_pose(m, ctx)
    assert plugin.orbit.head == pytest.approx((0.0, 0.0))


def test_camera_fov_status_carries_the_ground_stations_time() -> None:
    """The onboard end hands the plugin its ground stations' clock (the wall clock, whatever
    --speed is), so CAMERA_FOV_STATUS agrees with the rest of their telemetry."""
    import ttapi
    from ttctl.ends.onboard.orbit_camera import OrbitCameraPlugin
    from ttctl.ends.onboard.vehicle import SimVehicle
    from ttctl.ends.plugins import Context

    v = SimVehicle()
    v.step(100.0)  # the vehicle's clock is far ahead
    gcs: list[object] = []
    ctx = Context(send=lambda m, urgent=False: None, send_gcs=gcs.append, vehicle=v,
                  every=lambda s, fn: None, dialect=shipped())
    plugin = OrbitCameraPlugin(rate=10.0, boot_ms=lambda: 2500)
    plugin.start(ctx)
    pose = ttapi.TtVrPose(time_usec=1, device=int(ttapi.TtVrDevice.TT_VR_DEVICE_HMD), role=0, index=0,
                          flags=int(ttapi.TtVrPoseFlags.TT_VR_POSE_FLAGS_VALID), position=[0, 0, 1.7],
                          orientation=list(yaw_pitch_quat(0.0, 0.0)), velocity=[0, 0, 0], angular_velocity=[0, 0, 0])
    plugin.on_pose(pose, ctx)
    plugin.publish()
    (fov,) = gcs
    assert fov.time_boot_ms == 2500  # type: ignore[attr-defined]
