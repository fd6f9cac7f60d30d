"""What the link commands share: pacing from --profile/--rate, endpoint specs, signing,
signals, the progress bar, one-line messages. (The dialect on the link: dialect.py.)"""

from __future__ import annotations

import asyncio
import contextlib
import signal
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .. import interrupts
from ..errors import Fail

TABLET = (255, 190)
ONBOARD = (1, 240)
TICK = 0.25  # how often the command loops look at progress, timeouts and signals


@dataclass
class LinkChoice:
    """How fast this end sends, and what the link carries each way (None: unknown)."""

    pace_Bps: float | None
    send_capacity: float | None
    recv_capacity: float | None
    quiet: float | None  # silence after which a half-received frame is given up
    mtu: int = 100  # the link's packet size: the profile's (100 for DJI's DTT, 128 for the Payload SDK channel)
    pipe_Bps: float | None = None  # a MOP pipeline's rate (--pipe-rate, or the profile's [NAME.pipe])

    def describe(self) -> str:
        return f"paced at {self.pace_Bps:.0f} B/s" if self.pace_Bps else "unpaced"


def link_choice(rate: float | None, profile: str | None, distance: float, sysid: int,
                profile_file: Path | None = None, pipe_rate: float | None = None) -> LinkChoice:
    from ..link.model import ProfileError, load_profile

    if rate is not None and rate <= 0:
        raise Fail("--rate must be a positive number of bytes per second")
    if distance < 0:
        raise Fail("--distance must not be negative")
    if pipe_rate is not None and not (pipe_rate > 0 and pipe_rate < float("inf")):
        raise Fail("--pipe-rate must be a positive number of bytes per second")
    send_cap = recv_cap = None
    mtu = 100
    pipe_Bps = pipe_rate
    if profile is not None or profile_file is not None:
        try:
            prof = load_profile(profile, str(profile_file) if profile_file else None)
        except ProfileError as e:
            raise Fail(str(e)) from None
        note = prof.extrapolated(distance)
        if note:
            err(f"warning: {note}")
        mine, other = ("up", "down") if sysid == TABLET[0] else ("down", "up")
        send_cap = prof.capacity_Bps(mine, distance)
        recv_cap = prof.capacity_Bps(other, distance)
        mtu = prof.mtu
        if pipe_Bps is None and prof.pipe is not None:
            pipe_Bps = prof.pipe.rate_Bps
    if rate is not None:
        send_cap = rate
        recv_cap = recv_cap or rate
    quiet = 3 * mtu / recv_cap if recv_cap else None
    return LinkChoice(send_cap, send_cap, recv_cap, quiet, mtu, pipe_Bps)


DEFAULT_PIPE_BPS = 100_000.0  # the mop profile's pipeline (link/profiles.toml)


def check_pipeline(text: str | None) -> None:
    """A --pipeline that cannot work is refused before anything else is looked at."""
    if text is not None:
        pipe_link(text, LinkChoice(None, None, None, None), lambda line: None)


def pipe_link(text: str | None, link: LinkChoice, log: Any) -> tuple[Any, float | None]:
    """The --pipeline end (link.pipe.PipeLink) and its rate, or (None, None) without one."""
    if text is None:
        return None, None
    from ..link.pipe import PipeLink, parse_pipe
    from ..link.transport import TransportError

    try:
        return PipeLink(parse_pipe(text), log), link.pipe_Bps or DEFAULT_PIPE_BPS
    except TransportError as e:
        raise Fail(str(e)) from None


def parse_endpoint(text: str, udp: str, option: str = "") -> Any:
    from ..link.transport import TransportError, parse_spec

    try:
        return parse_spec(text, udp=udp)
    except TransportError as e:
        raise Fail(f"{option} {e}" if option else str(e)) from None


def load_signing(key_file: Path | None, accept_unsigned: bool, bindings: Any = None) -> Any:
    """MAVLink 2 signing for the DTT link from --key FILE (None without one): the file holds
    the 32-byte key as 64 hex digits, or a passphrase whose SHA-256 is the key (MAVProxy's
    `signing setup PASSPHRASE` convention). Every frame sent is signed; frames received must
    carry a good signature unless --accept-unsigned."""
    if key_file is None:
        if accept_unsigned:
            raise Fail("--accept-unsigned needs --key")
        return None
    import hashlib
    import re

    from ..safeio import KiB, read_capped

    raw = read_capped(key_file, f"--key {key_file}", 4 * KiB)
    text = raw.decode("utf-8", "replace").strip()
    if not text:
        raise Fail(f"--key {key_file} is empty; put 64 hex digits or a passphrase in it")
    key = bytes.fromhex(text) if re.fullmatch(r"[0-9a-fA-F]{64}", text) else hashlib.sha256(text.encode()).digest()
    if re.fullmatch(r"(0[xX])?[0-9a-fA-F]{32,}", text) and not re.fullmatch(r"[0-9a-fA-F]{64}", text):
        err(f"warning: --key {key_file} holds {len(text)} characters of hex, not the 64 hex digits of a key: "
            f"it is used as a passphrase (its SHA-256 is the key)")
    if bindings is None:
        from .dialect import load_bindings

        bindings = load_bindings(None)
    return bindings.signing(key, allow_unsigned=accept_unsigned)


def check_id(value: int, what: str) -> None:
    """A MAVLink system or component id of an end: 1..255 (0 is MAVLink's broadcast address,
    which no end can be, nor be the single target of a transfer or a command)."""
    if not 1 <= value <= 255:
        why = " (0 is MAVLink's broadcast address)" if value == 0 else ""
        raise Fail(f"{what} must be in 1..255, not {value}{why}")


class Signals:
    """SIGINT/SIGTERM set `stop` (and `wake`) instead of raising in the middle of the loop."""

    def __init__(self, loop: asyncio.AbstractEventLoop, wake: asyncio.Event) -> None:
        loop.set_exception_handler(_loop_error)
        self.stop = asyncio.Event()
        self.got: int | None = None
        self._loop = loop
        self._wake = wake
        for sig in (signal.SIGINT, signal.SIGTERM):
            with contextlib.suppress(NotImplementedError, RuntimeError):  # not the main thread, or no signals
                loop.add_signal_handler(sig, self._on, sig)
        if interrupts.seen():  # a Ctrl-C Python swallowed on the way here (in a finalizer, say)
            self._on(signal.SIGINT)

    def _on(self, sig: int) -> None:
        self.got = sig
        self.stop.set()
        self._wake.set()

    def remove(self) -> None:
        for sig in (signal.SIGINT, signal.SIGTERM):
            with contextlib.suppress(NotImplementedError, RuntimeError):
                self._loop.remove_signal_handler(sig)


def oversize_note(transport: Any) -> None:
    n = transport.stats.oversize
    if n:
        err(f"dropped {n} datagram(s) longer than {transport.mtu} bytes (DJI's link refuses them)")


def _loop_error(loop: asyncio.AbstractEventLoop, context: dict[str, Any]) -> None:
    """Whatever asyncio would print with a traceback, as one line."""
    exc = context.get("exception")
    what = f"{type(exc).__name__}: {exc}" if exc is not None else ""
    err(f"warning: {context.get('message', 'error in the event loop')}{': ' + what if what else ''}")


async def tick(wake: asyncio.Event, timeout: float = TICK) -> None:
    with contextlib.suppress(TimeoutError):
        await asyncio.wait_for(wake.wait(), timeout)
    wake.clear()


def err(text: str) -> None:
    print(f"ttctl: {text}", file=sys.stderr, flush=True)


async def start(runner: Any) -> None:
    from ..link.transport import TransportError

    try:
        await runner.start()
    except TransportError as e:
        raise Fail(str(e)) from None


class Bar:
    """A rich progress bar on stderr, only when stderr is a terminal."""

    def __init__(self, label: str, total: int) -> None:
        self.p: Any = None
        if not sys.stderr.isatty():
            return
        from rich.console import Console
        from rich.progress import (
            BarColumn,
            DownloadColumn,
            Progress,
            TextColumn,
            TimeRemainingColumn,
            TransferSpeedColumn,
        )

        self.p = Progress(TextColumn("{task.description}"), BarColumn(), DownloadColumn(), TransferSpeedColumn(),
                          TimeRemainingColumn(), TextColumn("{task.fields[extra]}"),
                          console=Console(stderr=True), transient=True)
        self.task = self.p.add_task(label, total=total, extra="")
        self.p.start()

    def log(self, text: str) -> None:
        if self.p is not None:
            self.p.console.print(f"ttctl: {text}", markup=False, highlight=False)
        else:
            err(text)

    def update(self, done: int, total: int, extra: str = "") -> None:
        if self.p is not None:
            self.p.update(self.task, completed=done, total=total, extra=extra)

    def stop(self) -> None:
        if self.p is not None:
            self.p.stop()
            self.p = None


async def await_peer(runner: Any, wake: asyncio.Event, sigs: Signals, timeout: float) -> bool:
    """A listening end (udpin, tcpin) has nowhere to send until the peer reaches it: wait for
    that (False if interrupted; Fail after `timeout`)."""
    transport = runner.transport
    if not transport.spec.listening:
        return True
    loop = asyncio.get_running_loop()
    end = loop.time() + timeout
    while transport.peer is None:
        if sigs.stop.is_set():
            return False
        if loop.time() >= end:
            raise Fail(f"timed out: nobody reached {transport.describe()} within {timeout:g} s", 1)
        await tick(wake, 0.05)
    return True


def who(ids: tuple[int, ...]) -> str:
    return f"{ids[0]}/{ids[1]}"
