"""The generated node's MOP pipeline (cpp/ttapi/pipe_link.hpp, mop_link.hpp) beside its low-speed
channel (psdk_link.hpp), built with g++ -Werror against DJI's real headers (dji_mop_channel.h,
dji_low_speed_data_channel.h, vendored as system headers) and the stand-ins for their functions
(tests/cpp/fake_psdk/: the low-speed channel over UDP, the MOP channel over TCP), run as
tests/cpp/psdk/mop_node.cpp against an app in this process (tests/mop_lib.py: ttctl's Python
transfer engine, file data on the pipeline while it is connected, everything else on the
low-speed channel, frames told apart by pymavlink):

- a 2 MB upload whose data goes over the pipeline (the stand-in counts the bytes), the node's
  statuses on the low-speed channel; SHA-256 equal;
- the same with the pipeline closed twice mid-transfer (once by the stand-in under the node, once
  by the app in the middle of a frame): the file still arrives whole;
- a fetch served by the node over the pipeline in PIPE_MTU geometry, through an SDK that takes
  at most 7 bytes a send (short writes keep frames whole);
- OsdkMopLink (osdk_mop_link.hpp) on the Onboard SDK 4.1's real MOP headers with stand-ins for DTT
  and the MOP server (tests/cpp/osdk_standin/): send-file --profile m300 --pipeline delivers a file;
- commands on the low-speed channel during a file on the pipeline: answered as fast as with no file;
- bad input: an SDK that fails every call (DJI's words on stderr once, no crash, no hang, the
  node stops on SIGINT), a flood of garbage on the pipeline (no crash, memory bounded, a command
  sent after it on the pipeline still answered on the low-speed channel).
"""

from __future__ import annotations

import contextlib
import json
import os
import random
import shutil
import signal
import socket
import statistics
import subprocess
import time
from pathlib import Path
from typing import Any

import pytest

from conformance_lib import pymavlink_module
from conftest import ROOT
from e2e_lib import LOCAL, free_port, send
from machine import busy as busy_machine
from machine import scaled
from mop_lib import NODE, WARN, App, MopNode, build_mop_node, sha

pytestmark = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

MB2 = 2 * 1024 * 1024


@pytest.fixture(scope="module")
def mop_node(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return build_mop_node(tmp_path_factory.mktemp("mop"))


@pytest.fixture(scope="module")
def pm(tmp_path_factory: pytest.TempPathFactory) -> Any:
    return pymavlink_module("ttapi", tmp_path_factory.mktemp("pm"))


@pytest.fixture
def nodes() -> Any:
    started: list[MopNode] = []

    def start(*args: Any, **kw: Any) -> MopNode:
        n = MopNode(*args, **kw)
        started.append(n)
        return n

    yield start
    for n in started:
        n.kill()


def upload(app: App, node: MopNode, src: Path, timeout: float) -> None:
    sender = app.ep.send_file(src, NODE)
    app.run(lambda: sender.done and (node.inbox / src.name).exists(), timeout)
    assert sender.result is not None and sender.result.ok, sender.result


def test_a_2mb_upload_goes_over_the_pipeline(mop_node: Path, pm: Any, tmp_path: Path, nodes: Any) -> None:
    """2 MB from the app: the data frames over the pipeline (the MOP stand-in read at least the
    file's bytes), the node's statuses back over the low-speed channel; SHA-256 equal."""
    node = nodes(mop_node, tmp_path, {})
    node.wait_ready()
    src = tmp_path / "big.bin"
    src.write_bytes(random.Random(1).randbytes(MB2))
    app = App(node, pm, tmp_path)
    try:
        upload(app, node, src, 120)
    finally:
        app.close()
    assert sha(node.inbox / "big.bin") == sha(src)
    stats = node.stop()
    assert stats["sdk_bytes_in"] >= MB2 and stats["bytes_in"] == stats["sdk_bytes_in"], stats
    assert stats["pipe_frames_in"] >= MB2 // 107 and stats["pipe_opens"] == 1, stats
    assert app.udp_out_data == 0, "file data went on the low-speed channel with the pipeline up"
    assert stats["packets_out"] > 0 and stats["pipe_frames_out"] == 0, stats  # statuses: low-speed only
    assert stats["sdk_live_handles"] == 0, stats  # every handle closed and destroyed


def test_the_pipeline_closed_twice_mid_transfer(mop_node: Path, pm: Any, tmp_path: Path, nodes: Any) -> None:
    """The stand-in closes the connection under the node after 500 kB, the app closes it in the
    middle of a frame after 1.2 MB: each time the data carries on over the low-speed channel
    until the app connects again, and the file arrives whole."""
    node = nodes(mop_node, tmp_path, {"TTCTL_FAKE_MOP_CLOSE_AFTER": "500000"})
    node.wait_ready()
    src = tmp_path / "big.bin"
    src.write_bytes(random.Random(2).randbytes(MB2))
    app = App(node, pm, tmp_path, cut_at=(1_200_000,))
    try:
        upload(app, node, src, 180)
    finally:
        app.close()
    assert sha(node.inbox / "big.bin") == sha(src)
    assert app.cuts == 1 and app.connections >= 3, (app.cuts, app.connections)
    stats = node.stop()
    assert stats["sdk_forced_closes"] == 1 and stats["connections"] >= 3, stats
    # reopened after the first close at least (after the second, the upload may end on the
    # low-speed channel before the node hears the third connection's hello: a busy machine)
    assert stats["pipe_closes"] >= 2 and stats["pipe_opens"] >= 2, stats
    assert stats["bad_bytes"] < 300, stats  # the half frames, dropped with their connections
    closed = node.pipe_events("closed")
    assert closed and all(c["name"] == "DJI_ERROR_MOP_CHANNEL_MODULE_CODE_CONNECTION_CLOSE" for c in closed), closed
    assert "peer channel" in closed[0]["words"], closed  # DJI's own sentence
    assert stats["sdk_live_handles"] == 0, stats


def test_a_fetch_served_over_the_pipeline_with_short_writes(mop_node: Path, pm: Any, tmp_path: Path,
                                                            nodes: Any) -> None:
    """The app fetches 600 kB; the node sends its data on the pipeline through an SDK that takes
    at most 7 bytes a send: frames arrive whole (pymavlink parses every one, no garbage), wide
    (TT_FILE_DATA_WIDE, as ttctl's Python cuts them for a stream), and the file is whole."""
    node = nodes(mop_node, tmp_path, {"TTCTL_FAKE_MOP_SHORT": "1"})
    served = node.serve / "log.bin"
    served.write_bytes(random.Random(3).randbytes(600_000))
    node.wait_ready()
    app = App(node, pm, tmp_path)
    try:
        app.run(lambda: app.tcp is not None and bool(node.pipe_events("opened")), 30)
        req = app.ep.request_file("log.bin", NODE)
        got = tmp_path / "app" / "log.bin"
        app.run(lambda: got.exists() or req.code is not None, 120)
    finally:
        app.close()
    assert req.code is None, (req.code, req.error)
    assert sha(got) == sha(served)
    stats = node.stop()
    assert stats["sdk_short_sends"] > 0 and stats["short_writes"] > 0, stats
    assert stats["pipe_bytes_out"] >= 600_000, stats
    data = sum(app.pipe_in_frames[k] for k in ("TT_FILE_DATA", "TT_FILE_DATA_WIDE", "TT_FILE_DATA_FIT"))
    assert 0 < data <= stats["pipe_frames_out"], (app.pipe_in_frames, stats)  # (the last may be on their way)
    assert app.pipe_in_frames["BAD_DATA"] == 0, app.pipe_in_frames
    assert set(app.pipe_in_frames) == {"TT_FILE_DATA_WIDE"}, app.pipe_in_frames  # a stream's frames: wide


def test_an_sdk_failing_every_call(mop_node: Path, tmp_path: Path, nodes: Any) -> None:
    """Every MOP call fails: the node says so once in DJI's words (on stderr), tries again every
    second without crashing or hanging, and stops on SIGINT."""
    node = nodes(mop_node, tmp_path, {"TTCTL_FAKE_MOP_FAIL": "1"})
    node.wait_for(lambda: bool(node.pipe_events("problem")), 10)
    time.sleep(3.5)
    assert node.p.poll() is None, node.err.read_text()
    err = node.err.read_text().splitlines()
    assert err == ["MOP: DjiMopChannel_Init: System error. Please contact DJI for help."], err
    stats = node.stop(10)
    assert stats["sdk_failed_calls"] >= 3 and stats["pipe_problems"] >= 3, stats  # tried again, told once
    assert stats["connections"] == 0 and stats["pipe_opens"] == 0, stats


def test_a_flood_of_garbage_on_the_pipeline(mop_node: Path, pm: Any, tmp_path: Path, nodes: Any) -> None:
    """30 MB of noise on the pipeline (with half frames of every kind in it): the node parses
    and drops it, its memory stays bounded, and a command sent on the pipeline after it is
    answered on the low-speed channel."""
    node = nodes(mop_node, tmp_path, {})
    node.wait_ready()
    rng = random.Random(4)
    mav = pm.MAVLink(None, srcSystem=255, srcComponent=190)
    udp = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    udp.bind((LOCAL, 0))
    udp.settimeout(0.2)
    udp.sendto(mav.heartbeat_encode(6, 8, 0, 0, 4).pack(mav), (LOCAL, node.port))  # where the app is
    with socket.create_connection((LOCAL, node.pipe_port), timeout=5) as s:
        chunk = bytearray(rng.randbytes(1 << 20))
        for i in range(0, len(chunk), 97):
            chunk[i] = 0xFD  # false starts everywhere
        for _ in range(30):
            s.sendall(chunk)
        cmd = mav.tt_action_command_encode(1, 240, 7, 1, 0, [0.0] * 4, b"").pack(mav)
        s.sendall(bytes(300) + cmd)
        acked = False
        end = time.monotonic() + scaled(30)
        parser = pm.MAVLink(None)
        parser.robust_parsing = True
        while not acked and time.monotonic() < end:
            try:
                data = udp.recv(65536)
            except TimeoutError:
                continue
            acked = any(m.get_type() == "TT_COMMAND_ACK" and m.command_id == 7
                        for m in parser.parse_buffer(data) or [])
        udp.close()
    assert acked, node.out.read_text()
    stats = node.stop()
    assert stats["bad_bytes"] >= 29 * (1 << 20) and stats["sdk_bytes_in"] >= 30 * (1 << 20), stats
    assert stats["peak_kib"] < 64 * 1024, stats


def test_the_osdk_mop_link_on_the_onboard_sdk_41(mop_node: Path, tmp_path: Path) -> None:
    """OsdkMopLink built against DJI's OSDK 4.1 headers (MopServer::accept, MopPipeline::sendData
    and recvData with their DataPackType, MopServer::close, Vehicle::mopServer), with the stand-ins
    for DTT and the MOP server: `send-file --profile m300 --pipeline tcpout:` delivers 500 kB whole,
    its data over the pipeline, and the close reaches the program in DJI's name for it."""
    vendor = ROOT / "tests" / "vendor" / "dji" / "osdk-4.1.0"
    dirs = sorted({p.parent for p in vendor.rglob("*.h*")})
    standin = ROOT / "tests" / "cpp" / "osdk_standin"
    exe = tmp_path / "osdk_mop_node"
    proc = subprocess.run(["g++", *WARN, "-O1", "-I", str(mop_node.parent / "out" / "cpp"),
                           *[a for d in dirs for a in ("-isystem", str(d))], "-DFAKE_OSDK_VERSION=41",
                           str(standin / "osdk_mop_node.cpp"), str(standin / "fake_osdk.cpp"),
                           str(standin / "fake_osdk_mop.cpp"), "-pthread", "-o", str(exe), "-lz"],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-5000:]
    (tmp_path / "outbox").mkdir()
    src = tmp_path / "up.bin"
    src.write_bytes(random.Random(6).randbytes(500_000))
    dtt, pipe = free_port(), free_port(socket.SOCK_STREAM)
    with open(tmp_path / "prog.out", "w") as out, open(tmp_path / "prog.err", "w") as err:
        prog = subprocess.Popen([str(exe)], cwd=tmp_path, stdout=out, stderr=err,
                                env={**os.environ, "FAKE_OSDK_LISTEN": f"{LOCAL}:{dtt}",
                                     "TTCTL_FAKE_MOP_PORT": str(pipe)})
    try:
        time.sleep(0.3)
        assert prog.poll() is None, (tmp_path / "prog.err").read_text()
        proc2, r = send(str(src), "--to", f"udpout:{LOCAL}:{dtt}", "--profile", "m300", "--pipeline",
                        f"tcpout:{LOCAL}:{pipe}", "--pipe-rate", "100000", "--timeout", "30", timeout=150)
        assert proc2.returncode == 0 and r["ok"], proc2.stderr
        assert r["pipeline_bytes_out"] >= 500_000, r
        assert sha(tmp_path / "inbox" / "up.bin") == sha(src)
    finally:
        prog.send_signal(signal.SIGINT)
        time.sleep(1.5)
        with contextlib.suppress(OSError):  # MopServer::accept cannot be interrupted: a connection ends it
            socket.create_connection((LOCAL, pipe), timeout=1).close()
        code = prog.wait(20)
    assert code == 0, (tmp_path / "prog.err").read_text()
    lines = [json.loads(x) for x in (tmp_path / "prog.out").read_text().splitlines()]
    closed = [x for x in lines if x.get("kind") == 2]
    assert closed and closed[0]["call"] == "MopPipeline::recvData", lines
    assert closed[0]["words"] == "MOP_CONNECTIONCLOSE", lines
    stats = lines[-1]
    assert stats["connections"] >= 1 and stats["pipe_frames_in"] >= 500_000 // 247, stats


def command_latencies(app: App, count: int, until: Any, timeout: float) -> list[float]:
    """`count` commands from the app, one every 0.25 s while `until()` is false (and then until
    all are answered): their round trips."""
    import ttapi
    from conftest import shipped

    b = shipped()
    cmds: list[Any] = []
    due = [time.monotonic()]

    def step() -> bool:
        now = time.monotonic()
        if len(cmds) < count and now >= due[0]:
            app.ep.now = now
            cmds.append(app.ep.command(b.TtActionCommand(action=int(ttapi.TtAction.TT_ACTION_HOVER)), NODE))
            due[0] = now + 0.25
        return len(cmds) == count and all(c.done for c in cmds) and until()

    app.run(step, timeout)
    assert all(c.ok for c in cmds), [c.error for c in cmds]
    return sorted(c.latency for c in cmds)


def test_commands_keep_their_latency_during_a_file_on_the_pipeline(mop_node: Path, pm: Any, tmp_path: Path,
                                                                   nodes: Any) -> None:
    """Commands on the low-speed channel while 1 MB moves on the pipeline are answered as fast as
    with no file moving (p95 within 50 ms of it): file data never queues in front of them."""
    node = nodes(mop_node, tmp_path, {})
    node.wait_ready()
    src = tmp_path / "big.bin"
    src.write_bytes(random.Random(5).randbytes(1 << 20))
    app = App(node, pm, tmp_path, rate_Bps=60_000.0)  # (a rate a busy test machine keeps up with on both ends)
    try:
        idle = command_latencies(app, 12, lambda: True, 60)
        sender = app.ep.send_file(src, NODE)
        busy = command_latencies(app, 24, lambda: True, 60)
        assert not sender.done, "the file finished before the commands: nothing was measured"
        app.run(lambda: sender.done and (node.inbox / src.name).exists(), 120)
    finally:
        app.close()
    assert sha(node.inbox / "big.bin") == sha(src)
    # the typical command is as fast as idle; the tail only bounded, since on a busy machine the
    # in-test app itself (Python, beside the node) is what stalls now and then
    assert statistics.median(busy) <= statistics.median(idle) + 0.05 * busy_machine(), (idle, busy)
    p95 = lambda xs: xs[int(0.95 * (len(xs) - 1))]  # noqa: E731
    assert p95(busy) <= p95(idle) + 0.5 * busy_machine(), (idle, busy)  # (the tail waits for cores too)
    stats = node.stop()
    assert stats["pipe_frames_in"] > 0, stats
