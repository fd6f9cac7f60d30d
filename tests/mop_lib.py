"""Helpers for tests/test_cpp_mop.py: the C++ node with a MOP pipeline (tests/cpp/psdk/mop_node.cpp,
built against DJI's vendored headers with the PSDK and MOP stand-ins), and an app that speaks to
it on both paths from this process: a ttctl Endpoint (the Python transfer engine) whose packets go
to the node's low-speed channel (UDP, as the PSDK stand-in takes them) unless they carry only file
data while the pipeline (TCP, as the MOP stand-in takes it) is connected. Which frames a packet
holds is decided by pymavlink (mavgen's own Python for ttapi.xml), not by ttctl's parser."""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import random
import select
import signal
import socket
import subprocess
import time
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

from conftest import ROOT, run_ttctl, shipped
from e2e_lib import LOCAL, free_port
from machine import scaled

WARN = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
PSDK_INCLUDE = ROOT / "tests" / "vendor" / "dji" / "psdk-3.13.1" / "psdk_lib" / "include"
FAKE_PSDK = ROOT / "tests" / "cpp" / "fake_psdk"
PROGRAM = ROOT / "tests" / "cpp" / "psdk" / "mop_node.cpp"
DATA = {"TT_FILE_DATA", "TT_FILE_DATA_WIDE", "TT_FILE_DATA_FIT"}
NODE = (1, 240)


def build_mop_node(tmp: Path) -> Path:
    out = tmp / "out"
    proc = run_ttctl("gen", str(ROOT / "dialects" / "ttapi.xml"), "--lang", "cpp", "-o", str(out), timeout=300)
    assert proc.returncode == 0, proc.stderr
    exe = tmp / "mop_node"
    run = subprocess.run(["g++", *WARN, "-O1", "-I", str(out / "cpp"), "-I", str(FAKE_PSDK), "-isystem",
                          str(PSDK_INCLUDE), str(PROGRAM), str(FAKE_PSDK / "fake_psdk.cpp"),
                          str(FAKE_PSDK / "fake_mop.cpp"), "-pthread", "-o", str(exe), "-lz"],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-5000:]
    return exe


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


class MopNode:
    """mop_node as a process: its JSON lines in a file, its stderr in another."""

    def __init__(self, exe: Path, folder: Path, env: dict[str, str], *args: str) -> None:
        self.port = free_port()
        self.pipe_port = free_port(socket.SOCK_STREAM)
        self.inbox = folder / "inbox"
        self.serve = folder / "outbox"
        self.serve.mkdir(exist_ok=True)
        self.out = folder / "node.out"
        self.err = folder / "node.err"
        with open(self.out, "w") as o, open(self.err, "w") as e:
            self.p = subprocess.Popen([str(exe), str(self.inbox), str(self.serve), *args], stdout=o, stderr=e,
                                      env={**os.environ, "FAKE_PSDK_LISTEN": f"{LOCAL}:{self.port}",
                                           "TTCTL_FAKE_MOP_PORT": str(self.pipe_port), **env})

    def lines(self) -> list[dict[str, Any]]:
        return [json.loads(line) for line in self.out.read_text().splitlines() if line.startswith("{")]

    def pipe_events(self, kind: str) -> list[dict[str, Any]]:
        return [x for x in self.lines() if x["event"] == "pipe" and x["kind"] == kind]

    def wait_for(self, what: Callable[[], bool], timeout: float = 30) -> None:
        timeout = scaled(timeout)  # longer on a busy machine
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if what():
                return
            assert self.p.poll() is None, self.err.read_text()
            time.sleep(0.05)
        raise AssertionError(f"mop_node: not so after {timeout} s:\n{self.out.read_text()}\n{self.err.read_text()}")

    def wait_ready(self) -> None:
        self.wait_for(lambda: bool(self.pipe_events("listening")))

    def stop(self, timeout: float = 30) -> dict[str, Any]:
        timeout = scaled(timeout)  # longer on a busy machine
        self.p.send_signal(signal.SIGINT)
        assert self.p.wait(timeout) == 0, self.err.read_text()
        return next(x for x in self.lines() if x["event"] == "stats")

    def kill(self) -> None:
        if self.p.poll() is None:
            self.p.kill()
            self.p.wait(10)


class App:
    """The app's two paths to the node, driven from the test's thread (see the module comment).
    `cut_at`: pipeline bytes written after which the app closes the pipeline itself, each time
    in the middle of a frame (half a packet written, the connection closed)."""

    def __init__(self, node: MopNode, pm: ModuleType, folder: Path, rate_Bps: float = 150_000.0,
                 cut_at: tuple[int, ...] = ()) -> None:
        from ttctl.proto.endpoint import Endpoint
        from ttctl.proto.storage import ReceiveDir
        from ttctl.proto.transfer import TransferConfig

        # narrow frames (TT_FILE_DATA_FIT, one 128-byte packet each): a packet holds whole frames
        self.ep = Endpoint(shipped(), 255, 190, mtu=128, rate_Bps=rate_Bps, receive_dir=ReceiveDir(folder / "app"),
                           config=TransferConfig(frame_mode="narrow"), rng=random.Random(7))
        self.ep.now = time.monotonic()  # (transfers start on the same clock as run())
        self.node = node
        self.pm = pm
        self.udp = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.udp.bind((LOCAL, 0))
        self.tcp: socket.socket | None = None
        self.connections = 0
        self.next_connect = 0.0
        self.cut_at = list(cut_at)
        self.cuts = 0
        self.pipe_out = 0  # bytes written to the pipeline
        self.pipe_in = 0  # bytes read from it
        self.udp_out_data = 0  # file-data packets that went on the low-speed channel
        self.pipe_in_frames: Counter[str] = Counter()  # what came on the pipeline, by pymavlink
        self.pipe_fit_counts: Counter[int] = Counter()  # TT_FILE_DATA_FIT.count on the pipeline
        self._pm_in: Any = None

    def _mav(self) -> Any:
        mav = self.pm.MAVLink(None)
        mav.robust_parsing = True
        return mav

    def frames(self, data: bytes) -> list[Any]:
        mav = self._mav()
        return [m for m in (mav.parse_buffer(data) or []) if m.get_type() != "BAD_DATA"]

    def only_data(self, pkt: bytes) -> bool:
        msgs = self.frames(pkt)
        return bool(msgs) and all(m.get_type() in DATA for m in msgs)

    def connect(self, now: float) -> None:
        try:
            s = socket.create_connection((LOCAL, self.node.pipe_port), timeout=0.5)
        except OSError:
            self.next_connect = now + 0.2
            return
        s.settimeout(5.0)
        self.tcp = s
        self.connections += 1
        self._pm_in = self._mav()
        mav = self.pm.MAVLink(None, srcSystem=255, srcComponent=190)
        s.sendall(mav.heartbeat_encode(6, 8, 0, 0, 4).pack(mav))  # hello: the node takes the connection

    def close_pipe(self, now: float) -> None:
        if self.tcp is not None:
            self.tcp.close()
            self.ep.forget_source(f"pipe{self.connections}")  # its half frame goes with it
        self.tcp = None
        self.next_connect = now + 1.0

    def send(self, now: float, pkt: bytes) -> None:
        if self.tcp is not None and self.only_data(pkt):
            if self.cut_at and self.pipe_out + len(pkt) >= self.cut_at[0]:
                self.cut_at.pop(0)
                self.cuts += 1
                with contextlib.suppress(OSError):
                    self.tcp.sendall(pkt[: len(pkt) // 2])  # half a frame, then the connection goes
                self.pipe_out += len(pkt) // 2
                self.close_pipe(now)
                return  # (the frame's bytes are lost: the receiver's status names them)
            try:
                self.tcp.sendall(pkt)
                self.pipe_out += len(pkt)
                return
            except OSError:
                self.close_pipe(now)  # the node closed it: data goes on the low-speed channel
        if self.only_data(pkt):
            self.udp_out_data += 1
        self.udp.sendto(pkt, (LOCAL, self.node.port))

    def run(self, until: Callable[[], bool], timeout: float) -> None:
        end = time.monotonic() + timeout
        self.udp.sendto(b"", (LOCAL, self.node.port))  # (the stand-in learns the app's address)
        while not until():
            now = time.monotonic()
            assert now < end, f"not done after {timeout} s"
            assert self.node.p.poll() is None, self.node.err.read_text()
            if self.tcp is None and now >= self.next_connect:
                self.connect(now)
            while (pkt := self.ep.poll(now)) is not None:
                self.send(now, pkt)
            wake = self.ep.wakeup()
            wait = 0.05 if wake is None else max(0.0, min(0.05, wake - time.monotonic()))
            socks = [self.udp] + ([self.tcp] if self.tcp is not None else [])
            ready, _, _ = select.select(socks, [], [], wait)
            now = time.monotonic()
            if self.udp in ready:
                data, _ = self.udp.recvfrom(65536)
                self.ep.receive(now, data, "lsp")
            if self.tcp is not None and self.tcp in ready:
                try:
                    data = self.tcp.recv(65536)
                except OSError:
                    data = b""
                if not data:
                    self.close_pipe(now)
                else:
                    self.pipe_in += len(data)
                    for m in self._pm_in.parse_buffer(data) or []:
                        self.pipe_in_frames[m.get_type()] += 1
                        if m.get_type() == "TT_FILE_DATA_FIT":
                            self.pipe_fit_counts[m.count] += 1
                    self.ep.receive_stream(now, data, f"pipe{self.connections}")
            self.ep.flush(now, 0.5)

    def close(self) -> None:
        self.udp.close()
        if self.tcp is not None:
            self.tcp.close()
