"""Recordings that went through standard ROS tools replay (real processes; rosbags-convert, the
rosbags CLI, as the tool): a ROS 1 bag converted to a ROS 2 bag folder (SQLite and MCAP
storage), and our MCAP converted to a ROS 1 bag, give the samples the original gives, although
the converters drop MCAP's metadata records, ROS 1's header.seq and MCAP's sequence numbers.
The Joy messages follow vive_ros's layout; recordings of version 1 (our old layout) still read."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import assert_no_traceback, run_ttctl

CONVERT = shutil.which("rosbags-convert") or str(Path(__import__("sys").executable).with_name("rosbags-convert"))


def _replay(src: Path, out: Path) -> list[dict]:
    p = run_ttctl("hmd", "dump", "--source", "replay", str(src), "--speed", "0", "-o", str(out), "-q", timeout=60)
    assert_no_traceback(p)
    assert p.returncode == 0, p.stderr
    lines = out.read_text().splitlines()
    assert json.loads(lines[0])["type"] == "recording"
    return sorted((json.loads(x) for x in lines[1:]), key=lambda d: (d["t"], d["index"], d["type"]))


@pytest.fixture(scope="module")
def original(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    folder = tmp_path_factory.mktemp("orig")
    out = {}
    for fmt in ("bag", "mcap"):
        path = folder / f"rec.{fmt}"
        p = run_ttctl("hmd", "dump", "--duration", "2", "--speed", "0", "--seed", "5", "-o", str(path), "-q",
                      timeout=60)
        assert p.returncode == 0, p.stderr
        out[fmt] = path
    return out


@pytest.mark.parametrize("storage", ["sqlite3", "mcap"])
def test_a_bag_converted_to_a_ros2_folder_replays(tmp_path: Path, original: dict[str, Path], storage: str) -> None:
    dst = tmp_path / "ros2"
    subprocess.run([CONVERT, "--src", str(original["bag"]), "--dst", str(dst), "--dst-storage", storage],
                   check=True, capture_output=True, timeout=120)
    assert (dst / "metadata.yaml").is_file()
    want = _replay(original["bag"], tmp_path / "want.jsonl")
    got = _replay(dst, tmp_path / "got.jsonl")
    assert len(got) == len(want) > 500
    assert got == want
    assert any(d["type"] == "controller" for d in got)
    if storage == "mcap":  # the .mcap alone, without its folder: no ttctl metadata record in it
        bare = tmp_path / "bare.mcap"
        shutil.copy(next(dst.glob("*.mcap")), bare)
        assert _replay(bare, tmp_path / "bare.jsonl") == want


def test_our_mcap_converted_to_a_bag_replays(tmp_path: Path, original: dict[str, Path]) -> None:
    dst = tmp_path / "conv.bag"
    subprocess.run([CONVERT, "--src", str(original["mcap"]), "--dst", str(dst)], check=True, capture_output=True,
                   timeout=120)
    want = _replay(original["mcap"], tmp_path / "want.jsonl")
    got = _replay(dst, tmp_path / "got.jsonl")
    assert got == want and len(got) > 500


def test_a_folder_that_is_no_bag_is_one_line(tmp_path: Path) -> None:
    p = run_ttctl("hmd", "dump", "--source", "replay", str(tmp_path), "--speed", "0", timeout=60)
    assert p.returncode == 2 and p.stderr.count("\n") == 1 and "not a ROS 2 bag folder" in p.stderr, p.stderr


def test_joy_layouts() -> None:
    """Version 2 (vive_ros: axes [pad x, pad y, trigger], buttons [menu, trigger, pad pressed, grip],
    then pad touched) and version 1 (axes [trigger, pad x, pad y], buttons [trigger, pad touched,
    pad pressed, menu, grip]) give the same sample; a lost sequence number is counted instead."""
    from ttctl.hmd.formats.ros import Rebuilder

    devices = json.dumps({"index": 3, "kind": "controller", "role": "left", "serial": "C", "frame": "controller_left",
                          "valid": True, "connected": True})
    got = []
    for version, axes, buttons in ((2, [0.5, -0.25, 0.75], [1, 0, 1, 0, 1]), (1, [0.75, 0.5, -0.25], [0, 1, 1, 1, 0])):
        r = Rebuilder("x", version)
        r.devices(0, devices)
        r.joy("controller_left", 1, 0, axes, buttons)
        r.joy("controller_left", 2, 0, axes, buttons)
        got.append(r.out[-2:])
    for a, b in zip(*got, strict=True):
        assert (a.trigger, a.pad_x, a.pad_y, a.buttons) == (b.trigger, b.pad_x, b.pad_y, b.buttons)
    s = got[0][0]
    assert (s.pad_x, s.pad_y, s.trigger) == (0.5, -0.25, 0.75)
    assert s.buttons == {"menu": True, "trigger_click": False, "pad_pressed": True, "grip": False, "pad_touched": True}
    assert [x.packet for x in got[0]] == [1, 2]  # no sequence in the file: counted per controller
