"""Frame maths: rotation matrix to quaternion, OpenVR to ROS REP-103, sign continuity.

OpenVR's tracking space is right-handed with +y up and -z forward (metres); a device's body
axes follow the same convention. ROS REP-103 is x forward, y left, z up. The change of axes is
the rotation C = [[0,0,-1],[-1,0,0],[0,1,0]] (det +1): a vector becomes C v = (-z, -x, y), an
orientation C R C^T, which for a quaternion keeps w and maps the vector part like a vector:
(x, y, z, w) -> (-z, -x, y, w). Converting both world and body axes is what makes "x forward"
true of the headset's own frame too.

Quaternions come from matrices by Shepperd's method: pick the largest of w, x, y, z from the
matrix's diagonal and derive the others from it, so the division is never by a small number
(the trace-only formula fails near 180-degree rotations, where w -> 0).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from .model import ControllerSample, PoseSample, Quat, Sample, Vec3

Matrix = Sequence[Sequence[float]]  # 3x3, or 3x4 (OpenVR's HmdMatrix34_t: rotation | translation)


def quat_from_matrix(m: Matrix) -> Quat:
    """The unit quaternion (x, y, z, w) of the rotation in m's first three columns, w >= 0.
    Exact near 180 degrees (Shepperd); a matrix that is not quite orthonormal gives the
    nearest-looking quaternion, normalised."""
    m00, m01, m02 = m[0][0], m[0][1], m[0][2]
    m10, m11, m12 = m[1][0], m[1][1], m[1][2]
    m20, m21, m22 = m[2][0], m[2][1], m[2][2]
    trace = m00 + m11 + m22
    if trace >= m00 and trace >= m11 and trace >= m22:
        s = math.sqrt(max(1.0 + trace, 0.0)) * 2.0  # 4w
        w, x, y, z = 0.25 * s, (m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s
    elif m00 >= m11 and m00 >= m22:
        s = math.sqrt(max(1.0 + m00 - m11 - m22, 0.0)) * 2.0  # 4x
        w, x, y, z = (m21 - m12) / s, 0.25 * s, (m01 + m10) / s, (m02 + m20) / s
    elif m11 >= m22:
        s = math.sqrt(max(1.0 + m11 - m00 - m22, 0.0)) * 2.0  # 4y
        w, x, y, z = (m02 - m20) / s, (m01 + m10) / s, 0.25 * s, (m12 + m21) / s
    else:
        s = math.sqrt(max(1.0 + m22 - m00 - m11, 0.0)) * 2.0  # 4z
        w, x, y, z = (m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25 * s
    if w < 0:
        w, x, y, z = -w, -x, -y, -z
    return normalise((x, y, z, w))


def matrix_from_quat(q: Quat) -> list[list[float]]:
    """The 3x3 rotation matrix of a (not necessarily unit) quaternion (x, y, z, w)."""
    x, y, z, w = normalise(q)
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ]


def normalise(q: Quat) -> Quat:
    """q / |q|; the identity for a zero (or non-finite) quaternion."""
    n = math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3])
    if not n > 0 or not math.isfinite(n):
        return (0.0, 0.0, 0.0, 1.0)
    return (q[0] / n, q[1] / n, q[2] / n, q[3] / n)


def continuous(q: Quat, previous: Quat | None) -> Quat:
    """q or -q (the same rotation), whichever is nearer `previous`: no sign flips between samples."""
    if previous is not None and q[0] * previous[0] + q[1] * previous[1] + q[2] * previous[2] + q[3] * previous[3] < 0:
        return (-q[0], -q[1], -q[2], -q[3])
    return q


def vec_to_ros(v: Vec3) -> Vec3:
    """An OpenVR vector in REP-103 axes: (-z, -x, y)."""
    return (-v[2], -v[0], v[1])


def vec_to_openvr(v: Vec3) -> Vec3:
    """A REP-103 vector in OpenVR axes: the inverse of vec_to_ros."""
    return (-v[1], v[2], -v[0])


def quat_to_ros(q: Quat) -> Quat:
    """C R C^T as a quaternion: w kept, the vector part mapped like a vector."""
    x, y, z = vec_to_ros((q[0], q[1], q[2]))
    return (x, y, z, q[3])


def quat_to_openvr(q: Quat) -> Quat:
    x, y, z = vec_to_openvr((q[0], q[1], q[2]))
    return (x, y, z, q[3])


def pose_to_ros(s: PoseSample) -> PoseSample:
    """The same pose with world and body axes in REP-103."""
    return PoseSample(s.t, s.device, s.valid, s.connected, vec_to_ros(s.position), quat_to_ros(s.orientation),
                      vec_to_ros(s.velocity), vec_to_ros(s.angular_velocity))


def pose_to_openvr(s: PoseSample) -> PoseSample:
    return PoseSample(s.t, s.device, s.valid, s.connected, vec_to_openvr(s.position), quat_to_openvr(s.orientation),
                      vec_to_openvr(s.velocity), vec_to_openvr(s.angular_velocity))


def convert(s: Sample, src: str, dst: str) -> Sample:
    """A sample recorded in frame `src` ("ros" / "openvr") expressed in `dst`."""
    if src == dst or isinstance(s, ControllerSample):
        return s
    return pose_to_ros(s) if dst == "ros" else pose_to_openvr(s)


class Continuity:
    """Keeps each device's quaternions sign-continuous from sample to sample (and unit)."""

    def __init__(self) -> None:
        self._last: dict[int, Quat] = {}

    def __call__(self, s: Sample) -> Sample:
        if isinstance(s, PoseSample) and s.valid:
            q = continuous(normalise(s.orientation), self._last.get(s.device.index))
            self._last[s.device.index] = q
            s.orientation = q
        return s


def yaw_pitch_roll(q: Quat) -> tuple[float, float, float]:
    """REP-103 Z-Y-X Euler angles (yaw about z, then pitch about y, then roll about x), radians.
    Pitch is positive nose *down* in REP-103 (right-handed about y, which points left)."""
    x, y, z, w = normalise(q)
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x))))
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    return yaw, pitch, roll
