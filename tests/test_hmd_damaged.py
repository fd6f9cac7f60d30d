"""`ttctl hmd dump --source replay` of a recording that is cut short or damaged (real processes):
refused in one line that says what is wrong (exit 1, nothing written), or with `--salvage` read
up to the damage with a warning; a cut bag's words carry no Python tuple; an MCAP whose summary
CRC is wrong (the MCAP specification's summary_crc, which Foxglove's reader checks) is refused."""

from __future__ import annotations

import zlib
from pathlib import Path

import pytest

from conftest import assert_no_traceback, run_ttctl
from hmd_recordings import make_samples, record


@pytest.fixture(scope="module")
def recordings(tmp_path_factory: pytest.TempPathFactory) -> dict[str, bytes]:
    folder = tmp_path_factory.mktemp("rec")
    samples = make_samples(3.0)
    out = {}
    for fmt in ("jsonl", "csv", "mcap", "bag"):
        path = folder / f"rec.{fmt}"
        record(path, samples)
        out[fmt] = path.read_bytes()
    return out


def replay(path: Path, *extra: str) -> tuple[int, str, Path]:
    out = path.parent / "out.jsonl"
    p = run_ttctl("hmd", "dump", "--source", "replay", str(path), "--speed", "0", "-o", str(out), *extra, timeout=60)
    assert_no_traceback(p)
    return p.returncode, p.stderr, out


@pytest.mark.parametrize("fmt", ["jsonl", "csv", "mcap"])
def test_a_cut_recording_is_refused_or_salvaged(tmp_path: Path, recordings: dict[str, bytes], fmt: str) -> None:
    data = recordings[fmt]
    cut = tmp_path / f"cut.{fmt}"
    cut.write_bytes(data[: len(data) * 6 // 10])
    code, err, out = replay(cut)
    assert code == 1, err
    assert err.count("\n") == 1 and "cut short" in err and "--salvage" in err, err
    assert not out.exists() and [p.name for p in tmp_path.iterdir()] == [cut.name]  # nothing written
    code, err, out = replay(cut, "--salvage")
    assert code == 0, err
    assert "warning:" in err and "cut short" in err, err
    salvaged = len(out.read_text().splitlines())
    out.unlink()
    whole = tmp_path / f"whole.{fmt}"
    whole.write_bytes(data)
    code, err, out = replay(whole)
    assert code == 0 and "warning" not in err, err
    assert 0 < salvaged < len(out.read_text().splitlines())


def test_a_cut_bag_says_so_without_a_python_tuple(tmp_path: Path, recordings: dict[str, bytes]) -> None:
    data = recordings["bag"]
    cut = tmp_path / "cut.bag"
    cut.write_bytes(data[: len(data) * 6 // 10])
    code, err, _ = replay(cut)
    assert code != 0 and err.count("\n") == 1, err
    assert "cut short" in err and "reindex" in err, err
    assert "('" not in err and "',)" not in err, err


def _break_summary_crc(data: bytes) -> bytes:
    """The same file with its Footer's summary_crc off by one."""
    at = len(data) - 8 - 4  # magic (8), then summary_crc (4) is the footer's last field
    crc = int.from_bytes(data[at:at + 4], "little")
    assert crc != 0
    return data[:at] + ((crc + 1) & 0xFFFFFFFF).to_bytes(4, "little") + data[at + 4:]


def test_an_mcap_whose_summary_crc_is_wrong_is_refused(tmp_path: Path, recordings: dict[str, bytes]) -> None:
    data = recordings["mcap"]
    footer = data[-8 - 29:-8]
    start = int.from_bytes(footer[9:17], "little")
    assert zlib.crc32(footer[:-4], zlib.crc32(data[start:len(data) - 8 - 29])) == \
        int.from_bytes(footer[-4:], "little")  # what a good file's CRC covers
    bad = tmp_path / "bad.mcap"
    bad.write_bytes(_break_summary_crc(data))
    code, err, out = replay(bad)
    assert code == 1 and err.count("\n") == 1 and "summary's CRC does not match" in err, err
    assert not out.exists()
    code, err, _ = replay(bad, "--salvage")
    assert code == 0 and "warning:" in err, err


@pytest.mark.parametrize("what", ["fifo", "/dev/zero", "zeros", "no newline"])
def test_a_replay_source_that_would_block_or_fill_the_memory_is_one_line(tmp_path: Path, what: str) -> None:
    import os

    if what == "fifo":
        path = tmp_path / "pipe.jsonl"
        os.mkfifo(path)  # opening it to read would wait for a writer forever
    elif what == "/dev/zero":
        path = Path("/dev/zero")
    else:
        path = tmp_path / "big.jsonl"
        path.write_bytes(b"\0" * (3 << 20) if what == "zeros" else b'{"type": "pose", "t": ' + b"1" * (3 << 20))
    p = run_ttctl("hmd", "dump", "--source", "replay", str(path), "--speed", "0", "-o", str(tmp_path / "o.jsonl"),
                  timeout=30)
    assert_no_traceback(p)
    assert p.returncode == 2 and p.stderr.count("\n") == 1, p.stderr
    assert ("not a regular file" if what in ("fifo", "/dev/zero") else "longer than 1024 KiB") in p.stderr, p.stderr
    assert not (tmp_path / "o.jsonl").exists()
