"""The pose sources of `ttctl hmd dump`: the synthetic user, and the OpenVR source against a fake
of the openvr module (tests/fake_openvr.py) and against the real module without SteamVR."""

from __future__ import annotations

import itertools
import math
import re
import sys
import time
from collections import defaultdict

import pytest

from fake_openvr import FakeDevice, FakeOpenVR, FakeSystem
from ttctl.errors import Fail
from ttctl.hmd.frames import matrix_from_quat
from ttctl.hmd.model import ControllerSample, PoseSample
from ttctl.hmd.sources import Source
from ttctl.hmd.sources.openvr_source import OpenVRSource, pulse
from ttctl.hmd.sources.synthetic import SyntheticSource, look_at, rotation

T0 = 1_700_000_000.0


def run(seed: int = 0, duration: float = 10.0, **kw) -> list:
    return list(SyntheticSource(seed=seed, duration=duration, t0=T0, **kw).samples())


@pytest.fixture(scope="module")
def long_run() -> list:
    """60 s of a synthetic user, shared by the statistical checks."""
    return run(seed=0, duration=60.0)


def poses(samples, frame: str) -> list[PoseSample]:
    return [s for s in samples if isinstance(s, PoseSample) and s.device.frame == frame]


def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


# -- the synthetic source -------------------------------------------------------------------------

def test_synthetic_is_a_source():
    src: Source = SyntheticSource(duration=0.1, t0=T0)
    assert src.frame == "openvr" and src.paced is False
    list(src.samples())
    src.close()
    assert src.counts["hmd"] == 9


def test_synthetic_is_deterministic_per_seed():
    a, b, c = run(1, 5.0), run(1, 5.0), run(2, 5.0)
    assert a == b
    assert a != c
    assert [s.position for s in poses(a, "hmd")] != [s.position for s in poses(c, "hmd")]


def test_synthetic_t0_shifts_time_only():
    a = run(3, 2.0)
    b = list(SyntheticSource(seed=3, duration=2.0, t0=T0 + 100).samples())
    assert [s.t + 100 for s in a] == pytest.approx([s.t for s in b])
    assert [getattr(s, "position", None) for s in a] == [getattr(s, "position", None) for s in b]


@pytest.mark.parametrize(("rate_hmd", "rate_c", "duration"),
                         [(90, 250, 2.0), (60, 120, 1.3), (144, 500, 0.77), (30.5, 77.7, 3.1), (90, 250, 1 / 3)])
def test_synthetic_counts_are_rate_times_duration(rate_hmd, rate_c, duration):
    src = SyntheticSource(rate_hmd=rate_hmd, rate_controllers=rate_c, duration=duration, t0=T0)
    samples = list(src.samples())
    assert abs(len(poses(samples, "hmd")) - rate_hmd * duration) <= 1
    for frame in ("controller_left", "controller_right"):
        assert abs(len(poses(samples, frame)) - rate_c * duration) <= 1
        n = sum(1 for s in samples if s.device.frame == frame)
        assert src.counts[frame] == n
    assert src.counts["hmd"] == len(poses(samples, "hmd"))
    assert all(s.t - T0 < duration for s in samples)
    # base stations: at the start and once a second
    assert len(poses(samples, "base_station_LHB_2A41C7E0")) == math.ceil(duration)


def test_synthetic_samples_are_in_time_order_on_exact_grids(long_run):
    ts = [s.t for s in long_run]
    assert ts == sorted(ts)
    hmd = poses(long_run, "hmd")
    assert [s.t for s in hmd] == [T0 + n * (1 / 90) for n in range(len(hmd))]


def test_synthetic_devices(long_run):
    frames = {s.device.frame: s.device for s in long_run}
    assert set(frames) == {"hmd", "controller_left", "controller_right", "base_station_LHB_2A41C7E0",
                           "base_station_LHB_7D93B15F"}
    assert frames["hmd"].index == 0 and frames["controller_left"].index == 3 and frames["controller_right"].index == 4
    assert all(d.serial for d in frames.values())
    assert all(s.valid and s.connected for s in long_run if isinstance(s, PoseSample))


def test_synthetic_quaternions_are_unit_and_sign_continuous(long_run):
    last = {}
    for s in long_run:
        if isinstance(s, PoseSample):
            assert math.isclose(math.sqrt(sum(c * c for c in s.orientation)), 1.0, abs_tol=1e-12)
            if s.device.index in last:
                assert sum(a * b for a, b in zip(s.orientation, last[s.device.index], strict=True)) > 0.9
            last[s.device.index] = s.orientation


def test_synthetic_head_is_a_standing_user(long_run):
    hmd = poses(long_run, "hmd")
    assert all(1.55 < s.position[1] < 1.8 for s in hmd)
    assert all(abs(s.position[0]) < 0.5 and abs(s.position[2]) < 0.5 for s in hmd)
    assert hmd[0].position[1] == pytest.approx(1.7)
    # hands stay within reach of the head, also when the body turns round
    head = {round(s.t - T0, 6): s.position for s in hmd}
    for frame in ("controller_left", "controller_right"):
        near = [math.dist(head[k], s.position) for s in poses(long_run, frame) if (k := round(s.t - T0, 6)) in head]
        assert len(near) > 100 and max(near) < 1.2


def test_synthetic_user_turns_round(long_run):
    """Room-scale users turn their whole body: the headset's quaternion must cross w = 0 (a
    source that rebuilt w >= 0 at every sample would flip sign there)."""
    hmd = poses(long_run, "hmd")
    assert any(s.orientation[3] < 0 for s in hmd)


def test_synthetic_velocities_match_finite_differences(long_run):
    """Central differences of positions and orientations against the reported velocities:
    the error of a central difference is O(dt^2), far below a missing or wrong-signed term."""
    for frame in ("hmd", "controller_left", "controller_right"):
        seq = poses(long_run, frame)
        worst_v = worst_w = 0.0
        for a, b, c in zip(seq, seq[1:], seq[2:], strict=False):
            dt = c.t - a.t
            v = [(c.position[i] - a.position[i]) / dt for i in range(3)]
            worst_v = max(worst_v, math.dist(v, b.velocity))
            # world angular velocity: q_c * conj(q_a) is a rotation of |w| dt about w
            ax, ay, az, aw = a.orientation
            x, y, z, w = qmul(c.orientation, (-ax, -ay, -az, aw))
            angle = 2 * math.atan2(math.sqrt(x * x + y * y + z * z), w)
            n = math.sqrt(x * x + y * y + z * z) or 1.0
            omega = [angle / dt * x / n, angle / dt * y / n, angle / dt * z / n]
            worst_w = max(worst_w, math.dist(omega, b.angular_velocity))
        assert worst_v < 0.02, frame  # m/s
        assert worst_w < 0.1, frame  # rad/s
        assert max(math.dist((0, 0, 0), s.velocity) for s in seq) > 0.1  # it does move


def test_synthetic_head_yaw_speeds_are_realistic(long_run):
    """Peak head yaw speeds of ordinary VR use: tens to a few hundred deg/s, never the ~780 deg/s
    of vigorous shaking (Grossman et al. 1988)."""
    yaw_rates = [abs(math.degrees(s.angular_velocity[1])) for s in poses(long_run, "hmd")]
    assert 100 < max(yaw_rates) < 500
    turning = [r for r in yaw_rates if r > 5]
    assert 0.1 < len(turning) / len(yaw_rates) < 0.8  # turns and pauses
    hands = [math.dist((0, 0, 0), s.velocity) for s in poses(long_run, "controller_right")]
    assert 0.3 < max(hands) < 2.5


def test_synthetic_buttons(long_run):
    states = [s for s in long_run if isinstance(s, ControllerSample)]
    for name in ("trigger_click", "pad_touched", "pad_pressed", "menu", "grip"):
        assert any(s.buttons[name] for s in states), name
    assert any(0 < s.trigger < 1 for s in states)
    for s in states:
        assert s.buttons["trigger_click"] == (s.trigger == 1.0)
        assert 0.0 <= s.trigger <= 1.0 and s.pad_x ** 2 + s.pad_y ** 2 <= 1.0
        if s.buttons["pad_pressed"]:
            assert s.buttons["pad_touched"]
        if not s.buttons["pad_touched"]:
            assert s.pad_x == s.pad_y == 0.0
    by_device = defaultdict(list)
    for s in states:
        by_device[s.device.frame].append(s)
    assert set(by_device) == {"controller_left", "controller_right"}
    for seq in by_device.values():
        assert [s.packet for s in seq] == list(range(1, len(seq) + 1))
        assert all((a.trigger, a.pad_x, a.pad_y, a.buttons) != (b.trigger, b.pad_x, b.pad_y, b.buttons)
                   for a, b in itertools.pairwise(seq))  # a packet only when something changed


def test_synthetic_base_stations_look_down_at_the_play_area(long_run):
    for frame in ("base_station_LHB_2A41C7E0", "base_station_LHB_7D93B15F"):
        seq = poses(long_run, frame)
        assert [s.t - T0 for s in seq] == [float(k) for k in range(60)]
        assert all(s.position == seq[0].position and s.orientation == seq[0].orientation for s in seq)
        assert seq[0].position[1] == pytest.approx(2.0)
        forward = [-matrix_from_quat(seq[0].orientation)[i][2] for i in range(3)]  # body -z
        to_centre = [-c for c in seq[0].position]
        assert forward[1] < 0 and forward[0] * to_centre[0] > 0 and forward[2] * to_centre[2] > 0


def test_rotation_and_look_at_are_proper_rotations():
    for r in (rotation(0.3, -0.2, 0.1), look_at((1.5, 2.0, 1.5), (0.0, 1.0, 0.0))):
        rt_r = [[sum(r[k][i] * r[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
        assert [c for row in rt_r for c in row] == pytest.approx([1, 0, 0, 0, 1, 0, 0, 0, 1], abs=1e-12)
    assert [rotation(math.pi / 2, 0, 0)[i][2] for i in range(3)] == pytest.approx([1, 0, 0])  # -z -> -x: left


def test_synthetic_dropouts():
    samples = run(4, 20.0, dropouts=True)
    assert all(s.valid for s in poses(samples, "hmd"))
    for frame in ("controller_left", "controller_right"):
        seq = poses(samples, frame)
        lost = [s for s in seq if not s.valid]
        assert lost, frame
        runs, current = [], 0
        for s in seq:
            if not s.valid:
                current += 1
            elif current:
                runs.append(current)
                current = 0
        assert max(runs) / 250 <= 0.41  # brief losses
        assert all(s.velocity == (0.0, 0.0, 0.0) for s in lost)
    assert all(s.valid for s in run(4, 20.0) if isinstance(s, PoseSample))


def test_synthetic_rejects_bad_rates():
    with pytest.raises(Fail, match="rate_hmd"):
        SyntheticSource(rate_hmd=0)
    with pytest.raises(Fail, match="duration"):
        SyntheticSource(duration=-1)


# -- the OpenVR source, against a fake module -------------------------------------------------------

Q90Y = (0.0, math.sqrt(0.5), 0.0, math.sqrt(0.5))  # 90 deg about +y


def fake_rig(**kw) -> FakeOpenVR:
    """An HMD, two base stations and two controllers, like a Vive set-up."""
    vr = FakeOpenVR(**kw)
    m = [row[:3] for row in matrix_from_quat(Q90Y)]
    hmd = FakeDevice(1, serial="LHR-HMD", velocity=(0.1, 0.0, -0.2), angular_velocity=(0.0, 1.5, 0.0),
                     matrix=[[*m[0], 0.1], [*m[1], 1.7], [*m[2], -0.2]])
    vr.system.devices = {0: hmd, 1: FakeDevice(4, serial="LHB-1"), 2: FakeDevice(4, serial="LHB-2"),
                         3: FakeDevice(2, 1, "LHR-L"), 4: FakeDevice(2, 2, "LHR-R")}
    return vr


def take(src: OpenVRSource, system: FakeSystem, polls: int) -> list:
    """Samples until the fake has been polled `polls` times (independent of timing)."""
    out = []
    for s in src.samples():
        if system.polls > polls:
            break
        out.append(s)
    return out


def test_openvr_poses_and_flags():
    vr = fake_rig()
    vr.system.devices[4].valid = False
    vr.system.devices[4].matrix[1][3] = 0.9
    src = OpenVRSource(rate_hmd=1000, rate_controllers=1000, module=vr)
    assert src.frame == "openvr" and src.paced is True and vr.inits == [3]
    samples = take(src, vr.system, 5)
    src.close()
    src.close()
    assert vr.shutdowns == 1
    hmd = poses(samples, "hmd")
    assert len(hmd) == 5
    h = hmd[0]
    assert h.position == pytest.approx((0.1, 1.7, -0.2)) and h.orientation == pytest.approx(Q90Y)
    assert h.velocity == pytest.approx((0.1, 0.0, -0.2)) and h.angular_velocity == pytest.approx((0.0, 1.5, 0.0))
    assert h.valid and h.connected and h.device.serial == "LHR-HMD" and h.device.index == 0
    right = poses(samples, "controller_right")
    assert len(right) == 5 and all(not s.valid and s.connected for s in right)  # flagged, still yielded
    assert right[0].position[1] == pytest.approx(0.9)
    assert len(poses(samples, "controller_left")) == 5
    assert len(poses(samples, "base_station_LHB_1")) == 1  # fixed: once a second
    assert vr.system.origins == [1] * len(vr.system.origins)  # TrackingUniverseStanding
    assert all(a is vr.system.arrays[0] for a in vr.system.arrays)  # one preallocated array
    assert len(vr.system.arrays[0]) == 64
    assert src.counts["hmd"] == 6  # the 6th poll's hmd sample was yielded too (take() dropped it)


def test_openvr_rates_and_duration():
    vr = fake_rig()
    started = time.monotonic()
    src = OpenVRSource(rate_hmd=100, rate_controllers=200, duration=0.25, module=vr)
    samples = list(src.samples())
    assert time.monotonic() - started >= 0.24  # paced: it sleeps to the ticks
    # ticks missed (a GC pause, a slow machine) are skipped, never caught up in a burst: at most rate x duration
    hmd, left = len(poses(samples, "hmd")), len(poses(samples, "controller_left"))
    assert 15 <= hmd <= 25 + 1 and 30 <= left <= 50 + 1
    assert abs(left - 2 * hmd) <= 0.2 * left
    assert [s.t for s in samples] == sorted(s.t for s in samples)


def test_openvr_follows_late_connect_disconnect_and_role_swap():
    vr = fake_rig()
    script = vr.system.script
    script[3] = lambda s: s.activate(5, FakeDevice(3, serial="LHR-TRK"))  # a tracker switched on late
    script[6] = lambda s: s.deactivate(3)  # the left controller switched off
    script[9] = lambda s: (s.set_role(4, 1), s.devices.update({6: FakeDevice(2, 2, "LHR-NEW")}),
                           s.activate(6, s.devices[6]))  # the right one becomes left, a new right one
    src = OpenVRSource(rate_hmd=1000, rate_controllers=1000, module=vr)
    samples = take(src, vr.system, 12)
    by_poll = [s.t for s in poses(samples, "hmd")]
    tracker = poses(samples, "tracker_LHR_TRK")
    assert tracker and tracker[0].t >= by_poll[2] and len(tracker) == 12 - 3  # seen from poll 4 on
    gone = [s for s in samples if isinstance(s, PoseSample) and s.device.index == 3 and s.t >= by_poll[5]]
    assert len(gone) == 1 and not gone[0].connected and gone[0].device.frame == "controller_left"
    index4 = [s for s in samples if isinstance(s, PoseSample) and s.device.index == 4]
    assert [s.device.frame for s in index4] == ["controller_right"] * 9 + ["controller_left"] * 3
    new = [s for s in samples if isinstance(s, PoseSample) and s.device.index == 6]
    assert [s.device.frame for s in new] == ["controller_right"] * 3
    assert src.devices[6].serial == "LHR-NEW" and src.devices[3].kind == "controller"
    src.close()


def test_openvr_controller_states():
    vr = fake_rig()
    left = vr.system.devices[3]
    left.packet = 7

    def touch(s):  # thumb on the pad: touched, not pressed
        left.packet, left.touched, left.axes = 8, 1 << 32, [(0.25, -0.5), (0.0, 0.0)] + [(0.0, 0.0)] * 3

    def press(s):  # pad pressed, menu and grip; trigger fully pulled
        left.packet, left.pressed = 9, (1 << 32) | (1 << 1) | (1 << 2)
        left.axes = [(0.25, -0.5), (1.0, 0.0)] + [(0.0, 0.0)] * 3

    def same_packet(s):  # the bits change but the packet does not: nothing is emitted
        left.pressed = 0

    def click(s):  # the trigger's click bit at 0.9
        left.packet, left.pressed, left.touched, left.axes = 10, 1 << 33, 0, [(0.0, 0.0), (0.9, 0.0)] + [(0, 0)] * 3

    vr.system.script.update({3: touch, 5: press, 6: same_packet, 8: click})
    src = OpenVRSource(rate_hmd=1000, rate_controllers=1000, module=vr)
    samples = take(src, vr.system, 10)
    src.close()
    states = [s for s in samples if isinstance(s, ControllerSample) and s.device.frame == "controller_left"]
    assert [s.packet for s in states] == [7, 8, 9, 10]
    first, touched, pressed, clicked = states
    assert first.button_list == [0, 0, 0, 0, 0] and first.trigger == 0.0
    assert touched.buttons["pad_touched"] and not touched.buttons["pad_pressed"]
    assert (touched.pad_x, touched.pad_y) == (0.25, -0.5) and touched.trigger == 0.0
    assert pressed.button_list == [1, 1, 1, 1, 1] and pressed.trigger == 1.0
    assert clicked.buttons["trigger_click"] and clicked.trigger == pytest.approx(0.9)
    assert not clicked.buttons["pad_touched"] and not clicked.buttons["menu"]
    assert [s.packet for s in samples if isinstance(s, ControllerSample) and s.device.index == 4] == [1]


def test_openvr_controller_back_from_off_reports_its_state_again():
    """Switched off and on, a controller may come back with the packet number it had: its
    inputs are reported afresh (and its pose resumes) rather than waiting for the next change."""
    vr = fake_rig()

    def back_on(s):
        s.devices[3].connected = s.devices[3].valid = True
        s.activate(3, s.devices[3])

    vr.system.script.update({3: lambda s: s.deactivate(3), 7: back_on})
    src = OpenVRSource(rate_hmd=1000, rate_controllers=1000, module=vr)
    samples = take(src, vr.system, 10)
    src.close()
    left = [s for s in samples if s.device.index == 3]
    kinds = [("state" if isinstance(s, ControllerSample) else "pose" if s.connected else "off") for s in left]
    # polls 1-2 on, 3 off (reported once), 4-6 silent, 7 on again: its state afresh, once
    assert kinds == ["pose", "state", "pose", "off", "pose", "state", "pose", "pose", "pose"]


@pytest.mark.parametrize(("code", "words"),
                         [(110, "SteamVR installed"), (108, "headset"), (121, "SteamVR is not running")])
def test_openvr_init_errors_are_one_line(code, words):
    vr = FakeOpenVR(installed=int(code != 110), init_error=code)
    with pytest.raises(Fail) as e:
        OpenVRSource(module=vr)
    msg = str(e.value)
    assert "\n" not in msg and msg.startswith("OpenVR could not start: ")
    assert re.search(rf"\b{code}\b", msg) and words in msg and msg.endswith("try --source synthetic")
    assert f"({code})" not in msg  # OpenVR's description's own "(110)" is not repeated
    assert vr.inits == [3]  # background application: never starts SteamVR


def test_openvr_init_error_without_a_description_function():
    vr = FakeOpenVR(init_error=121, describe=False)
    with pytest.raises(Fail, match=r"OpenVR could not start: 121 no server for background app .*--source synthetic"):
        OpenVRSource(module=vr)


def test_openvr_missing_module(monkeypatch):
    monkeypatch.setitem(sys.modules, "openvr", None)  # import openvr -> ImportError
    with pytest.raises(Fail, match=r"pip install 'ttctl\[vr\]'"):
        OpenVRSource()


def test_pulse_clamps_and_pulses():
    vr = fake_rig()
    assert pulse("right", 5000, module=vr)[0] == 3999
    assert "clamped" in (pulse("left", -5, module=vr)[1] or "")
    assert pulse("left", 1000, module=vr) == (1000, None)
    assert vr.system.pulses == [(4, 0, 3999), (3, 0, 0), (3, 0, 1000)]
    assert vr.shutdowns == 3 and vr.inits == [3, 3, 3]


def test_pulse_without_that_controller():
    vr = fake_rig()
    del vr.system.devices[4]
    with pytest.raises(Fail, match="no right controller is connected"):
        pulse("right", 1000, module=vr)
    vr.system.devices[3].connected = False
    with pytest.raises(Fail, match="no left controller is connected"):
        pulse("left", 1000, module=vr)
    assert vr.system.pulses == [] and vr.shutdowns == 2
    with pytest.raises(Fail, match="left or right"):
        pulse("both", 1000, module=vr)
    with pytest.raises(Fail, match=r"OpenVR could not start: 108 ") as e:
        pulse("left", 1000, module=FakeOpenVR(init_error=108))
    assert "--source" not in str(e.value)  # `hmd pulse` has no --source to advise


# -- the OpenVR source, against the real module (no SteamVR here) ---------------------------------------

def test_real_openvr_without_steamvr_fails_with_its_code(capfd):
    openvr = pytest.importorskip("openvr")
    try:
        src = OpenVRSource(duration=0.0)
    except Fail as e:
        msg = str(e)
        assert "\n" not in msg and re.search(r"OpenVR could not start: \d{3} ", msg), msg
        assert msg.endswith("try --source synthetic")
        # libopenvr_api's own stderr lines ("Unable to read VR Path Registry ...") are kept out
        assert "VR Path Registry" not in capfd.readouterr().err
        return
    src.close()
    pytest.skip(f"the real openvr initialised here (runtime installed: {openvr.isRuntimeInstalled()})")
