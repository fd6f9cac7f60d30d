"""The frame maths of ttctl.hmd.frames: rotation matrix -> quaternion (exact near 180 degrees),
OpenVR -> ROS REP-103 (C R C^T), sign continuity, Euler angles."""

from __future__ import annotations

import math
import random

import pytest

from ttctl.hmd.frames import (
    Continuity,
    continuous,
    convert,
    matrix_from_quat,
    normalise,
    pose_to_openvr,
    pose_to_ros,
    quat_from_matrix,
    quat_to_ros,
    vec_to_ros,
    yaw_pitch_roll,
)
from ttctl.hmd.model import ControllerSample, Device, PoseSample

HMD = Device(0, "hmd")
C = [[0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]  # OpenVR -> REP-103 axes


def axis_angle_matrix(axis: tuple[float, float, float], angle: float) -> list[list[float]]:
    """Rodrigues' formula, written independently of the code under test."""
    n = math.sqrt(sum(a * a for a in axis))
    x, y, z = (a / n for a in axis)
    c, s, t = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c]]


def axis_angle_quat(axis: tuple[float, float, float], angle: float) -> tuple[float, float, float, float]:
    n = math.sqrt(sum(a * a for a in axis))
    s = math.sin(angle / 2) / n
    return (axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle / 2))


def same_rotation(q1, q2, tol: float = 1e-9) -> bool:
    """q and -q are the same rotation."""
    return (all(abs(a - b) <= tol for a, b in zip(q1, q2, strict=True))
            or all(abs(a + b) <= tol for a, b in zip(q1, q2, strict=True)))


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def apply(m, v):
    return tuple(sum(m[i][k] * v[k] for k in range(3)) for i in range(3))


def random_quat(rng: random.Random) -> tuple[float, float, float, float]:
    return normalise((rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1)))


AXES = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (1, -1, 0), (0, 1, 1), (1, 0, -1), (1, 1, 1), (-1, 2, 3)]


@pytest.mark.parametrize("axis", AXES)
@pytest.mark.parametrize("degrees", [180.0, 179.999, -179.999, 90.0, 45.0, 1e-4, 1e-9, 0.0])
def test_quat_from_matrix_known_rotations(axis, degrees):
    q = quat_from_matrix(axis_angle_matrix(axis, math.radians(degrees)))
    assert same_rotation(q, axis_angle_quat(axis, math.radians(degrees)), 1e-9)
    assert math.isclose(math.sqrt(sum(c * c for c in q)), 1.0, abs_tol=1e-12)
    assert q[3] >= 0


@pytest.mark.parametrize("axis", [(1, 0, 0), (0, 1, 0), (0, 0, 1)])
def test_half_turns_about_the_axes_are_exact(axis):
    """Where the trace formula divides by ~0: the answer must be the axis itself, w = 0."""
    q = quat_from_matrix(axis_angle_matrix(axis, math.pi))
    assert same_rotation(q, (*map(float, axis), 0.0), 1e-12)


def test_near_half_turn_keeps_the_small_w():
    """179.999 deg: w = cos(89.9995 deg) ~ 8.7e-6 must survive, not be lost in rounding."""
    angle = math.radians(179.999)
    q = quat_from_matrix(axis_angle_matrix((1, 1, 1), angle))
    assert math.isclose(q[3], math.cos(angle / 2), rel_tol=1e-5)


def test_round_trip_random_rotations():
    rng = random.Random(7)
    for _ in range(2000):
        q = random_quat(rng)
        assert same_rotation(quat_from_matrix(matrix_from_quat(q)), q, 1e-12)


def test_handedness_quarter_turn_about_z_maps_x_to_y():
    m = axis_angle_matrix((0, 0, 1), math.pi / 2)
    assert all(math.isclose(a, b, abs_tol=1e-15) for a, b in zip(apply(m, (1, 0, 0)), (0, 1, 0), strict=True))
    q = quat_from_matrix(m)
    assert same_rotation(q, (0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)), 1e-12)
    assert q[2] > 0  # right-handed: positive about +z


def test_a_3x4_pose_matrix_ignores_the_translation():
    m = axis_angle_matrix((0, 1, 0), 0.7)
    m34 = [[*m[0], 5.0], [*m[1], 1.7], [*m[2], -3.0]]
    assert quat_from_matrix(m34) == quat_from_matrix(m)


def test_slightly_scaled_matrix_still_gives_a_unit_quaternion():
    m = [[1.01 * c for c in row] for row in axis_angle_matrix((1, 2, 3), 2.0)]
    q = quat_from_matrix(m)
    assert math.isclose(math.sqrt(sum(c * c for c in q)), 1.0, abs_tol=1e-12)
    assert same_rotation(q, axis_angle_quat((1, 2, 3), 2.0), 1e-2)


# -- OpenVR -> ROS REP-103 --------------------------------------------------------------------

def test_headset_looking_forward_at_standing_height():
    """OpenVR: 1.7 m up (+y), looking along -z, 1 m forward. ROS: x forward, z up, identity."""
    s = pose_to_ros(PoseSample(0.0, HMD, position=(0.0, 1.7, -1.0)))
    assert s.position == pytest.approx((1.0, 0.0, 1.7))
    assert same_rotation(s.orientation, (0.0, 0.0, 0.0, 1.0), 1e-12)
    assert yaw_pitch_roll(s.orientation) == pytest.approx((0.0, 0.0, 0.0))


def test_looking_left_is_positive_yaw_about_z():
    """OpenVR yaw +90 deg about +y turns -z (forward) to -x (left); ROS: +90 about z, body x -> +y."""
    r_vr = axis_angle_matrix((0, 1, 0), math.pi / 2)
    assert apply(r_vr, (0, 0, -1)) == pytest.approx((-1, 0, 0))
    q = quat_to_ros(quat_from_matrix(r_vr))
    assert same_rotation(q, axis_angle_quat((0, 0, 1), math.pi / 2), 1e-12)
    assert yaw_pitch_roll(q) == pytest.approx((math.pi / 2, 0.0, 0.0))
    assert apply(matrix_from_quat(q), (1, 0, 0)) == pytest.approx((0, 1, 0), abs=1e-12)


def test_looking_up_is_negative_ros_pitch():
    """OpenVR +x is right; positive rotation about it lifts the nose. REP-103 pitch is nose-down positive."""
    q = quat_to_ros(quat_from_matrix(axis_angle_matrix((1, 0, 0), 0.4)))
    yaw, pitch, roll = yaw_pitch_roll(q)
    assert pitch == pytest.approx(-0.4) and yaw == pytest.approx(0.0) and roll == pytest.approx(0.0)


def test_conversion_is_c_r_c_transposed():
    rng = random.Random(3)
    for _ in range(200):
        q = random_quat(rng)
        expected = matmul(matmul(C, matrix_from_quat(q)), transpose(C))
        got = matrix_from_quat(quat_to_ros(q))
        assert all(math.isclose(got[i][j], expected[i][j], abs_tol=1e-12) for i in range(3) for j in range(3))
        v = (rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2))
        assert vec_to_ros(v) == pytest.approx(apply(C, v))


def test_ros_openvr_ros_round_trip():
    rng = random.Random(11)
    for _ in range(200):
        s = PoseSample(1.0, HMD, True, True, tuple(rng.uniform(-3, 3) for _ in range(3)), random_quat(rng),
                       tuple(rng.uniform(-1, 1) for _ in range(3)), tuple(rng.uniform(-5, 5) for _ in range(3)))
        back = convert(convert(s, "ros", "openvr"), "openvr", "ros")
        assert back.position == pytest.approx(s.position) and back.velocity == pytest.approx(s.velocity)
        assert back.orientation == pytest.approx(s.orientation)
        assert back.angular_velocity == pytest.approx(s.angular_velocity)
        assert pose_to_ros(pose_to_openvr(s)).orientation == pytest.approx(s.orientation)


def test_angular_velocity_converts_like_a_vector():
    """Turning left in OpenVR (+y) is turning left in ROS (+z)."""
    s = pose_to_ros(PoseSample(0.0, HMD, angular_velocity=(0.0, 2.0, 0.0), velocity=(0.0, 0.0, -1.0)))
    assert s.angular_velocity == pytest.approx((0.0, 0.0, 2.0))
    assert s.velocity == pytest.approx((1.0, 0.0, 0.0))


def test_convert_leaves_controller_samples_and_same_frame_alone():
    c = ControllerSample(0.0, Device(3, "controller", "left"), 1, 0.5)
    assert convert(c, "openvr", "ros") is c
    p = PoseSample(0.0, HMD, position=(1.0, 2.0, 3.0))
    assert convert(p, "ros", "ros") is p


# -- continuity and Euler angles ----------------------------------------------------------------

def test_continuous_flips_sign_to_stay_near_previous():
    q = axis_angle_quat((0, 1, 0), 3.0)
    neg = tuple(-c for c in q)
    assert continuous(neg, q) == pytest.approx(q)
    assert continuous(q, q) == q
    assert continuous(neg, None) == neg


def test_continuity_follows_a_full_turn_without_flips():
    keep = Continuity()
    last = None
    for k in range(721):
        q = quat_from_matrix(axis_angle_matrix((0, 1, 0), math.radians(k)))  # w >= 0: flips at 180 deg
        s = keep(PoseSample(float(k), HMD, orientation=q))
        if last is not None:
            assert sum(a * b for a, b in zip(s.orientation, last, strict=True)) > 0.99
        last = s.orientation
    assert last[3] == pytest.approx(1.0)  # 720 deg: back to +identity, continuously
    # an invalid sample is passed through untouched and does not move the reference
    bad = PoseSample(800.0, HMD, valid=False, orientation=(0.0, 0.0, 0.0, -1.0))
    assert keep(bad).orientation == (0.0, 0.0, 0.0, -1.0)


def test_yaw_pitch_roll_recovers_composed_angles():
    rng = random.Random(5)
    for _ in range(200):
        yaw, pitch, roll = rng.uniform(-3, 3), rng.uniform(-1.4, 1.4), rng.uniform(-3, 3)
        m = matmul(matmul(axis_angle_matrix((0, 0, 1), yaw), axis_angle_matrix((0, 1, 0), pitch)),
                   axis_angle_matrix((1, 0, 0), roll))
        assert yaw_pitch_roll(quat_from_matrix(m)) == pytest.approx((yaw, pitch, roll), abs=1e-9)
    # positive pitch is nose down: the body x axis tips below the horizon
    q = axis_angle_quat((0, 1, 0), 0.3)
    assert yaw_pitch_roll(q)[1] == pytest.approx(0.3)
    assert apply(matrix_from_quat(q), (1, 0, 0))[2] < 0
