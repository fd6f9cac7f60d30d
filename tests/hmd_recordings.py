"""Shared fixtures of the recording tests: a hand-made sample stream covering every case (invalid
and disconnected poses, role changes, button packets, moved base stations), what the ROS formats keep
of it, and a field-by-field comparison."""

from __future__ import annotations

import math
import random
from pathlib import Path

import numpy as np
import pytest

from ttctl.hmd.formats import check_output, format_for, open_writer
from ttctl.hmd.model import BUTTONS, ControllerSample, Device, PoseSample, Sample

T0 = 1_767_225_600.25  # 2026-01-01: epoch-sized times, where float seconds are coarsest
HMD = Device(0, "hmd", "none", "LHR-HMD0001")
LEFT = Device(1, "controller", "left", "LHR-C0001")
RIGHT_UNASSIGNED = Device(2, "controller", "none", "LHR-C0002")
RIGHT = Device(2, "controller", "right", "LHR-C0002")
BS = (Device(3, "base_station", "none", "LHB-1234ABCD"), Device(4, "base_station", "none", "LHB-5678EF01"))
MD5 = {"geometry_msgs/msg/PoseStamped": "d3812c3cbc69362b77dc0b19b345f8f5",
       "tf2_msgs/msg/TFMessage": "94810edda583a504dfda3829e70d7eec",
       "sensor_msgs/msg/Joy": "5a9ea5f83505693b71e785041e67a8bb",
       "geometry_msgs/msg/TwistStamped": "98d34b0043a2093cf9d9345ab6eef12e",
       "std_msgs/msg/String": "992ce8a1687cec8c8bd883ec73ca41d1"}
CSV_COLUMNS = ["t", "type", "frame", "parent", "child", "device", "index", "role", "serial", "valid", "connected",
               "px", "py", "pz", "qx", "qy", "qz", "qw", "vx", "vy", "vz", "wx", "wy", "wz",
               "packet", "trigger", "pad_x", "pad_y", "trigger_click", "pad_touched", "pad_pressed", "menu", "grip"]


def _quat(rng: random.Random) -> tuple[float, float, float, float]:
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(x * x for x in q))
    return (q[0] / n, q[1] / n, q[2] / n, q[3] / n)


def make_samples(seconds: float = 1.2) -> list[Sample]:
    """An hmd at 90 Hz, two controllers at 250 Hz with button changes (the right one without a
    hand at first, and disconnected for a while), the left one invalid for a stretch (garbage
    numbers), two base stations (one moved once): in time order."""
    rng = random.Random(7)
    out: list[tuple[float, int, Sample]] = []
    for k in range(int(seconds * 90)):
        t = T0 + k / 90
        position = (0.1 * math.sin(k / 20), 0.02 * k / 90, 1.6 + rng.gauss(0, 0.01))
        out.append((t, 0, PoseSample(t, HMD, True, True, position, _quat(rng),
                                     (rng.gauss(0, 0.3), rng.gauss(0, 0.3), 0.0), (0.0, 0.0, rng.gauss(0, 2.0)))))
    packets = {1: 100, 2: 500}
    for k in range(int(seconds * 250)):
        t = T0 + 0.0013 + k / 250
        for dev in (LEFT, RIGHT_UNASSIGNED if k < 40 else RIGHT):
            valid = not (dev.index == 1 and 80 <= k < 130) and not (dev.index == 2 and 200 <= k < 220)
            connected = not (dev.index == 2 and 200 <= k < 220)
            pos = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.5, 2)) if valid else (1e9, -7.5, 0.0)
            out.append((t, dev.index, PoseSample(t, dev, valid, connected, pos, _quat(rng),
                                                 (rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1)),
                                                 (rng.gauss(0, 3), rng.gauss(0, 3), rng.gauss(0, 3)))))
            if k % 7 == dev.index:  # the state changed: a new packet
                packets[dev.index] += 1
                buttons = {b: bool((k // 7 + i + dev.index) % 3 == 0) for i, b in enumerate(BUTTONS)}
                out.append((t + 0.0002, dev.index, ControllerSample(
                    t + 0.0002, dev, packets[dev.index], rng.random(), rng.uniform(-1, 1), rng.uniform(-1, 1),
                    buttons)))
        if k % 25 == 0:
            for i, bs in enumerate(BS):
                moved = 0.5 if (i == 1 and k >= 150) else 0.0
                out.append((t, bs.index, PoseSample(t, bs, True, True, (2.0 - 4 * i, 2.0 + moved, 2.5),
                                                    (0.0, 0.0, 0.7071067811865476, 0.7071067811865476))))
    out.sort(key=lambda x: (x[0], x[1]))
    return [s for _, _, s in out]


def ros_view(samples: list[Sample]) -> list[Sample]:
    """What the ROS formats keep: every valid pose and controller input (axes float32); of the
    invalid poses, the ones where a device's (identity, validity, connection) changes, as
    zeros (documented in ttctl.hmd.formats.ros)."""
    announced: dict[int, tuple[Device, bool | None, bool | None]] = {}
    out: list[Sample] = []
    for s in samples:
        last = announced.get(s.device.index)
        if isinstance(s, PoseSample):
            state = (s.device, s.valid, s.connected)
            if state != last:
                announced[s.device.index] = state
                if not s.valid:
                    out.append(PoseSample(s.t, s.device, False, s.connected))
            if s.valid:
                out.append(s)
        else:
            if last is None or last[0] != s.device:
                announced[s.device.index] = (s.device, None, None)
            f32 = [float(np.float32(v)) for v in (s.trigger, s.pad_x, s.pad_y)]
            out.append(ControllerSample(s.t, s.device, s.packet, f32[0], f32[1], f32[2], dict(s.buttons)))
    return out


def assert_same(got: list[Sample], want: list[Sample], tol: float = 1e-9) -> None:
    assert len(got) == len(want)
    for i, (g, w) in enumerate(zip(got, want, strict=True)):
        assert type(g) is type(w) and g.device == w.device, (i, g, w)
        assert abs(g.t - w.t) <= 1e-9, (i, g.t, w.t)
        if isinstance(g, PoseSample) and isinstance(w, PoseSample):
            assert (g.valid, g.connected) == (w.valid, w.connected), (i, g, w)
            for a, b in zip((*g.position, *g.orientation, *g.velocity, *g.angular_velocity),
                            (*w.position, *w.orientation, *w.velocity, *w.angular_velocity), strict=True):
                assert abs(a - b) <= tol, (i, g, w)
        elif isinstance(g, ControllerSample) and isinstance(w, ControllerSample):
            assert g.packet == w.packet and g.buttons == w.buttons, (i, g, w)
            assert all(abs(a - b) <= tol for a, b in zip(g.axes, w.axes, strict=True)), (i, g, w)


@pytest.fixture(scope="module", name="samples")
def samples_fixture() -> list[Sample]:
    return make_samples()


def record(path: Path, samples: list[Sample], fmt: str | None = None, frame: str = "ros") -> dict[str, int]:
    fmt = format_for(str(path), fmt)
    check_output(str(path), fmt)
    with open_writer(str(path), fmt, frame, "vr_world", {"source": "test", "rate": 90}) as w:
        for s in samples:
            w.write(s)
    return w.counts

