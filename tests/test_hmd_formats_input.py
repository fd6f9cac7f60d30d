"""Recordings, continued: damaged and foreign input fails in one line (never a traceback), output
paths are checked before any work, and the fast read/write paths equal the checked ones."""

from __future__ import annotations

import json
import math
import os
import random
import stat
import sys
import threading
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hmd_recordings import HMD, LEFT, T0, assert_same, record, samples_fixture  # noqa: F401
from ttctl.errors import Fail
from ttctl.hmd.formats import FORMATS, check_output, format_for, open_writer, read_recording
from ttctl.hmd.model import Device, PoseSample, Sample

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
