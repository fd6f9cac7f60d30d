"""Helpers for the end-to-end tests: real ttctl processes on 127.0.0.1, each with its output in
files, killed at the end of its test (the `start` fixture is in conftest.py)."""

from __future__ import annotations

import json
import os
import random
import socket
import subprocess
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from conftest import assert_no_traceback, run_ttctl, ttctl_cmd
from machine import scaled

LOCAL = "127.0.0.1"
SIZE = 64 * 1024


_PORTS_LOW, _PORTS_HIGH = 20000, 32000  # below Linux's ephemeral range (32768-60999)
_next_port: list[int] = []


def free_port(kind: int = socket.SOCK_DGRAM) -> int:
    """A port free now on 127.0.0.1, from below the kernel's ephemeral range and from this pytest
    worker's own slice of it, each handed out once per slice: a port the kernel gave out as an
    ephemeral one (bind 0) could be given to another socket (a process's udpout) before the test
    binds it ("Address already in use", seen beside CPU hogs)."""
    if not _next_port:
        worker = os.environ.get("PYTEST_XDIST_WORKER", "gw0")
        k = int(worker[2:]) if worker[2:].isdigit() else 0
        width = (_PORTS_HIGH - _PORTS_LOW) // 8
        _next_port.extend([_PORTS_LOW + (k % 8) * width, width, 0])
    base, width, i = _next_port
    for _ in range(width):
        port = base + (i % width)
        i += 1
        with socket.socket(socket.AF_INET, kind) as s:
            try:
                s.bind((LOCAL, port))
            except OSError:
                continue
        _next_port[2] = i
        return port
    raise RuntimeError(f"no free port in {base}..{base + width - 1}")


class Proc:
    """A ttctl process with its output in files (no pipe to fill up)."""

    def __init__(self, folder: Path, name: str, args: list[str]) -> None:
        self.name = name
        self.out_path = folder / f"{name}.out"
        self.err_path = folder / f"{name}.err"
        self._out = open(self.out_path, "w")  # noqa: SIM115 - closed in close()
        self._err = open(self.err_path, "w")  # noqa: SIM115
        self.p = subprocess.Popen(ttctl_cmd() + args, stdout=self._out, stderr=self._err, cwd=folder)

    @property
    def stdout(self) -> str:
        return self.out_path.read_text()

    @property
    def stderr(self) -> str:
        return self.err_path.read_text()

    def wait_for(self, text: str, timeout: float = 15.0, where: str = "stderr") -> None:
        timeout = scaled(timeout)  # an allowance for starting up: longer on a busy machine
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if text in (self.stderr if where == "stderr" else self.stdout):
                return
            if self.p.poll() is not None:
                break
            time.sleep(0.02)
        raise AssertionError(f"{self.name}: no {text!r} on {where} (exit {self.p.poll()}):\n"
                             f"{self.stdout}\n{self.stderr}")

    def wait(self, timeout: float = 15.0) -> int:
        timeout = scaled(timeout)
        try:
            return self.p.wait(timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            raise AssertionError(f"{self.name} did not exit in {timeout} s:\n{self.stdout}\n{self.stderr}") from None

    def signal(self, sig: int) -> None:
        if self.p.poll() is None:
            self.p.send_signal(sig)

    def kill(self) -> None:
        if self.p.poll() is None:
            self.p.kill()
            self.p.wait(5)

    def close(self) -> None:
        self.kill()
        self._out.close()
        self._err.close()


Start = Callable[..., Proc]


def data_file(folder: Path, name: str, size: int = SIZE, seed: int = 1) -> Path:
    path = folder / name
    path.write_bytes(random.Random(seed).randbytes(size))
    return path


def receiver(start: Start, tmp: Path, spec: str, *extra: str, name: str = "recv") -> Proc:
    p = start(name, "recv-file", "--listen", spec, "--dir", str(tmp / "inbox"), *extra)
    p.wait_for("receiving into")
    return p


def relay(start: Start, listen: int, to: int, *extra: str) -> Proc:
    p = start("relay", "link", "relay", "--listen", f"udp:{LOCAL}:{listen}", "--to", f"udp:{LOCAL}:{to}", *extra)
    p.wait_for("relay: udpin")
    return p


def send(*args: str, timeout: float = 60, cwd: Path | None = None) -> tuple[subprocess.CompletedProcess[str], dict]:
    proc = run_ttctl("send-file", *args, "--json", timeout=timeout, cwd=cwd)
    assert_no_traceback(proc)
    report = json.loads(proc.stdout) if proc.stdout.strip() else {}
    return proc, report


def one_line(text: str) -> str:
    lines = text.strip().splitlines()
    assert len(lines) == 1, text
    return lines[0]


def mavproxy_exe() -> str:
    """MAVProxy's script beside this interpreter (the test extra), or the test is skipped."""
    import shutil
    import sys

    import pytest

    exe = shutil.which("mavproxy.py", path=str(Path(sys.executable).parent))
    if exe is None:
        pytest.skip("MAVProxy is in the test extra")
    return exe


def run_mavproxy(port: int, steps: tuple[tuple[str, float], ...], cwd: Path, *extra: str) -> str:
    """MAVProxy 1.8.75, unmodified, listening on `port`, driven through its prompt: each step
    types its line (none for "") and waits its seconds; then its stdin closes and it ends.
    Returns what it printed."""
    p = subprocess.Popen([mavproxy_exe(), f"--master=udpin:{LOCAL}:{port}", "--source-system=255", *extra],
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, cwd=cwd)
    assert p.stdin is not None
    try:
        for line, wait in steps:
            if line:
                p.stdin.write(line + "\n")
                p.stdin.flush()
            time.sleep(wait)
        return p.communicate(timeout=20)[0]  # closes its stdin: MAVProxy ends
    finally:
        if p.poll() is None:
            p.kill()
            p.communicate()


async def until(probe: Callable[[], Any], pred: Callable[[Any], bool], timeout: float, poll: float = 0.2) -> Any:
    """Await `probe()` until `pred` holds of its value (a MAVSDK getter, say); AssertionError
    with the last value after `timeout` s (stretched on a busy machine)."""
    import asyncio

    timeout = scaled(timeout)
    end = time.monotonic() + timeout
    value = None
    while time.monotonic() < end:
        value = await probe()
        if pred(value):
            return value
        await asyncio.sleep(poll)
    raise AssertionError(f"still {value} after {timeout} s")
