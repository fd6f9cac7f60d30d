"""MAVSDK as a test peer, in a process of its own.

MAVSDK v4's Python package runs the C++ library inside the Python process. Tearing it down can
abort that process (seen in CI: `Fatal Python error: Aborted` in `Mavsdk.destroy` while a plugin's
`__del__` destroyed it from an executor thread), which took a pytest-xdist worker and its queued
tests with it, and the run then never finished. So each scenario runs in a forked child. The child
builds one `Mavsdk` (a ground station, 245/190, by its default configuration, which sends its
HEARTBEAT only once it heard a vehicle's), awaits the scenario with it, sends back what it returned
(or its traceback) and leaves with `os._exit`, never running MAVSDK's teardown. The parent turns a
failure into an AssertionError that carries the child's traceback, and kills a child that outlives
its time.
"""
from __future__ import annotations

import asyncio
import os
import pickle
import select
import signal
import time
import traceback
from collections.abc import Awaitable, Callable
from typing import Any


def fly(body: Callable[[Any], Awaitable[Any]], timeout: float, config: Callable[[], Any] | None = None) -> Any:
    """Run `await body(mavsdk)` in a forked child within `timeout` seconds and return its value
    (which must pickle). `config` builds the child's `Configuration` (default: a ground station).
    A child that MAVSDK's own C++ aborts before it reports (seen beside two CPU hogs: "terminate
    called after throwing ... std::system_error: Resource deadlock avoided" right after it
    discovered the autopilot, a thread of the library joining itself) is run once more; a second
    abort fails the test."""
    try:
        return _fly_once(body, timeout, config)
    except _Aborted:
        return _fly_once(body, timeout, config)


class _Aborted(AssertionError):
    """The MAVSDK child died of SIGABRT before it reported."""


def _fly_once(body: Callable[[Any], Awaitable[Any]], timeout: float, config: Callable[[], Any] | None) -> Any:
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: nothing it does may return into pytest
        os.close(read)
        try:
            outcome = ("ok", asyncio.run(asyncio.wait_for(_with_mavsdk(body, config), timeout)))
        except BaseException:
            outcome = ("failed", traceback.format_exc())
        try:
            data = pickle.dumps(outcome)
        except Exception:
            data = pickle.dumps(("failed", f"the scenario's value does not pickle: {outcome[1]!r}"))
        with os.fdopen(write, "wb") as out:
            out.write(data)
        os._exit(0)
    os.close(write)
    chunks: list[bytes] = []
    deadline = time.monotonic() + timeout + 30  # the child's own wait_for ends it first
    with os.fdopen(read, "rb") as inp:
        while True:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([inp], [], [], left)[0]:
                os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
                raise AssertionError(f"the MAVSDK scenario did not end within {timeout + 30:.0f} s")
            chunk = os.read(inp.fileno(), 1 << 16)
            if not chunk:
                break
            chunks.append(chunk)
    _, status = os.waitpid(pid, 0)
    if not chunks:
        died = _Aborted if os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGABRT else AssertionError
        raise died(f"the MAVSDK child died before it reported (wait status {status:#x})")
    kind, value = pickle.loads(b"".join(chunks))
    if kind != "ok":
        raise AssertionError(f"in the MAVSDK child:\n{value}")
    return value


async def _with_mavsdk(body: Callable[[Any], Awaitable[Any]], config: Callable[[], Any] | None) -> Any:
    from mavsdk.asyncio import ComponentType, Configuration, Mavsdk

    cfg = config() if config else Configuration.create_with_component_type(ComponentType.GROUND_STATION)
    return await body(Mavsdk(cfg))  # never destroyed: the child ends with os._exit
