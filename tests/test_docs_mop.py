"""docs/dji/mop.md: its figures are what `bench transfer` and `bench latency` compute for the mop
profile, its numbers are the profile's, and its three shells move a file across a pipeline that
drops twice, run as written (on free ports)."""

from __future__ import annotations

import hashlib
import os
import re
import shlex
import signal
import socket
from pathlib import Path

from e2e_lib import Start, free_port
from ttctl.bench import pipeline
from ttctl.bench.latency import run_model
from ttctl.link.model import load_profile

DOC = Path(__file__).resolve().parent.parent / "docs" / "dji" / "mop.md"
MOP = load_profile("mop")


def test_the_profile_numbers_are_the_shipped_ones() -> None:
    text = DOC.read_text()
    assert MOP.mtu == 128 and (MOP.capacity_Bps("up", 10), MOP.capacity_Bps("down", 10)) == (3000, 4000)
    assert "128-byte packets, 3000 B/s up, 4000 B/s down" in text
    assert MOP.pipe is not None and f"{MOP.pipe.rate_Bps:.0f} B/s each way" in text


def test_the_transfer_figures_are_the_benchmarks() -> None:
    text = " ".join(DOC.read_text().split())
    rows = {(r.direction, r.drops): r for r in pipeline.rows(MOP, 10, 2_000_000, [1, 2, 3])}
    assert rows[("up", 0)].retransmitted == 0 and rows[("down", 0)].retransmitted == 0 and "Nothing is resent" in text
    assert f"goodput is {rows[('up', 0)].of_pipe:.3f} of the pipeline's modelled rate" in text
    assert rows[("up", 0)].of_pipe == rows[("down", 0)].of_pipe or f"{rows[('down', 0)].of_pipe:.3f}" in text
    assert f"goodput is {rows[('up', 2)].of_pipe:.3f} up and {rows[('down', 2)].of_pipe:.3f} down" in text
    assert f"({rows[('up', 2)].retransmitted} up, {rows[('down', 2)].retransmitted} down)" in text
    assert f"({rows[('up', 2)].lost_in_flight}, {rows[('down', 2)].lost_in_flight})" in text


def test_the_latency_table_is_the_benchmark() -> None:
    text = DOC.read_text()
    phases = {p.phase: p for p in run_model(MOP, 10, 50, 1, 1.0, 2_000_000)}
    for phase, label in (("idle", "idle"), ("upload", "upload on the pipeline"),
                         ("download", "download on the pipeline")):
        p = phases[phase]
        assert f"| {label} | {p.p50_ms:.0f} | {p.p95_ms:.0f} |" in text, (phase, p)


def test_the_three_shells(tmp_path: Path, start: Start) -> None:
    block = re.search(r"Three shells:\n\n```\n(.*?)```", DOC.read_text(), flags=re.S)
    assert block is not None
    lines = block.group(1).strip().splitlines()
    assert [line.split()[1] for line in lines] == ["link", "recv-file", "send-file"]
    ports = {"14550": free_port(), "14560": free_port(), "14551": free_port(socket.SOCK_STREAM),
             "14561": free_port(socket.SOCK_STREAM)}
    (tmp_path / "results.bin").write_bytes(os.urandom(1_500_000))  # about 16 s: both drops land in it
    procs = []
    for i, line in enumerate(lines):
        for old, new in ports.items():
            line = line.replace(f":{old}", f":{new}")
        args = shlex.split(line)[1:]
        if args[0] == "recv-file":
            args += ["--count", "1"]
        if args[0] == "send-file":
            args += ["--no-compress"]
        procs.append(start(f"shell{i}", *args))
        procs[-1].wait_for({"link": "relay: udpin", "recv-file": "receiving into"}.get(args[0], ""))
    relay, recv, send = procs
    assert send.wait(120) == 0, send.stderr
    assert recv.wait(30) == 0, recv.stderr
    digest = hashlib.sha256((tmp_path / "results.bin").read_bytes()).hexdigest()
    assert hashlib.sha256((tmp_path / "inbox" / "results.bin").read_bytes()).hexdigest() == digest
    relay.signal(signal.SIGINT)
    relay.wait(10)
    assert re.search(r"pipeline \d+ B up, \d+ B down, [2-9] closed", relay.stderr), relay.stderr
    assert send.stderr.count("pipeline open") >= 3, send.stderr
