"""Hostile input, the last cases (issue 30): output paths that are FIFOs or devices, documents nested
deeper than Python's recursion limit, far-out link model numbers, empty choices, and the partial
state of a file whose name another file took. Each: one line, the documented exit status, nothing
replaced, nothing left behind. Real processes where a command runs.
"""

from __future__ import annotations

import hashlib
import os
import signal
import stat
import subprocess
import time
from pathlib import Path

import pytest

from conftest import run_ttctl, ttctl_cmd
from machine import scaled

NOWHERE = "udpout:127.0.0.1:9"


def _one_error_line(proc: subprocess.CompletedProcess[str], code: int, *words: str) -> str:
    lines = [ln for ln in proc.stderr.splitlines() if ln.strip()]
    assert proc.returncode == code, (proc.returncode, proc.stderr[-2000:])
    assert len(lines) == 1 and lines[0].startswith("ttctl: error: "), proc.stderr[-2000:]
    assert "Traceback" not in proc.stderr
    for w in words:
        assert w in lines[0], lines[0]
    return lines[0]


@pytest.mark.parametrize("argv", [
    ["bench", "link", "--plot", "{out}.png"],
    ["bench", "transfer", "--quick", "--plot", "{out}.png"],
    ["bench", "link", "--to", NOWHERE, "-o", "{out}.json"],
    ["link", "fit", "{tmp}/m.json", "-o", "{out}.toml"],
])
def test_an_output_that_is_a_fifo_is_refused_and_left_alone(tmp_path: Path, argv: list[str]) -> None:
    """A FIFO (or, as root, /dev/null) under an output name is never renamed over: refused before
    any work, and it is still a FIFO afterwards."""
    out = tmp_path / "out"
    suffix = Path(argv[-1]).suffix
    fifo = Path(f"{out}{suffix}")
    os.mkfifo(fifo)
    (tmp_path / "m.json").write_text("{}")
    proc = run_ttctl(*[a.format(out=out, tmp=tmp_path) for a in argv], timeout=60)
    _one_error_line(proc, 2, "not a regular file")
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(["m.json", fifo.name])


def test_hmd_dump_into_a_fifo_waits_for_its_reader_and_hears_ctrl_c(tmp_path: Path) -> None:
    """`hmd dump -o FIFO` with nobody reading waits (a blocking open() would be deaf to Ctrl-C);
    Ctrl-C ends it in one line, exit 130; with a reader, the samples flow into the FIFO."""
    fifo = tmp_path / "poses.jsonl"
    os.mkfifo(fifo)
    p = subprocess.Popen([*ttctl_cmd(), "hmd", "dump", "--duration", "30", "-o", str(fifo)],
                         stderr=subprocess.PIPE, text=True)
    time.sleep(scaled(1.5))  # (started and waiting: longer on a busy machine)
    assert p.poll() is None  # waiting for a reader
    p.send_signal(signal.SIGINT)
    _, stderr = p.communicate(timeout=20)
    assert p.returncode == 130, stderr
    assert "waiting for a reader" in stderr and "Traceback" not in stderr
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)

    p = subprocess.Popen([*ttctl_cmd(), "hmd", "dump", "--duration", "1", "-o", str(fifo)],
                         stderr=subprocess.PIPE, text=True)
    with open(fifo, "rb") as reader:
        data = reader.read()
    _, stderr = p.communicate(timeout=30)
    assert p.returncode == 0, stderr
    assert data.count(b"\n") > 10 and data.startswith(b"{")


def _deep_yaml(tmp: Path) -> Path:
    path = tmp / "deep.yaml"
    path.write_text("- " + "[" * 20000 + "]" * 20000 + "\n")
    return path


def _deep_json(tmp: Path) -> Path:
    path = tmp / "deep.json"
    path.write_text("[" * 100000 + "]" * 100000)
    return path


def test_documents_nested_past_the_recursion_limit_are_one_line(tmp_path: Path) -> None:
    _one_error_line(run_ttctl("emulate", "tablet", "--to", NOWHERE, "--script", str(_deep_yaml(tmp_path))), 2,
                    "nested too deeply")
    deep = str(_deep_json(tmp_path))
    _one_error_line(run_ttctl("link", "fit", deep, "-o", str(tmp_path / "f.toml")), 2, "nested too deeply")
    _one_error_line(run_ttctl("bench", "link", "--like", deep), 2, "nested too deeply")
    rec = tmp_path / "deep.jsonl"
    good = run_ttctl("hmd", "dump", "--duration", "0.2", "-o", str(rec))
    assert good.returncode == 0, good.stderr
    with open(rec, "a") as f:
        f.write("[" * 100000 + "]" * 100000 + "\n")
    _one_error_line(run_ttctl("hmd", "dump", "--source", "replay", str(rec), "-o", str(tmp_path / "o.jsonl")), 2,
                    "nested too deeply")
    assert not (tmp_path / "o.jsonl").exists() and not (tmp_path / "f.toml").exists()


def test_a_deep_trajectory_is_refused_in_words() -> None:
    from ttctl.ends.onboard.trajectory import TrajectoryError, parse_trajectory

    with pytest.raises(TrajectoryError, match="nested too deeply"):
        parse_trajectory("waypoints: " + "[" * 20000 + "]" * 20000)


def test_the_relay_warns_of_far_distances_and_endless_bursts() -> None:
    """As every other command does for a distance outside the profile's measurements; a mean burst
    that outlasts any run is an outage, and said so."""
    for extra, words in ((["--distance", "1e308"], "extrapolated at 1e+308 m"),
                         (["--loss-model", "burst", "--burst-mean", "1e308"], "longer than any run")):
        p = subprocess.Popen([*ttctl_cmd(), "link", "relay", "--listen", "udpin:127.0.0.1:0", "--to", NOWHERE,
                              *extra], stderr=subprocess.PIPE, text=True)
        try:
            assert p.stderr is not None
            first = p.stderr.readline()
        finally:
            p.send_signal(signal.SIGINT)
            p.communicate(timeout=20)
        assert first.startswith("ttctl: warning: ") and words in first, first


@pytest.mark.parametrize(("argv", "words"), [
    (["bench", "transfer", "--protocols", " , "], "--protocols names none"),
    (["bench", "latency", "--count", "2", "--dialect", "/nonexistent/x.xml"], "/nonexistent/x.xml"),
    (["hmd", "dump", "--to", NOWHERE, "--profile", "", "--duration", "1"], "unknown link profile ''"),
])
def test_empty_and_missing_choices_are_refused(tmp_path: Path, argv: list[str], words: str) -> None:
    proc = run_ttctl(*argv, cwd=tmp_path, timeout=60)
    _one_error_line(proc, 2, words)
    assert list(tmp_path.iterdir()) == []


def test_a_partial_whose_name_another_file_took_is_cleaned(tmp_path: Path) -> None:
    """A transfer killed half-way leaves its partial state for a resume; once another file takes
    that name, the state could never be used and would stay forever: it goes, unless a transfer of
    this process still writes it."""
    from ttctl.proto.storage import PARTIAL_DIR, ReceiveDir

    old, live, new = b"a" * 5000, b"b" * 3000, b"c" * 4000
    store = ReceiveDir(tmp_path)
    store.prepare()
    killed = store.partial("mission.yaml", len(old), hashlib.sha256(old).digest())
    killed.write(0, old[:2000])
    killed.save()
    killed.close()
    other = store.partial("other.yaml", len(old), hashlib.sha256(old).digest())
    other.write(0, old[:1000])
    other.save()
    del killed
    writing = store.partial("mission.yaml", len(live), hashlib.sha256(live).digest())  # still being written
    writing.write(0, live[:100])
    writing.save()
    done = store.partial("mission.yaml", len(new), hashlib.sha256(new).digest())
    done.write(0, new)
    assert done.complete and done.verify()
    assert done.finish(overwrite=False).read_bytes() == new
    left = sorted(p.name for p in (tmp_path / PARTIAL_DIR).iterdir() if not p.name.startswith(".lock"))
    assert left == sorted([f"{writing.key}.part", f"{writing.key}.json", f"{other.key}.part", f"{other.key}.json"])
    store.release(failed=False)
