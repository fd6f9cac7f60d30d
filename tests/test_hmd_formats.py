"""Recordings of VR pose streams: each format is checked by a reader that is not ours (mcap +
mcap_ros2, rosbags' bag reader with its own typestore, json, csv), then replayed and compared field
by field; writes are atomic (abort, exception, SIGKILL); damaged input is one clear Fail."""

from __future__ import annotations

import csv
import json
import math
import os
import random
import signal
import stat
import subprocess
import sys
import textwrap
import threading
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from ttctl.errors import Fail
from ttctl.hmd.formats import FORMATS, check_output, format_for, open_writer, read_recording
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


@pytest.fixture(scope="module")
def samples() -> list[Sample]:
    return make_samples()


def record(path: Path, samples: list[Sample], fmt: str | None = None, frame: str = "ros") -> dict[str, int]:
    fmt = format_for(str(path), fmt)
    check_output(str(path), fmt)
    with open_writer(str(path), fmt, frame, "vr_world", {"source": "test", "rate": 90}) as w:
        for s in samples:
            w.write(s)
    return w.counts


def test_generator_covers_the_cases(samples: list[Sample]) -> None:
    poses = [s for s in samples if isinstance(s, PoseSample)]
    assert any(not s.valid for s in poses) and any(not s.connected for s in poses)
    assert {s.device.frame for s in samples} >= {"hmd", "controller_left", "controller_right",
                                                 "controller_LHR_C0002", "base_station_LHB_1234ABCD"}
    assert len(ros_view(samples)) < len(samples)


# ------------------------------------------------------------------------------------------------ formats


@pytest.mark.parametrize("frame", ["ros", "openvr"])
def test_jsonl_is_documented_json_and_replays_exactly(tmp_path: Path, samples: list[Sample], frame: str) -> None:
    path = tmp_path / "rec.jsonl"
    assert record(path, samples, frame=frame) == {"pose": sum(isinstance(s, PoseSample) for s in samples),
                                                  "controller": sum(isinstance(s, ControllerSample) for s in samples)}
    lines = [json.loads(line) for line in path.read_text().splitlines()]
    assert lines[0] == {"type": "recording", "format": "ttctl.hmd", "version": 1, "frame": frame,
                        "parent_frame": "vr_world", "meta": {"source": "test", "rate": 90}}
    pose = next(x for x in lines if x["type"] == "pose")
    assert set(pose) == {"t", "type", "frame", "parent", "child", "device", "index", "role", "serial", "valid",
                         "connected", "position", "orientation", "velocity", "angular_velocity"}
    assert pose["frame"] == frame and pose["parent"] == "vr_world" and pose["child"] == "hmd"
    joy = next(x for x in lines if x["type"] == "controller")
    assert set(joy) == {"t", "type", "child", "device", "index", "role", "serial", "packet", "axes", "buttons"}
    assert list(joy["buttons"]) == list(BUTTONS) and len(joy["axes"]) == 3
    assert len(lines) == len(samples) + 1
    rec = read_recording(str(path))
    assert (rec.frame, rec.parent_frame, rec.meta, rec.format, rec.truncated) == (
        frame, "vr_world", {"source": "test", "rate": 90}, "jsonl", False)
    assert_same(list(rec.samples), samples, tol=0.0)


def test_csv_has_one_header_and_replays_exactly(tmp_path: Path, samples: list[Sample]) -> None:
    path = tmp_path / "rec.csv"
    record(path, samples)
    with path.open(newline="") as f:
        rows = list(csv.DictReader(f))
    with path.open() as f:
        assert next(csv.reader(f)) == CSV_COLUMNS
    assert len(rows) == len(samples)
    pose = next(r for r in rows if r["type"] == "pose")
    joy = next(r for r in rows if r["type"] == "controller")
    assert pose["packet"] == pose["grip"] == "" and joy["px"] == joy["valid"] == ""
    assert {r["frame"] for r in rows} == {"ros"} and {r["parent"] for r in rows} == {"vr_world"}
    rec = read_recording(str(path))
    assert (rec.frame, rec.parent_frame, rec.format) == ("ros", "vr_world", "csv")
    assert_same(list(rec.samples), samples, tol=0.0)


def test_jsonl_and_csv_go_to_stdout(samples: list[Sample], capsys: pytest.CaptureFixture[str]) -> None:
    for fmt in ("jsonl", "csv"):
        with open_writer(None, format_for(None, fmt), "ros", "world", {}) as w:
            for s in samples[:20]:
                w.write(s)
        out = capsys.readouterr().out
        assert out.endswith("\n") and len(out.splitlines()) == 21


def test_mcap_is_ros2_that_mcap_tools_read_and_replays(tmp_path: Path, samples: list[Sample]) -> None:
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory
    from rosbags.rosbag2.metadata import parse_qos

    path = tmp_path / "rec.mcap"
    counts = record(path, samples, frame="openvr")
    assert path.read_bytes()[:8] == b"\x89MCAP0\r\n"
    with path.open("rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        assert reader.get_header().profile == "ros2"
        summary = reader.get_summary()
        meta = {m.name: m.metadata for m in reader.iter_metadata()}
        messages = list(reader.iter_decoded_messages(log_time_order=False))
    assert meta["ttctl"]["frame"] == "openvr" and meta["ttctl"]["parent_frame"] == "vr_world"
    assert json.loads(meta["ttctl"]["meta"]) == {"source": "test", "rate": 90}
    assert summary is not None
    for channel in summary.channels.values():
        schema = summary.schemas[channel.schema_id]
        assert (channel.message_encoding, schema.encoding) == ("cdr", "ros2msg")
        qos = parse_qos(channel.metadata["offered_qos_profiles"])
        assert qos[0].durability.name == ("TRANSIENT_LOCAL" if channel.topic == "/tf_static" else "VOLATILE")
    by_topic: dict[str, list[Any]] = {}
    for msg_schema, channel, message, decoded in messages:
        assert msg_schema is not None
        by_topic.setdefault(channel.topic, []).append((msg_schema.name, message, decoded))
    assert {t: len(v) for t, v in by_topic.items()} == counts
    valid = [s for s in samples if isinstance(s, PoseSample) and s.valid]
    moving = [s for s in valid if s.device.kind != "base_station"]
    assert len(by_topic["/tf"]) == len(moving)
    assert len(by_topic["/vr/hmd/pose"]) == sum(s.device == HMD for s in valid)
    assert len(by_topic["/vr/controller_left/joy"]) == sum(isinstance(s, ControllerSample) and s.device == LEFT
                                                          for s in samples)
    assert {name for v in by_topic.values() for name, _, _ in v} == set(MD5)
    times = [m.log_time for _, _, m, _ in messages]
    assert times == sorted(times) and times[0] == round((T0 - int(T0)) * 1e9) + int(T0) * 10**9
    for _, message, pose in by_topic["/vr/hmd/pose"]:
        q = pose.pose.orientation
        assert abs(q.x**2 + q.y**2 + q.z**2 + q.w**2 - 1) < 1e-9
        assert pose.header.frame_id == "vr_world"
        assert pose.header.stamp.sec * 10**9 + pose.header.stamp.nanosec == message.log_time
    tf = [tr for _, _, m in by_topic["/tf"] for tr in m.transforms]
    assert {tr.child_frame_id for tr in tf} == {"hmd", "controller_left", "controller_right", "controller_LHR_C0002"}
    assert all(abs(tr.transform.translation.x) < 10 for tr in tf)  # no invalid garbage in the tf tree
    statics = [m for _, _, m in by_topic["/tf_static"]]
    assert len(statics) == 3  # first one, both, the moved one again: every message has all stations
    assert [len(m.transforms) for m in statics] == [1, 2, 2]
    assert all(tr.child_frame_id.startswith("base_station_") for m in statics for tr in m.transforms)
    joys = [(msg, m) for _, msg, m in by_topic["/vr/controller_left/joy"]]
    want = [s for s in samples if isinstance(s, ControllerSample) and s.device == LEFT]
    for (message, joy), s in zip(joys, want, strict=True):
        assert len(joy.axes) == 3 and abs(joy.axes[0] - s.trigger) < 1e-6 and list(joy.buttons) == s.button_list
        assert joy.header.frame_id == "controller_left" and message.sequence == s.packet
    devices = [json.loads(m.data) for _, _, m in by_topic["/vr/devices"]]
    assert {"index": 1, "kind": "controller", "role": "left", "serial": "LHR-C0001", "frame": "controller_left",
            "valid": False, "connected": True} in devices
    rec = read_recording(str(path))
    assert (rec.frame, rec.parent_frame, rec.meta, rec.format, rec.truncated) == (
        "openvr", "vr_world", {"source": "test", "rate": 90}, "mcap", False)
    assert_same(list(rec.samples), ros_view(samples))


def _noetic() -> Any:
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore

    store = get_typestore(Stores.ROS1_NOETIC)
    store.register(get_types_from_msg("geometry_msgs/TransformStamped[] transforms", "tf2_msgs/msg/TFMessage"))
    return store


def test_bag_is_ros1_that_rosbags_reads_and_replays(tmp_path: Path, samples: list[Sample]) -> None:
    from rosbags.rosbag1 import Reader

    path = tmp_path / "rec.bag"
    counts = record(path, samples)
    assert path.read_bytes()[:13] == b"#ROSBAG V2.0\n"
    store = _noetic()
    with Reader(path) as reader:
        conns = {c.topic: c for c in reader.connections}
        assert {t: c.msgcount for t, c in conns.items()} == counts
        for c in conns.values():
            assert c.digest == MD5[c.msgtype], c
            assert getattr(c.ext, "latching", None) == (1 if c.topic in ("/tf_static", "/vr/recording") else 0)
        assert conns["/tf"].msgtype == "tf2_msgs/msg/TFMessage" and conns["/tf_static"].msgcount == 3
        assert conns["/vr/hmd/pose"].msgtype == "geometry_msgs/msg/PoseStamped"
        times, joys = [], []
        for conn, ns, raw in reader.messages():
            times.append(ns)
            msg = store.deserialize_ros1(raw, conn.msgtype)
            if conn.topic == "/vr/controller_right/joy":
                joys.append(msg)
            if conn.topic == "/vr/recording":
                info = json.loads(msg.data)
                assert (info["frame"], info["parent_frame"]) == ("ros", "vr_world")
            if conn.topic == "/tf_static":
                assert all(tr.child_frame_id.startswith("base_station_") for tr in msg.transforms)
    assert times == sorted(times)
    right = [s for s in samples if isinstance(s, ControllerSample) and s.device == RIGHT]
    assert [j.header.seq for j in joys] == [s.packet for s in right]
    assert [list(j.buttons) for j in joys] == [s.button_list for s in right]
    rec = read_recording(str(path))
    assert (rec.frame, rec.parent_frame, rec.meta, rec.format) == ("ros", "vr_world", {"source": "test", "rate": 90},
                                                                   "bag")
    # samples of one instant come by device index, poses first (documented in bagfile)
    want = sorted(ros_view(samples), key=lambda s: (s.t, s.device.index, isinstance(s, ControllerSample)))
    assert_same(list(rec.samples), want)


# ------------------------------------------------------------------------------------------------ atomicity


@pytest.mark.parametrize("fmt", FORMATS)
def test_close_abort_and_exceptions_leave_whole_files_or_nothing(tmp_path: Path, samples: list[Sample],
                                                                 fmt: str) -> None:
    path = tmp_path / f"rec.{fmt}"
    w = open_writer(str(path), fmt, "ros", "world", {})
    for s in samples[:50]:
        w.write(s)
    assert [p.name for p in tmp_path.iterdir()] != ["rec." + fmt]  # still under a temporary name
    w.abort()
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(KeyboardInterrupt), open_writer(str(path), fmt, "ros", "world", {}) as w:
        for s in samples[:50]:
            w.write(s)
        raise KeyboardInterrupt
    assert list(tmp_path.iterdir()) == []
    record(path, samples[:50], fmt)
    assert [p.name for p in tmp_path.iterdir()] == [path.name]
    mask = os.umask(0)
    os.umask(mask)
    assert path.stat().st_mode & 0o777 == 0o666 & ~mask


@pytest.mark.parametrize("fmt", FORMATS)
def test_an_empty_recording_replays_as_empty(tmp_path: Path, fmt: str) -> None:
    path = tmp_path / f"rec.{fmt}"
    record(path, [], fmt, frame="openvr")
    rec = read_recording(str(path))
    assert list(rec.samples) == [] and rec.frame == ("ros" if fmt == "csv" else "openvr")  # CSV: rows carry it


@pytest.mark.parametrize("fmt", FORMATS)
def test_a_killed_writer_leaves_nothing_under_the_final_name(tmp_path: Path, fmt: str) -> None:
    path = tmp_path / f"rec.{fmt}"
    script = textwrap.dedent(f"""
        import sys, time
        from ttctl.hmd.formats import open_writer
        from ttctl.hmd.model import Device, PoseSample
        w = open_writer({str(path)!r}, {fmt!r}, "ros", "world", {{}})
        for k in range(3000):
            w.write(PoseSample(1.7e9 + k / 90, Device(0, "hmd")))
        print("ready", flush=True)
        time.sleep(60)
    """)
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    try:
        assert proc.stdout is not None and proc.stdout.readline() == "ready\n"
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=30)
    assert not path.exists()
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(f".rec.{fmt}.")]  # the leftover, hidden


def test_a_cut_mcap_replays_up_to_the_cut(tmp_path: Path, samples: list[Sample],
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    from ttctl.hmd.formats import mcapfile

    monkeypatch.setattr(mcapfile, "CHUNK_SIZE", 16 * 1024)
    path = tmp_path / "rec.mcap"
    record(path, samples)
    data = path.read_bytes()
    cut = tmp_path / "cut.mcap"
    cut.write_bytes(data[: len(data) * 2 // 3])
    rec = read_recording(str(cut))
    assert rec.truncated
    got = list(rec.samples)
    want = ros_view(samples)
    assert 0 < len(got) < len(want)
    assert_same(got, want[: len(got)])


# ------------------------------------------------------------------------------------------------ bad input


def _fails(path: Path, *words: str) -> str:
    with pytest.raises(Fail) as e:
        rec = read_recording(str(path))
        list(rec.samples)
    text = str(e.value)
    assert e.value.code == 2 and "\n" not in text and str(path) in text, text
    assert all(w in text for w in words), text
    return text


PNG = b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\x00\x00\x00\x01\x00\x00\x00\x01\x08\x06\x00\x00\x00\x1f\x15\xc4\x89"


@pytest.mark.parametrize("ext", [".jsonl", ".csv", ".mcap", ".bag", ".dat"])
def test_empty_and_foreign_files_fail_in_one_line(tmp_path: Path, ext: str) -> None:
    empty = tmp_path / f"empty{ext}"
    empty.write_bytes(b"")
    _fails(empty, "empty")
    png = tmp_path / f"image{ext}"
    png.write_bytes(PNG)
    _fails(png, "not")


def test_bad_text_recordings_fail_naming_the_line(tmp_path: Path, samples: list[Sample]) -> None:
    path = tmp_path / "rec.jsonl"
    record(path, samples[:5])
    lines = path.read_text().splitlines()
    bad = tmp_path / "bad.jsonl"
    bad.write_text("\n".join([*lines[:3], "[1, 2]", *lines[3:]]) + "\n")
    _fails(bad, "line 4", "not an object")
    bad.write_text("\n".join([*lines[:3], '{"t": 1, "type": "pose"}']) + "\n")
    _fails(bad, "line 4", "missing")
    bad.write_text("\n".join([*lines[:3], "{nope"]) + "\n")
    _fails(bad, "line 4", "not JSON")
    wrong = tmp_path / "wrong.csv"
    wrong.write_text("time,x,y,z\n1,2,3,4\n")
    _fails(wrong, "header")
    good = tmp_path / "rec.csv"
    record(good, samples[:5])
    rows = good.read_text().splitlines()
    wrong.write_text("\n".join([*rows[:3], rows[3].replace(",pose,", ",banana,")]) + "\n")
    _fails(wrong, "line 4", "banana")


def test_cut_text_recordings_drop_the_partial_line(tmp_path: Path, samples: list[Sample]) -> None:
    for ext in ("jsonl", "csv"):
        path = tmp_path / f"rec.{ext}"
        record(path, samples[:30])
        data = path.read_bytes()
        path.write_bytes(data[:-25])
        rec = read_recording(str(path))
        assert rec.truncated
        assert_same(list(rec.samples), samples[:29], tol=0.0)


def test_a_cut_or_damaged_bag_fails_in_one_line(tmp_path: Path, samples: list[Sample]) -> None:
    path = tmp_path / "rec.bag"
    record(path, samples[:200])
    data = path.read_bytes()
    cut = tmp_path / "cut.bag"
    cut.write_bytes(data[: len(data) // 2])
    _fails(cut, "bag")


@pytest.mark.parametrize("fmt", FORMATS)
def test_random_damage_is_a_fail_or_a_recording_never_a_traceback(tmp_path: Path, samples: list[Sample],
                                                                  fmt: str) -> None:
    path = tmp_path / f"rec.{fmt}"
    record(path, samples[:300])
    data = path.read_bytes()
    rng = random.Random(fmt)
    bad = tmp_path / f"bad.{fmt}"
    for k in range(40):
        mutated = bytearray(data)
        if k % 2:
            del mutated[rng.randrange(len(data)):]
        else:
            for _ in range(rng.randint(1, 8)):
                mutated[rng.randrange(len(data))] = rng.randrange(256)
        bad.write_bytes(bytes(mutated))
        try:
            for _ in read_recording(str(bad)).samples:
                pass
        except Fail as e:
            assert "\n" not in str(e) and str(bad) in str(e)


def test_missing_files_and_folders_fail(tmp_path: Path) -> None:
    _fails(tmp_path / "nope.mcap", "no such file")
    (tmp_path / "bag_dir").mkdir()
    _fails(tmp_path / "bag_dir", "directory")


def test_text_goes_straight_into_a_fifo_which_mcap_refuses(tmp_path: Path, samples: list[Sample]) -> None:
    fifo = tmp_path / "pipe.jsonl"
    os.mkfifo(fifo)
    with pytest.raises(Fail, match="not a regular file"):
        check_output(str(fifo), "mcap")
    got: list[bytes] = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_bytes()))
    reader.start()
    check_output(str(fifo), "jsonl")
    record(fifo, samples[:10])
    reader.join(timeout=10)
    assert len(got[0].splitlines()) == 11 and stat.S_ISFIFO(fifo.stat().st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pipe.jsonl"]


# ------------------------------------------------------------------------------------------------ output


def test_format_for() -> None:
    assert format_for(None, None) == "jsonl"
    assert format_for("a.JSONL", None) == format_for("a.ndjson", None) == "jsonl"
    assert [format_for(f"x.{f}", None) for f in FORMATS] == list(FORMATS)
    assert format_for("x.txt", "CSV") == "csv"
    for path, fmt, words in [("x.txt", None, "extension"), ("x.csv", "parquet", "jsonl, csv, mcap, bag"),
                             (None, "mcap", "-o"), (None, "bag", "-o")]:
        with pytest.raises(Fail, match=words) as e:
            format_for(path, fmt)
        assert e.value.code == 2


def test_check_output_refuses_before_any_work(tmp_path: Path) -> None:
    for path, fmt, words in [(tmp_path / "missing" / "x.jsonl", "jsonl", "does not exist"),
                             (tmp_path, "mcap", "directory"), (None, "mcap", "-o")]:
        with pytest.raises(Fail, match=words):
            check_output(None if path is None else str(path), fmt)
    check_output(str(tmp_path / "x.bag"), "bag")
    check_output(None, "csv")
    assert list(tmp_path.iterdir()) == []
    if os.geteuid() == 0:
        pytest.skip("root writes into read-only folders")
    locked = tmp_path / "locked"
    locked.mkdir(mode=0o500)
    try:
        with pytest.raises(Fail, match="cannot write"):
            check_output(str(locked / "x.mcap"), "mcap")
    finally:
        locked.chmod(0o700)


def test_check_output_names_the_extra_when_it_is_missing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "mcap.writer", None)  # import fails as if mcap were not installed
    with pytest.raises(Fail, match=r"pip install 'ttctl\[record\]'"):
        check_output(str(tmp_path / "x.mcap"), "mcap")
    check_output(str(tmp_path / "x.jsonl"), "jsonl")


# ------------------------------------------------------------------------------------------------ fast paths


def _odd_samples() -> list[Sample]:
    """Poses JsonlWriter's fast path must hand to json.dumps, and ones it may format itself."""
    rng = random.Random(11)
    devices = [HMD, LEFT, Device(5, "tracker", "none", "S\u00e9rie \"7\"\\x"), Device(6, "tracker", "none", "")]
    values = [0.0, -0.0, 1.0, 1e16, 1e-5, 123456789.0, 5e-324, 1.7976931348623157e308, 0.1, -2.5]
    out: list[Sample] = []
    for k in range(400):
        nums = [rng.choice(values) if rng.random() < 0.3 else rng.gauss(0, 1) * 10 ** rng.randint(-8, 8)
                for _ in range(13)]
        odd = rng.random()
        if odd < 0.05:
            nums[rng.randrange(13)] = rng.choice([math.nan, math.inf, -math.inf])
        elif odd < 0.08:
            nums[rng.randrange(13)] = rng.randrange(-5, 5)  # an int: json.dumps writes 3, not 3.0
        elif odd < 0.10:
            nums[rng.randrange(13)] = np.float64(rng.random())  # a float subclass with its own repr
        valid: Any = rng.random() < 0.9
        if 0.10 <= odd < 0.12:
            valid = 1
        out.append(PoseSample(T0 + k / 7, rng.choice(devices), valid, rng.random() < 0.9, tuple(nums[0:3]),
                              tuple(nums[3:7]), tuple(nums[7:10]), tuple(nums[10:13])))
    return out


def test_jsonl_fast_lines_are_json_dumps_lines(tmp_path: Path) -> None:
    from ttctl.hmd.formats.text import JsonlWriter

    samples = _odd_samples()
    fast, slow = tmp_path / "fast.jsonl", tmp_path / "slow.jsonl"
    with open_writer(str(fast), "jsonl", "ros", "vr_world", {"a": 1}) as w:
        for s in samples:
            w.write(s)
    with open_writer(str(slow), "jsonl", "ros", "vr_world", {"a": 1}) as w2:
        assert isinstance(w2, JsonlWriter)
        for s in samples:
            w2._write_slowly(s)
    assert fast.read_bytes() == slow.read_bytes()
    assert w.counts == w2.counts == {"pose": len(samples)}
    assert "NaN" not in fast.read_text() and "null" in fast.read_text()


def test_jsonl_fast_reading_is_the_checked_reading(tmp_path: Path, samples: list[Sample]) -> None:
    """Lines of the usual shape skip the field checks; odd ones (ints, nulls, missing or extra
    keys, other key order, spaces) still go through them, to the same samples."""
    path = tmp_path / "rec.jsonl"
    record(path, samples[:300])
    lines = path.read_text().splitlines()
    rng = random.Random(5)
    odd = [lines[0]]
    for line in lines[1:]:
        obj = json.loads(line)
        r = rng.random()
        if r < 0.1 and obj["type"] == "pose":
            obj["position"] = [round(v) for v in obj["position"]]
        elif r < 0.2:
            obj.pop("child", None)  # not read: the device fields say it
            obj.pop("frame", None)  # the recording's, when missing
            obj["extra"] = {"x": [1, 2]}
        elif r < 0.3:
            obj = dict(reversed(list(obj.items())))
        text = json.dumps(obj, separators=(", ", ": ") if r > 0.9 else (",", ":"))
        odd.append(("  " + text) if 0.85 < r < 0.9 else text)
    odd_path = tmp_path / "odd.jsonl"
    odd_path.write_text("\n".join(odd) + "\n\n")
    want = list(read_recording(str(path)).samples)
    got = list(read_recording(str(odd_path)).samples)
    assert len(got) == len(want) == 300
    for g, w in zip(got, want, strict=True):
        assert type(g) is type(w) and g.device == w.device and g.t == w.t
        if isinstance(g, PoseSample) and isinstance(w, PoseSample):
            assert (g.valid, g.connected, g.orientation, g.velocity) == (w.valid, w.connected, w.orientation,
                                                                         w.velocity)
            assert all(abs(a - b) <= 0.5 for a, b in zip(g.position, w.position, strict=True))
    devices = {id(s.device) for s in got}
    assert len(devices) <= 6  # one Device per device, not per line


def test_bag_front_to_back_reading_matches_rosbags_reader(tmp_path: Path, samples: list[Sample],
                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    """Small chunks (so instants straddle them), then a bag whose chunks overlap in time (read by
    rosbags' Reader): the same samples as through rosbags' index, in the same order."""
    from rosbags.rosbag1 import Writer as RosbagsWriter

    from ttctl.hmd.formats import bagreplay

    monkeypatch.setattr(RosbagsWriter, "__init__", _small_chunks(RosbagsWriter.__init__))
    path = tmp_path / "rec.bag"
    record(path, samples)
    bag = bagreplay._Bag(str(path)).open()
    assert len(bag.chunk_infos) > 20 and bag.in_order()
    routes = bagreplay._routes(str(path), bag.connections)
    bag.close()
    assert_same(list(read_recording(str(path)).samples), list(bagreplay._samples_rosbags(str(path), routes)),
                tol=0.0)
    shuffled = tmp_path / "shuffled.bag"  # written out of time order: chunks overlap
    record(shuffled, samples[:60] + samples[200:400] + samples[60:200])  # devices announced first
    bag = bagreplay._Bag(str(shuffled)).open()
    assert not bag.in_order()
    bag.close()
    got = list(read_recording(str(shuffled)).samples)
    assert [s.t for s in got] == sorted(s.t for s in got) and len(got) > 300


def _small_chunks(init: Any) -> Any:
    def patched(self: Any, path: Any) -> None:
        init(self, path)
        self.chunk_threshold = 2048

    return patched


@pytest.mark.parametrize("fmt", ["mcap", "bag"])
def test_devices_sharing_a_frame_share_its_topics(tmp_path: Path, fmt: str) -> None:
    """A swapped controller takes over controller_left, a headset's serial shows up late: the
    topics stay one each (one MCAP channel, one bag connection), and replay follows the swap."""
    first, second = Device(1, "controller", "left", "LHR-A"), Device(5, "controller", "left", "LHR-B")
    hmds = (Device(0, "hmd"), Device(0, "hmd", "none", "LHR-H"))
    samples: list[Sample] = []
    for k in range(40):
        t = T0 + k / 100
        samples.append(PoseSample(t, hmds[k >= 20], True, True, (0.1 * k, 0.0, 1.6)))
        samples.append(PoseSample(t + 0.001, first if k < 15 else second, True, True, (0.0, 0.2, 1.0)))
    path = tmp_path / f"rec.{fmt}"
    counts = record(path, samples, fmt)
    assert counts["/vr/controller_left/pose"] == counts["/vr/hmd/twist"] == 40
    got = list(read_recording(str(path)).samples)
    assert [s.device for s in got] == [s.device for s in samples]
    if fmt == "mcap":
        from mcap.reader import make_reader

        with path.open("rb") as f:
            summary = make_reader(f).get_summary()
        assert summary is not None
        topics = [c.topic for c in summary.channels.values()]
        assert len(topics) == len(set(topics))
