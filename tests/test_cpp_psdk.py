"""The generated node on DJI's Payload SDK v3 low-speed channel (cpp/ttapi/psdk_link.hpp), built
with g++ -Werror against DJI's real headers (tests/vendor/dji/psdk-3.13.1/, as system headers)
and the stand-in for the four SDK functions it calls (tests/cpp/fake_psdk/: 128-byte packages,
the 512-byte flow-control buffer that discards, busyState, the callback on the SDK's own thread;
packets over UDP), run as tests/cpp/psdk/psdk_node.cpp against ttctl's Python ends through
`ttctl link relay --profile psdk` (128-byte packets, DJI's documented rates):

- the emulated tablet's script (a command, an upload, a fetch) and send-file both ways, in
  128-byte packets (TT_FILE_DATA_FIT carries 107 file bytes in each), nothing discarded by the
  flow controller;
- bad input: an SDK that refuses every fifth send (DJI's words reach the user, the file still
  arrives), a callback flood (the SDK's thread is never held, the queue drops what it cannot
  hold, memory stays bounded), and an SDK that answers every call with an error (the node says
  why in DJI's words and stops).
"""

from __future__ import annotations

import hashlib
import json
import os
import random
import shutil
import signal
import subprocess
import time
from pathlib import Path
from typing import Any

import pytest

from conftest import ROOT, run_ttctl
from e2e_lib import LOCAL, Start, free_port, relay, send
from machine import scaled

pytestmark = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

WARN = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
PSDK_INCLUDE = ROOT / "tests" / "vendor" / "dji" / "psdk-3.13.1" / "psdk_lib" / "include"
FAKE_PSDK = ROOT / "tests" / "cpp" / "fake_psdk"
PROGRAM = ROOT / "tests" / "cpp" / "psdk" / "psdk_node.cpp"


@pytest.fixture(scope="module")
def psdk_node(tmp_path_factory: pytest.TempPathFactory) -> Path:
    tmp = tmp_path_factory.mktemp("psdk")
    out = tmp / "out"
    proc = run_ttctl("gen", str(ROOT / "dialects" / "ttapi.xml"), "--lang", "cpp", "-o", str(out), timeout=300)
    assert proc.returncode == 0, proc.stderr
    exe = tmp / "psdk_node"
    run = subprocess.run(["g++", *WARN, "-O1", "-I", str(out / "cpp"), "-I", str(FAKE_PSDK), "-isystem",
                          str(PSDK_INCLUDE), str(PROGRAM), str(FAKE_PSDK / "fake_psdk.cpp"), "-pthread", "-o",
                          str(exe), "-lz"], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-5000:]
    return exe


class PsdkNode:
    """psdk_node as a process: its JSON lines in a file."""

    def __init__(self, exe: Path, folder: Path, env: dict[str, str], *args: str) -> None:
        self.port = free_port()
        self.inbox = folder / "inbox"
        self.serve = folder / "outbox"
        self.serve.mkdir(exist_ok=True)
        self.out = folder / "node.out"
        self.err = folder / "node.err"
        with open(self.out, "w") as o, open(self.err, "w") as e:
            self.p = subprocess.Popen([str(exe), str(self.inbox), str(self.serve), *args], stdout=o, stderr=e,
                                      env={**os.environ, "FAKE_PSDK_LISTEN": f"{LOCAL}:{self.port}", **env})

    def lines(self) -> list[dict[str, Any]]:
        return [json.loads(line) for line in self.out.read_text().splitlines() if line.startswith("{")]

    def wait_ready(self, timeout: float = 30) -> None:
        timeout = scaled(timeout)  # longer on a busy machine
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if any(x["event"] == "ready" for x in self.lines()):
                return
            assert self.p.poll() is None, self.err.read_text()
            time.sleep(0.05)
        raise AssertionError("psdk_node did not become ready")

    def stop(self) -> dict[str, Any]:
        self.p.send_signal(signal.SIGINT)
        assert self.p.wait(30) == 0, self.err.read_text()
        assert self.err.read_text() == ""
        return next(x for x in self.lines() if x["event"] == "stats")

    def kill(self) -> None:
        if self.p.poll() is None:
            self.p.kill()
            self.p.wait(10)


@pytest.fixture
def nodes() -> Any:
    started: list[PsdkNode] = []

    def start(*args: Any, **kw: Any) -> PsdkNode:
        n = PsdkNode(*args, **kw)
        started.append(n)
        return n

    yield start
    for n in started:
        n.kill()


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def test_the_emulated_tablet_over_the_psdk_channel(psdk_node: Path, tmp_path: Path, start: Start,
                                                   nodes: Any) -> None:
    """A take-off, an upload, a fetch and a landing from `emulate tablet --profile psdk` through
    the psdk relay (5 % loss) to the node on the PSDK stand-in: every file whole, every packet the
    node sent at most 128 bytes, the flow controller never full (nothing discarded), the callback
    never holding the SDK's thread."""
    node = nodes(psdk_node, tmp_path, {})
    served = node.serve / "log.bin"
    served.write_bytes(random.Random(1).randbytes(6000))
    up = tmp_path / "up.bin"
    up.write_bytes(random.Random(2).randbytes(3000))
    node.wait_ready()
    a = free_port()
    relay(start, a, node.port, "--profile", "psdk", "--loss", "0.05", "--seed", "4", "--stats-interval", "0")
    script = tmp_path / "script.yaml"
    script.write_text("- takeoff: 3\n- send: up.bin\n- fetch: log.bin\n- land\n")
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{a}", "--profile", "psdk", "--dir",
                     str(tmp_path / "tablet"), "--json", "--script", str(script), cwd=tmp_path, timeout=180)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    steps = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
    assert [s["ok"] for s in steps if s.get("event") == "step"] == [True] * 4, proc.stdout
    assert sha(node.inbox / "up.bin") == sha(up)
    assert sha(tmp_path / "tablet" / "log.bin") == sha(served)
    stats = node.stop()
    assert stats["problems"] == 0 and stats["refused"] == 0 and stats["lost"] == 0, stats
    assert stats["sdk_discarded"] == 0, stats  # the 512-byte buffer never overflowed
    assert stats["sdk_packets_out"] == stats["sent"] > 0, stats  # each send one package: none over 128 bytes
    assert stats["sdk_slowest_callback_us"] < 200_000, stats


def test_send_file_both_ways_over_the_psdk_channel(psdk_node: Path, tmp_path: Path, start: Start,
                                                   nodes: Any) -> None:
    """send-file --to and --from (--profile psdk, 128-byte packets) through the psdk relay: the
    upload and the fetch arrive whole, the fetch in TT_FILE_DATA_FIT frames (107 file bytes a
    packet), and the node never overflows the flow controller's buffer."""
    node = nodes(psdk_node, tmp_path, {})
    served = node.serve / "d.bin"
    served.write_bytes(random.Random(5).randbytes(12_000))
    src = tmp_path / "s.bin"
    src.write_bytes(random.Random(6).randbytes(5000))
    node.wait_ready()
    a = free_port()
    relay(start, a, node.port, "--profile", "psdk", "--loss", "0.03", "--seed", "7", "--stats-interval", "0")
    to = f"udpout:{LOCAL}:{a}"
    proc, r = send(str(src), "--to", to, "--profile", "psdk", timeout=120)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(node.inbox / "s.bin") == sha(src)
    (tmp_path / "got").mkdir()
    proc, f = send("d.bin", "--from", to, "--dir", str(tmp_path / "got"), "--profile", "psdk", timeout=120)
    assert proc.returncode == 0 and f["ok"], proc.stderr
    assert sha(tmp_path / "got" / "d.bin") == sha(served)
    stats = node.stop()
    assert stats["sdk_discarded"] == 0 and stats["problems"] == 0, stats
    assert stats["sent"] >= 12_000 // 107, stats


def test_a_node_faster_than_the_channel_stops_while_busy(psdk_node: Path, tmp_path: Path, start: Start,
                                                         nodes: Any) -> None:
    """The node paced at 8000 B/s on a channel limited to 2000 B/s (the stand-in's bandwidth
    limit): the link stops while busyState is set and never lets the 512-byte flow-control buffer
    overflow, so nothing is discarded and the fetch completes."""
    node = nodes(psdk_node, tmp_path, {"FAKE_PSDK_RATE": "2000"}, "128", "8000")
    served = node.serve / "d.bin"
    served.write_bytes(random.Random(10).randbytes(8000))
    node.wait_ready()
    a = free_port()
    relay(start, a, node.port, "--profile", "psdk", "--stats-interval", "0")
    (tmp_path / "got").mkdir()
    proc, f = send("d.bin", "--from", f"udpout:{LOCAL}:{a}", "--dir", str(tmp_path / "got"), "--profile", "psdk",
                   timeout=120)
    assert proc.returncode == 0 and f["ok"], proc.stderr
    assert sha(tmp_path / "got" / "d.bin") == sha(served)
    stats = node.stop()
    assert stats["sdk_discarded"] == 0, stats
    assert stats["busy_waits"] + stats["buffer_waits"] > 0, stats  # it did have to wait


def test_a_send_the_sdk_refuses_is_told_in_djis_words(psdk_node: Path, tmp_path: Path, start: Start,
                                                      nodes: Any) -> None:
    """The stand-in refuses every fifth SendData (DJI_ERROR_SYSTEM_MODULE_CODE_BUSY): each refusal
    reaches the user with the call, the code's name and DJI's words from dji_error.h; the packet
    is lost, and the protocol sends again, so the fetch still completes."""
    node = nodes(psdk_node, tmp_path, {"FAKE_PSDK_REFUSE_EVERY": "5"})
    served = node.serve / "d.bin"
    served.write_bytes(random.Random(8).randbytes(6000))
    node.wait_ready()
    a = free_port()
    relay(start, a, node.port, "--profile", "psdk", "--stats-interval", "0")
    (tmp_path / "got").mkdir()
    proc, f = send("d.bin", "--from", f"udpout:{LOCAL}:{a}", "--dir", str(tmp_path / "got"), "--profile", "psdk",
                   timeout=120)
    assert proc.returncode == 0 and f["ok"], proc.stderr
    assert sha(tmp_path / "got" / "d.bin") == sha(served)
    stats = node.stop()
    problems = [x for x in node.lines() if x["event"] == "problem"]
    assert stats["refused"] >= 5 and len(problems) == stats["problems"] == stats["refused"], stats
    assert {(p["call"], p["name"], p["words"], p["hint"]) for p in problems} == {
        ("DjiLowSpeedDataChannel_SendData", "DJI_ERROR_SYSTEM_MODULE_CODE_BUSY", "System is busy.",
         "Please try again later.")}


def test_a_callback_flood_never_holds_the_sdks_thread(psdk_node: Path, tmp_path: Path, start: Start,
                                                      nodes: Any) -> None:
    """After the first packet the stand-in calls the receive callback 200,000 times as fast as its
    thread can, with 128 bytes of noise each: no call holds the SDK's thread long (it copies or
    drops, and returns), the queue drops what it cannot hold (counted), memory stays bounded, and
    the node still takes a file afterwards."""
    node = nodes(psdk_node, tmp_path, {"FAKE_PSDK_FLOOD": "200000"})
    node.wait_ready()
    a = free_port()
    relay(start, a, node.port, "--profile", "psdk", "--stats-interval", "0")
    src = tmp_path / "s.bin"
    src.write_bytes(random.Random(9).randbytes(3000))
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{a}", "--profile", "psdk", timeout=120)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(node.inbox / "s.bin") == sha(src)
    stats = node.stop()
    # every call counted as received; the stand-in counts a call when it returns and its thread still
    # runs when the node prints (the relay's datagrams go on): one call may be in flight then
    assert stats["sdk_callbacks"] >= 200_000 and 0 <= stats["received"] - stats["sdk_callbacks"] <= 1, stats
    assert stats["dropped"] > 0, stats  # the fixed queue was full: dropped, not grown
    assert stats["sdk_slowest_callback_us"] < 200_000, stats  # copies and returns, even on a busy machine
    assert stats["peak_kib"] < 64 * 1024, stats


def test_an_sdk_that_fails_every_call_is_told_in_djis_words(psdk_node: Path, tmp_path: Path) -> None:
    """Every call answers DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR: the node does not start; the
    user's problem handler got the call and DJI's words, and the program says them in one line."""
    port = free_port()
    (tmp_path / "outbox").mkdir()
    run = subprocess.run([str(psdk_node), str(tmp_path / "inbox"), str(tmp_path / "outbox")], capture_output=True,
                         text=True, timeout=60,
                         env={**os.environ, "FAKE_PSDK_LISTEN": f"{LOCAL}:{port}", "FAKE_PSDK_FAIL": "all"})
    assert run.returncode == 1
    assert run.stderr == "DjiLowSpeedDataChannel_Init: System error. Please contact DJI for help.\n"
    problems = [json.loads(line) for line in run.stdout.splitlines()]
    assert problems == [{"event": "problem", "call": "DjiLowSpeedDataChannel_Init", "code": "0xec",
                         "name": "DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR", "words": "System error.",
                         "hint": "Please contact DJI for help."}]


def test_a_node_whose_packets_exceed_the_channels_is_refused(psdk_node: Path, tmp_path: Path) -> None:
    """mtu 200 on a channel of 128-byte packages: open() refuses, in words."""
    (tmp_path / "outbox").mkdir()
    run = subprocess.run([str(psdk_node), str(tmp_path / "inbox"), str(tmp_path / "outbox"), "200"],
                         capture_output=True, text=True, timeout=60,
                         env={**os.environ, "FAKE_PSDK_LISTEN": f"{LOCAL}:{free_port()}"})
    assert run.returncode == 1
    assert run.stderr == "the node's packets (mtu 200) are larger than the channel's 128 bytes\n"
