"""Recordings of VR pose streams: each format is checked by a reader that is not ours (mcap +
mcap_ros2, rosbags' bag reader with its own typestore, json, csv), then replayed and compared field
by field; writes are atomic (abort, exception, SIGKILL); damaged input is one clear Fail."""

from __future__ import annotations

import csv
import json
import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path
from typing import Any

import pytest

from hmd_recordings import CSV_COLUMNS, HMD, LEFT, MD5, RIGHT, T0, assert_same, record, ros_view, samples_fixture  # noqa: F401
from ttctl.hmd.formats import FORMATS, format_for, open_writer, read_recording
from ttctl.hmd.model import BUTTONS, ControllerSample, PoseSample, Sample


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
        latched = channel.topic in ("/tf_static", "/vr/recording")
        assert qos[0].durability.name == ("TRANSIENT_LOCAL" if latched else "VOLATILE")
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
        # vive_ros's layout (vive_node.cpp): axes [pad x, pad y, trigger], buttons [menu, trigger, pad
        # pressed, grip], then the pad touched
        assert len(joy.axes) == 3 and abs(joy.axes[2] - s.trigger) < 1e-6
        assert abs(joy.axes[0] - s.pad_x) < 1e-6 and abs(joy.axes[1] - s.pad_y) < 1e-6
        assert list(joy.buttons) == [int(s.buttons[b]) for b in ("menu", "trigger_click", "pad_pressed", "grip",
                                                                    "pad_touched")]
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
    assert [list(j.buttons) for j in joys] == [s.joy_buttons for s in right]
    assert [list(j.axes) for j in joys] == [pytest.approx([s.pad_x, s.pad_y, s.trigger], abs=1e-6) for s in right]
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
