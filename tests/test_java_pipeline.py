"""PipelineLink, the generated Java runtime's MOP link over DJI Mobile SDK v5's PipelineManager
(5.3+), and the Session's two paths: file data on the pipeline while it is open, everything else
on the low-speed link (ttctl's MOP contract, /work/notes/mop_contract.md; issue 27). The tablet is
tests/java/pipeline/PipelineTablet.java wired as docs/dji/tablet-java.md wires it, on the
stand-in PipelineManager/Pipeline of tests/java/msdk5 (DJI's packages and signatures; the stream
is a TCP connection to TTCTL_FAKE_PIPELINE).

Real processes: the tablet, `ttctl emulate onboard` on a UDP link, and between them
tests/pipe_mux.py, the onboard side of the pipeline (pymavlink parses every frame on it); and the
tablet against ttctl's own pipeline end (`emulate onboard --profile mop --pipeline tcpin:`),
directly and through `ttctl link relay --profile mop --pipe-drop`.

- a 2 MB upload and a 2 MB fetch, SHA-256 equal, the upload's data frames on the pipeline (none
  on the low-speed link) and the fetch's arriving there; commands on the low-speed link, their
  p95 latency while the files move about what it is with none moving;
- the pipeline closed twice mid-transfer from the onboard side: both files still arrive, the
  tablet reconnected;
- short writes (7 bytes a call): frames still whole (pymavlink parses them all);
- a half frame left by a close is dropped, never glued to the next connection's bytes;
- a pipeline that never opens: everything on the low-speed link, one line saying so;
- an SDK failing every call: its words reach the state listener and problem(), said once on
  stderr; everything stays on the low-speed link; no hang;
- a garbage flood on the pipeline: heap bounded, commands on the low-speed link still answered;
- end to end with ttctl's pipeline: 2 MB each way, SHA-256 equal, the data on the pipeline (with
  UdpLink, with PayloadLink as the docs wire it, signed; a fetch alone, which the tablet's hello
  opens); the relay closing the pipeline twice mid-transfer, and stalling it (closed after 2 s).
"""

from __future__ import annotations

import hashlib
import os
import random
import re
import shutil
import socket
import subprocess
from pathlib import Path

import pytest

from conformance_lib import build_java, pymavlink_module
from conftest import ROOT
from e2e_lib import LOCAL, Start, free_port, relay
from machine import busy
from pipe_mux import DATA, PipeMux

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

MB2 = 2 * 1024 * 1024


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    drivers = sorted((ROOT / "tests/java/msdk5").rglob("*.java")) + [ROOT / "tests/java/pipeline/PipelineTablet.java"]
    cls, _ = build_java(tmp_path_factory.mktemp("java_pipeline"), drivers)
    return cls


@pytest.fixture(scope="module")
def pm(tmp_path_factory: pytest.TempPathFactory) -> object:
    return pymavlink_module("ttapi", tmp_path_factory.mktemp("pm"))


def tablet(classes: Path, cwd: Path, mux: PipeMux | tuple[int, int], *args: str, env: dict[str, str] | None = None,
           heap: str = "256m", timeout: float = 400) -> tuple[dict[str, str], str]:
    """The Java tablet, its link to `mux`'s ports (or (udp port, pipeline port))."""
    udp, pipe = (mux.udp_port, mux.pipe_port) if isinstance(mux, PipeMux) else mux
    e = dict(os.environ, TTCTL_FAKE_PIPELINE=f"{LOCAL}:{pipe}", **(env or {}))
    proc = subprocess.run(["java", f"-Xmx{heap}", f"-Dttctl.msdk.udp={LOCAL}:{udp}", "-cp", str(classes),
                           "PipelineTablet", f"udp={LOCAL}:{udp}", *args], capture_output=True, text=True,
                          timeout=timeout, cwd=cwd, env=e)
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, text[-4000:]
    lines = [ln for ln in proc.stdout.splitlines() if ln.startswith("RESULT ")]
    assert lines, text[-4000:]
    return dict(re.findall(r"(\w+)=(\S+)", lines[-1])), text


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


# The onboard end's own link stands for both its paths here (tests/pipe_mux.py splits them): fast
# and clean, with the largest packet ttctl's profiles allow (the mux cuts the pipeline's frames to it).
PROFILE = """
[pipe]
description = "the mux's onboard side: a clean link with 255-byte packets"
mtu = 255
[pipe.up]
rate_Bps = [[0, 1000000]]
loss = [[0, 0.0]]
latency_s = 0.001
queue_packets = 64
feedback = true
[pipe.down]
rate_Bps = [[0, 200000]]
loss = [[0, 0.0]]
latency_s = 0.001
queue_packets = 64
feedback = true
"""


def onboard(start: Start, tmp: Path) -> tuple[int, Path]:
    port = free_port()
    (tmp / "pipe.toml").write_text(PROFILE)
    (tmp / "served").mkdir()
    back = tmp / "served" / "flight.log"
    back.write_bytes(random.Random(28).randbytes(MB2))
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{port}", "--inbox",
                 str(tmp / "inbox"), "--serve", str(tmp / "served"), "--no-entry-points", "--profile-file",
                 str(tmp / "pipe.toml"), "--profile", "pipe")
    node.wait_for("onboard 1:")
    return port, back


def transfer(classes: Path, tmp: Path, start: Start, pm: object, drops: tuple[int, ...] = (),
             env: dict[str, str] | None = None) -> tuple[dict[str, str], str, PipeMux, Path, Path]:
    port, back = onboard(start, tmp)
    up = tmp / "mission.bin"
    up.write_bytes(random.Random(27).randbytes(MB2))
    mux = PipeMux(pm, port, drops=drops, refuse=0.5, mtu=255)  # type: ignore[arg-type]
    try:
        # three processes move 2 MB each way in Python and Java: on a busy machine a command's tries
        # wait for cores, so it gets more of them (the runtime's default, 3 retries, when idle)
        r, text = tablet(classes, tmp, mux, "run=e2e", f"send={up}", "fetch=flight.log", f"dir={tmp / 'got'}",
                         "timeout=60", f"retries={round(3 * busy())}", env=env)
    finally:
        mux.close()
    assert r["opened"] == "true" and r["command_ack"] == "TT_COMMAND_ACK", text[-3000:]
    assert r["send_ok"] == "true" and r["fetch_ok"] == "true", text[-3000:]
    assert sha(tmp / "inbox" / "mission.bin") == sha(up) == r["send_sha256"]
    assert sha(tmp / "got" / "flight.log") == sha(back) == r["fetch_sha256"]
    # the upload's data went on the pipeline (pymavlink parsed every frame of it there) ...
    assert mux.pipe_up_bytes >= MB2, (mux.pipe_up, mux.low_up)
    # ... and the fetch's came back on it
    assert sum(mux.pipe_down[n] for n in DATA) * 246 >= MB2 * 0.9, mux.pipe_down
    # commands, offers, statuses stayed on the low-speed link
    # the pipeline carried file data (wide frames, as ttctl's ends cut them for a stream) and the
    # tablet's hello, its HEARTBEAT, once on each connection
    assert set(mux.pipe_up) == {"TT_FILE_DATA_WIDE", "HEARTBEAT"}, mux.pipe_up
    assert mux.pipe_up["HEARTBEAT"] == mux.connections, (mux.pipe_up, mux.connections)
    assert mux.low_up["TT_ACTION_COMMAND"] >= 2 and mux.low_up["TT_FILE_OFFER"] >= 1, mux.low_up
    assert mux.low_up["TT_FILE_STATUS"] >= 1, mux.low_up
    return r, text, mux, up, back


def test_upload_and_fetch_over_the_pipeline(classes: Path, tmp_path: Path, start: Start, pm: object) -> None:
    r, text, mux, _, _ = transfer(classes, tmp_path, start, pm)
    # while the pipeline was open no file data went on the low-speed link
    assert sum(mux.low_up[n] for n in DATA) == 0, mux.low_up
    assert int(r["pipe_connects"]) == 1 and mux.connections == 1, text[-2000:]
    assert int(r["pipe_bytes_out"]) >= MB2 and int(r["pipe_frames_in"]) >= MB2 // 246, r
    assert int(r["low_bytes"]) < MB2 // 10, r  # the link carried control, not the files
    commands_keep_their_latency(r)


def test_pipeline_closed_twice_mid_transfer(classes: Path, tmp_path: Path, start: Start, pm: object) -> None:
    r, text, mux, _, _ = transfer(classes, tmp_path, start, pm, drops=(MB2 // 3, 2 * MB2 // 3))
    assert len(mux.dropped_at) == 2 and mux.connections >= 3, (mux.dropped_at, mux.connections)
    assert int(r["pipe_connects"]) >= 3, r
    assert text.count("EVENT pipeline closed") >= 2, text[-3000:]
    # a drop costs the bytes in flight, not the file: what went twice is a small part of it
    assert mux.pipe_up_bytes < 2 * MB2, mux.pipe_up_bytes


def test_short_writes_keep_frames_whole(classes: Path, tmp_path: Path, start: Start, pm: object) -> None:
    r, text, _mux, _, _ = transfer(classes, tmp_path, start, pm, env={"TTCTL_FAKE_PIPELINE_SHORT": "1"})
    assert int(r["pipe_short_writes"]) > 1000, r
    assert int(r["pipe_connects"]) == 1, text[-2000:]


def test_a_pipeline_that_never_opens_leaves_everything_on_the_link(classes: Path, tmp_path: Path, start: Start,
                                                                   pm: object) -> None:
    port, _back = onboard(start, tmp_path)
    mux = PipeMux(pm, port, mtu=255)  # type: ignore[arg-type]
    up = tmp_path / "mission.bin"
    up.write_bytes(random.Random(29).randbytes(40000))
    nobody = free_port(socket.SOCK_STREAM)  # nothing listens: every connectPipeline fails
    try:
        r, text = tablet(classes, tmp_path, (mux.udp_port, nobody), "run=e2e", "wait_open_ms=3000", f"send={up}",
                         "timeout=60", "rate=20000", timeout=200)
    finally:
        mux.close()
    assert r["opened"] == "false" and r["send_ok"] == "true", text[-3000:]
    assert sha(tmp_path / "inbox" / "mission.bin") == sha(up) == r["send_sha256"]
    assert int(r["pipe_bytes_out"]) == 0 and int(r["low_bytes"]) > 40000, r
    assert sum(mux.low_up[n] for n in DATA) >= 40000 // 247, mux.low_up  # the data went on the link
    said = [ln for ln in text.splitlines() if ln.startswith("ttctl PipelineLink:")]
    assert len(said) == 1 and "connectPipeline" in said[0] and "CONNECT_FAILED" in said[0], said


def test_an_sdk_failing_every_call_is_said_once_in_its_words(classes: Path, tmp_path: Path, start: Start,
                                                             pm: object) -> None:
    port, _ = onboard(start, tmp_path)
    mux = PipeMux(pm, port)  # type: ignore[arg-type]
    try:
        r, text = tablet(classes, tmp_path, mux, "run=fail", "wait_ms=4000", env={"TTCTL_FAKE_PIPELINE_FAIL": "1"},
                         timeout=120)
    finally:
        mux.close()
    assert r["command_ack"] == "TT_COMMAND_ACK", text[-3000:]  # the low-speed link works on
    assert r["problem_has_words"] == "true" and r["told_state"] == "true" and r["open"] == "false", text[-3000:]
    said = [ln for ln in text.splitlines() if ln.startswith("ttctl PipelineLink:")]
    assert len(said) == 1, said  # once per kind, though connect failed every second
    assert int(r["states"]) == 1, r
    assert 3 <= int(r["sdk_calls"]) <= 10, r  # a connect a second, not a spin
    assert mux.connections == 0 and int(r["sdk_connects"]) == 0, r
    assert re.search(r"EVENT closed in \d{1,4} ms", text), text[-2000:]


def test_a_half_frame_at_a_close_is_never_glued_to_the_next_connection(classes: Path, tmp_path: Path,
                                                                       pm: object) -> None:
    mux = PipeMux(pm, free_port(), split=True)  # type: ignore[arg-type]
    try:
        r, text = tablet(classes, tmp_path, mux, "run=split", timeout=120)
    finally:
        mux.close()
    assert int(r["pipe_connects"]) >= 2 and mux.connections >= 2, text[-2000:]
    # the second connection's whole frame, and not the first one's glued to its tail
    assert int(r["pipe_frames_in"]) == 1, r
    assert int(r["discarded"]) >= 6, r  # the first half (of a 21-byte HEARTBEAT) dropped at the close


def test_a_garbage_flood_on_the_pipeline(classes: Path, tmp_path: Path, start: Start, pm: object) -> None:
    port, _ = onboard(start, tmp_path)
    mux = PipeMux(pm, port, garbage=True)  # type: ignore[arg-type]
    try:
        r, text = tablet(classes, tmp_path, mux, "run=flood", "secs=5", heap="64m", timeout=120)
    finally:
        mux.close()
    assert r["opened"] == "true", text[-3000:]
    assert mux.garbage_bytes > 10 * MB2 and int(r["pipe_bytes_in"]) > 10 * MB2, (mux.garbage_bytes, r)
    assert int(r["heap_mb"]) < 32, r
    assert int(r["worst_command_ms"]) < 2000, r
    assert re.search(r"EVENT closed in \d{1,4} ms", text), text[-2000:]


# -- against ttctl's own pipeline end: emulate onboard --profile mop --pipeline tcpin: ----------------

def mop_onboard(start: Start, tmp: Path, pipe_port: int, *extra: str) -> tuple[int, Path]:
    port = free_port()
    (tmp / "served").mkdir()
    back = tmp / "served" / "flight.log"
    back.write_bytes(random.Random(28).randbytes(MB2))
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{port}", "--inbox",
                 str(tmp / "inbox"), "--serve", str(tmp / "served"), "--no-entry-points", "--profile", "mop",
                 "--pipeline", f"tcpin:{LOCAL}:{pipe_port}", *extra)
    node.wait_for("onboard 1:")
    return port, back


def mop_transfer(classes: Path, tmp: Path, back: Path, ports: tuple[int, int],
                 *args: str) -> tuple[dict[str, str], str]:
    up = tmp / "mission.bin"
    up.write_bytes(random.Random(27).randbytes(MB2))
    r, text = tablet(classes, tmp, ports, "run=e2e", f"send={up}", "fetch=flight.log", f"dir={tmp / 'got'}",
                     "timeout=60", "rate=3000", *args)
    assert r["opened"] == "true" and r["command_ack"] == "TT_COMMAND_ACK", text[-3000:]
    assert r["send_ok"] == "true" and r["fetch_ok"] == "true", text[-3000:]
    assert sha(tmp / "inbox" / "mission.bin") == sha(up) == r["send_sha256"]
    assert sha(tmp / "got" / "flight.log") == sha(back) == r["fetch_sha256"]
    # both files' data went on the pipeline; the 3 KB/s link could not have carried them in the time
    assert int(r["pipe_bytes_out"]) >= MB2 and int(r["pipe_bytes_in"]) >= MB2, r
    commands_keep_their_latency(r)
    print("goodput up", r["send_goodput"], "B/s, down", r["fetch_goodput"], "B/s")
    return r, text


def commands_keep_their_latency(r: dict[str, str]) -> None:
    """Commands while both files move on the pipeline answer about as fast as with none moving."""
    print("command latency p95 without files", r["base_p95_ms"], "ms, during them", r["during_p95_ms"], "ms,",
          r["during_n"], "commands")
    base, during = int(r["base_p95_ms"]), int(r["during_p95_ms"])
    assert int(r["during_n"]) >= 5, r
    assert during <= max(2 * base, base + 400 * busy()), r  # (the tail waits for cores on a busy machine too)


def test_e2e_against_ttctl_emulate_onboard_with_a_pipeline(classes: Path, tmp_path: Path, start: Start) -> None:
    pipe = free_port(socket.SOCK_STREAM)
    port, back = mop_onboard(start, tmp_path, pipe)
    r, text = mop_transfer(classes, tmp_path, back, (port, pipe))
    assert int(r["pipe_connects"]) == 1, text[-2000:]
    # the figure: file goodput at least 0.8 of the pipeline's rate (100 000 B/s), each way, on an
    # idle machine; with other work taking the cores, the Java and Python ends move what they are given time for
    floor = 80000 / busy()
    assert int(r["send_goodput"]) >= floor and int(r["fetch_goodput"]) >= floor, (r, floor)
    assert int(r["low_bytes"]) < MB2 // 20, r  # control, offers, statuses: not the files


def test_e2e_as_the_docs_wire_it_payload_link_and_pipeline(classes: Path, tmp_path: Path, start: Start) -> None:
    """The low-speed link is PayloadLink on the MSDK v5 stand-in (128-byte packets at 3 KB/s,
    completions on the SDK's thread), beside the pipeline: docs/dji/tablet-java.md's wiring."""
    pipe = free_port(socket.SOCK_STREAM)
    port, back = mop_onboard(start, tmp_path, pipe)
    r, text = mop_transfer(classes, tmp_path, back, (port, pipe), "low=payload")
    assert int(r["pipe_connects"]) == 1 and r["mtu"] == "128", text[-2000:]


def test_e2e_signed_both_paths(classes: Path, tmp_path: Path, start: Start) -> None:
    """MAVLink 2 signing on both paths (emulate onboard --key takes only signed frames): the
    pipeline's frames under their own link id, as ttctl's ends sign theirs, so neither path's
    timestamps make the other's look like replays."""
    key = random.Random(12).randbytes(32).hex()
    (tmp_path / "key").write_text(key + "\n")
    pipe = free_port(socket.SOCK_STREAM)
    port, back = mop_onboard(start, tmp_path, pipe, "--key", str(tmp_path / "key"))
    r, text = mop_transfer(classes, tmp_path, back, (port, pipe), f"key={key}")
    assert int(r["pipe_connects"]) == 1, text[-2000:]


def test_e2e_a_fetch_alone_takes_the_pipeline(classes: Path, tmp_path: Path, start: Start) -> None:
    """No upload to open the way: the tablet's hello (its HEARTBEAT, first on each connection) is
    what ttctl's accepting end waits for before it puts file data on a connection."""
    pipe = free_port(socket.SOCK_STREAM)
    port, back = mop_onboard(start, tmp_path, pipe)
    r, text = tablet(classes, tmp_path, (port, pipe), "run=e2e", "fetch=flight.log", f"dir={tmp_path / 'got'}",
                     "timeout=60", "rate=3000")
    assert r["fetch_ok"] == "true", text[-3000:]
    assert sha(tmp_path / "got" / "flight.log") == sha(back) == r["fetch_sha256"]
    assert int(r["pipe_bytes_in"]) >= MB2 and int(r["fetch_goodput"]) >= 50000, r


def test_e2e_a_stalled_pipeline_is_closed_and_the_files_go_on(classes: Path, tmp_path: Path, start: Start) -> None:
    """`link relay --pipe-stall`: open, but nothing moves (DJI's send timeouts). The tablet's write
    takes nothing for 2 s: it closes the pipeline in one line, the transfers go on over the link,
    and it connects again."""
    pipe_air, pipe_tab, a = free_port(socket.SOCK_STREAM), free_port(socket.SOCK_STREAM), free_port()
    port, back = mop_onboard(start, tmp_path, pipe_air)
    relay(start, a, port, "--profile", "mop", "--pipe-listen", f"tcp:{LOCAL}:{pipe_tab}", "--pipe-to",
          f"tcp:{LOCAL}:{pipe_air}", "--pipe-stall", "8:6", "--stats-interval", "0")
    r, text = mop_transfer(classes, tmp_path, back, (a, pipe_tab))
    said = [ln for ln in text.splitlines() if ln.startswith("ttctl PipelineLink:")]
    assert len(said) == 1 and "writeData took nothing for 2000 ms" in said[0], text[-3000:]
    assert int(r["pipe_connects"]) >= 2, r


def test_e2e_pipeline_dropped_twice_by_ttctl_link_relay(classes: Path, tmp_path: Path, start: Start) -> None:
    pipe_air, pipe_tab, a = free_port(socket.SOCK_STREAM), free_port(socket.SOCK_STREAM), free_port()
    port, back = mop_onboard(start, tmp_path, pipe_air)
    air = relay(start, a, port, "--profile", "mop", "--pipe-listen", f"tcp:{LOCAL}:{pipe_tab}", "--pipe-to",
                f"tcp:{LOCAL}:{pipe_air}", "--pipe-drop", "8:1", "--pipe-drop", "16:1", "--stats-interval", "0")
    r, text = mop_transfer(classes, tmp_path, back, (a, pipe_tab))
    assert int(r["pipe_connects"]) >= 3, text[-3000:]
    assert text.count("EVENT pipeline closed") >= 2, text[-3000:]
    assert "Traceback" not in air.stderr, air.stderr[-2000:]
