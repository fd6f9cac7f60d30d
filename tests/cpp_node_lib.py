"""What the tests of the generated C++ onboard end share (tests/test_cpp_node_*.py, and
tests/test_cross_java_cpp.py): the programs, built once a session, the node as a process, a raw
MAVLink socket to it.

The programs are built from a freshly generated ttapi tree with g++ -std=c++17 -Wall -Wextra
-Wpedantic -Werror: tests/cpp/node/onboard_node.cpp (the onboard end, ttapi::link::Node on UDP)
around the GENERATED skeleton (cpp/onboard/ttapi_plugin.hpp) as a user edits it (EDITS:
on_command() counts and accepts, and refuses trajectory flights with words; the
DJI_POSE_STAMPED handler answers set-points with ctx.setpoint(), flying them, counted, or
refusing an altitude below 0.5 m, and echoes a pose of another topic; the TT_VR_CONTROLLER handler
counts messages and button changes), plain and once more with
-fsanitize=address,undefined for the hostile-input tests; and the drivers that run the
scheduler and the node sans-IO against Python's (scheduler_driver.cpp, node_driver.cpp).
The session fixtures cpp_node_bins and cpp_nodes (tests/conftest.py) hand them to the tests.

The tests, by topic:
- test_cpp_node_parity.py: the same decisions as Python's, in virtual time (the name rules'
  table, the scheduler's packets, the node receiving and serving);
- test_cpp_node_e2e.py: against the emulated tablet through the m100 relay, a retried command,
  a user's dialect that includes ttapi.xml;
- test_cpp_node_transfer.py: files against ttctl's Python ends: efficiency, SIGKILL and resume,
  several at once, an upload from the node;
- test_cpp_node_hostile.py: garbage, strangers, signing, and hostile input under the
  sanitizers.
- test_cpp_node_deflate.py: deflated transfers both ways against ttctl's Python ends, hostile
  streams, and the node built without zlib (TTCTL_NO_ZLIB).
"""

from __future__ import annotations

import hashlib
import json
import os
import random
import shutil
import signal
import socket
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import pytest

import ttapi
from conftest import ROOT, TTAPI, run_ttctl
from e2e_lib import LOCAL
from machine import scaled
from ttctl.wire.packets import packetize

needs_gxx = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

WARN = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
PROGRAM = ROOT / "tests" / "cpp" / "node" / "onboard_node.cpp"
SCHEDULER = ROOT / "tests" / "cpp" / "node" / "scheduler_driver.cpp"
NODE_DRIVER = ROOT / "tests" / "cpp" / "node" / "node_driver.cpp"

# The user's edits of the generated skeleton.
EDITS = [
    ("public:\n    const char* name() const noexcept override",
     "public:\n    std::uint64_t executed = 0;  // how many commands ran\n"
     "    std::uint64_t flown = 0;  // how many set-points were flown\n"
     "    std::uint64_t vr_messages = 0;  // TT_VR_CONTROLLER the handler got\n"
     "    std::uint64_t vr_changes = 0;  // of those: a controller's buttons changed\n"
     "    std::array<std::uint16_t, 256> vr_buttons{};  // the buttons last held, per controller\n\n"
     "    const char* name() const noexcept override"),
    ("""        // TODO: carry out cmd.action (a TtAction) with cmd.param and cmd.argument, from system frame.sysid
        return {TtResult::TT_RESULT_UNSUPPORTED, "not implemented on this vehicle yet"};""",
     """        ++executed;
        if (cmd.action == static_cast<std::uint8_t>(TtAction::TT_ACTION_FLY_TRAJECTORY)) {
            return {TtResult::TT_RESULT_DENIED, "refused: this test vehicle flies no trajectories"};
        }
        return TtResult::TT_RESULT_ACCEPTED;"""),
    ("        // TODO: handle DJI_POSE_STAMPED (from system frame.sysid, component frame.compid); "
     "ctx.send(...) replies",
     """        if (ctx.setpoint(msg, frame, [&]() -> std::optional<std::string> {
                if (msg.position[2] < 0.5) {
                    return "altitude below 0.5 m: land instead";
                }
                ++flown;
                return std::nullopt;
            }) != link::SetpointVerdict::not_setpoint) {
            return;
        }
        DjiPoseStamped echo = msg;  // another topic: echoed
        echo.target_system = frame.sysid;
        ctx.send(echo);"""),
    ("        // TODO: handle TT_VR_CONTROLLER (from system frame.sysid, component frame.compid); "
     "ctx.send(...) replies",
     """        ++vr_messages;  // the node has confirmed it already
        if (msg.buttons != vr_buttons[msg.index]) {
            vr_buttons[msg.index] = msg.buttons;
            ++vr_changes;
        }"""),
]


def gxx(*args: str) -> None:
    """g++ with `args`; a program (not -fsyntax-only) is linked with zlib (the runtime's
    deflate.hpp inflates with it)."""
    link = [] if "-fsyntax-only" in args or "-c" in args else ["-lz"]
    proc = subprocess.run(["g++", *args, *link], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-5000:]


def generate(tmp: Path) -> list[str]:
    """ttapi's C++ generated into `tmp`/out, the skeleton edited as a user would (EDITS); the
    g++ -I options that find the headers and the skeleton."""
    out = tmp / "out"
    proc = run_ttctl("gen", str(TTAPI), "--lang", "cpp", "-o", str(out), timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    skeleton = out / "cpp" / "onboard" / "ttapi_plugin.hpp"
    text = skeleton.read_text()
    for old, new in EDITS:
        assert old in text, old
        text = text.replace(old, new)
    skeleton.write_text(text)
    return ["-I", str(out / "cpp"), "-I", str(skeleton.parent)]


def build(tmp: Path) -> dict[str, Path]:
    """The programs, generated and built in `tmp` (in parallel): onboard_node plain and with
    the sanitizers, scheduler_driver, node_driver."""
    inc = generate(tmp)
    exes = {"plain": tmp / "onboard_node", "asan": tmp / "onboard_node_asan", "scheduler": tmp / "scheduler_driver",
            "driver": tmp / "node_driver"}
    with ThreadPoolExecutor(max_workers=2) as pool:
        jobs = [pool.submit(gxx, *WARN, "-O2", *inc, str(PROGRAM), "-o", str(exes["plain"])),
                pool.submit(gxx, *WARN, "-O1", "-g", "-fsanitize=address,undefined", "-fno-sanitize-recover=all",
                            "-fno-omit-frame-pointer", *inc, str(PROGRAM), "-o", str(exes["asan"])),
                pool.submit(gxx, *WARN, "-O1", *inc, str(SCHEDULER), "-o", str(exes["scheduler"])),
                pool.submit(gxx, *WARN, "-O1", *inc, str(NODE_DRIVER), "-o", str(exes["driver"]))]
        for job in jobs:
            job.result()
    return exes


class Node:
    """onboard_node as a process: JSON events on stdout (a file), stopped with SIGTERM."""

    def __init__(self, exe: Path, folder: Path, name: str, *args: str) -> None:
        self.name = name
        self.out_path = folder / f"{name}.out"
        self.err_path = folder / f"{name}.err"
        self._out = open(self.out_path, "w")  # noqa: SIM115 - closed in stop()
        self._err = open(self.err_path, "w")  # noqa: SIM115
        env = {**os.environ, "ASAN_OPTIONS": "detect_leaks=1:abort_on_error=0", "UBSAN_OPTIONS": "print_stacktrace=1"}
        self.p = subprocess.Popen([str(exe), *args], stdout=self._out, stderr=self._err, cwd=folder, env=env)
        self.port = int(self.wait_event("ready", 20)["port"])

    def events(self, kind: str | None = None) -> list[dict[str, Any]]:
        out = []
        for line in self.out_path.read_text().splitlines():
            try:
                e = json.loads(line)
            except ValueError:
                continue
            if kind is None or e.get("event") == kind:
                out.append(e)
        return out

    def wait_event(self, kind: str, timeout: float = 30.0, **match: Any) -> dict[str, Any]:
        timeout = scaled(timeout)  # longer on a busy machine
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for e in self.events(kind):
                if all(e.get(k) == v for k, v in match.items()):
                    return e
            if self.p.poll() is not None:
                break
            time.sleep(0.02)
        raise AssertionError(f"{self.name}: no {kind} {match} (exit {self.p.poll()}):\n{self.out_path.read_text()}\n"
                             f"{self.err_path.read_text()[-4000:]}")

    def stop(self) -> dict[str, Any]:
        """SIGTERM; the stats line. The process must exit cleanly with nothing on stderr (the
        sanitizers report there)."""
        if self.p.poll() is None:
            self.p.send_signal(signal.SIGTERM)
        try:
            code = self.p.wait(20)
        finally:
            self._out.close()
            self._err.close()
        err = self.err_path.read_text()
        assert code == 0 and err == "", f"{self.name}: exit {code}\n{err[-6000:]}"
        stats = self.events("stats")
        assert stats, self.out_path.read_text()[-3000:]
        return stats[-1]

    def kill(self) -> None:
        if self.p.poll() is None:
            self.p.kill()
            self.p.wait(10)
        self._out.close()
        self._err.close()


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def write(path: Path, size: int, seed: int) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(random.Random(seed).randbytes(size))
    return path


class Raw:
    """A UDP socket that speaks MAVLink to the node directly: frames in packets, and what comes
    back decoded."""

    def __init__(self, port: int, sysid: int = 255, compid: int = 190) -> None:
        self.s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.s.bind((LOCAL, 0))
        self.s.settimeout(0.05)
        self.to = (LOCAL, port)
        self.enc = ttapi.Encoder(sysid=sysid, compid=compid)
        self.parser = ttapi.Parser()

    def frames(self, *msgs: Any) -> None:
        """The messages' frames in DTT packets, by the packing rule."""
        for p in packetize([self.enc.encode(m) for m in msgs]):
            self.s.sendto(p, self.to)

    def raw(self, data: bytes) -> None:
        self.s.sendto(data, self.to)

    def collect(self, seconds: float, until: Any = None) -> list[Any]:
        out: list[Any] = []
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            try:
                data, _ = self.s.recvfrom(2048)
            except TimeoutError:
                continue
            out.extend(ttapi.Parser().feed(data))
            if until is not None and until(out):
                break
        return out

    def close(self) -> None:
        self.s.close()



class ServingOnboards:
    """The onboard end serving `serve` in two virtual-time worlds alike: ttctl's Python Endpoint
    ("python") and the C++ node's driver program ("cpp"), both paced at 6700 B/s in `mtu`-byte
    packets, signing with `key` from `timestamp` on if given, and drawing the same transfer ids
    (the driver is told the ids the Endpoint's seeded random draws). A world hands it what its
    tablet sent (`receive`) and takes what it sends now (`poll`)."""

    def __init__(self, driver: Path, tmp: Path, serve: Path, bindings: Any, seed: int, mtu: int = 100,
                 key: bytes | None = None, timestamp: int = 0) -> None:
        from ttctl.proto.endpoint import Endpoint
        from ttctl.proto.storage import ReceiveDir

        draws = random.Random(seed)
        draws.randint(1, 65535)  # the endpoint's first command id: its first draw
        ids = [draws.getrandbits(32) for _ in range(8)]
        signed = [key.hex(), str(timestamp)] if key is not None else []
        self.drv = subprocess.Popen([str(driver), str(tmp / "cpp_in"), str(serve), "6700", "0", str(mtu), *signed],
                                    stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        assert self.drv.stdin is not None and self.drv.stdout is not None
        self.stdin, self.stdout = self.drv.stdin, self.drv.stdout
        for i in ids:
            self.stdin.write(f"I {i}\n")
        self.python = Endpoint(bindings, 1, 240, mtu=mtu, rate_Bps=6700.0, receive_dir=ReceiveDir(tmp / "py_in"),
                               serve_dir=str(serve), rng=random.Random(seed),
                               signing=bindings.mavlink.Signing(key, 0, False, timestamp) if key is not None else None)

    def receive(self, name: str, now: float, pkt: bytes) -> None:
        if name == "python":
            self.python.receive(now, pkt)
        else:
            self.stdin.write(f"R {now!r} {pkt.hex()}\n")

    def poll(self, name: str, now: float) -> list[bytes]:
        if name == "python":
            out = []
            while (pkt := self.python.poll(now)) is not None:
                out.append(pkt)
            return out
        self.stdin.write(f"P {now!r}\n")
        self.stdin.flush()
        line = self.stdout.readline().strip()
        return [] if line == "-" else [bytes.fromhex(h) for h in line.split()]

    def set_pipe(self, name: str, now: float, open_: bool) -> None:
        """A MOP pipeline opens or closes beside the link (20000 B/s, as node_driver's)."""
        if name == "python":
            if open_:
                self.python.pipe.open(now, 20000.0)
            else:
                self.python.pipe.close(now)
        else:
            self.stdin.write(f"{'O' if open_ else 'C'} {now!r}\n")

    def poll_pipe(self, name: str, now: float) -> list[bytes]:
        """The frames the onboard end puts on the pipeline now."""
        if name == "python":
            out = []
            while (frame := self.python.pipe.poll(now)) is not None:
                out.append(frame)
            return out
        self.stdin.write(f"Q {now!r}\n")
        self.stdin.flush()
        line = self.stdout.readline().strip()
        return [] if line == "-" else [bytes.fromhex(h) for h in line.split()]

    def close(self) -> None:
        self.stdin.close()
        self.drv.wait(20)
