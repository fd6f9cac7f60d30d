"""`ttctl link relay`: the emulated DJI radio between two processes, in real time."""

from __future__ import annotations

import asyncio
import contextlib
import socket
import sys
from collections import OrderedDict
from collections.abc import Hashable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import Fail
from .common import Signals, err


@dataclass
class RelayOptions:
    listen: str
    to: str
    profile: str | None = None  # None: m100, or the one profile in profile_file
    distance: float = 10.0
    loss: float | None = None
    loss_model: str | None = None  # None: the profile's
    corrupt: float = 0.0
    duplicate: float = 0.0
    reorder: float = 0.0
    seed: int = 0
    rate: float | None = None
    stats_interval: float = 5.0
    outages: list[str] = field(default_factory=list)  # START:SECONDS, from the relay's start
    profile_file: Path | None = None
    burst_mean: float | None = None  # None: the profile's
    dialect: Path | None = None  # whose frames prove who is behind an address
    include_dirs: list[Path] = field(default_factory=list)
    pipe_listen: str | None = None  # a MOP pipeline: where the tablet side connects
    pipe_to: str | None = None  # ...and the onboard side's --pipeline tcpin:
    pipe_drops: list[str] = field(default_factory=list)  # START:SECONDS
    pipe_rate: float | None = None  # None: the profile's pipeline
    pipe_stalls: list[str] = field(default_factory=list)  # START:SECONDS


def _outage(text: str, option: str = "--outage") -> tuple[float, float]:
    start, sep, length = text.partition(":")
    try:
        if not sep:
            raise ValueError
        window = float(start), float(length)
    except ValueError:
        raise Fail(f"{option} wants START:SECONDS (seconds from the relay's start), not {text!r}") from None
    if option != "--outage" and not (0 <= window[0] < 1e9 and 0 < window[1] < 1e9):  # (--outage: Impairments)
        raise Fail(f"{option} {text}: a window needs a start >= 0 and a positive duration, in seconds")
    return window


def _pipe_relay(o: RelayOptions, prof: Any, log: Any) -> Any:
    """The emulated pipeline (link/pipe_relay.py), or None without --pipe-listen."""
    from ..link.pipe_relay import PipeRelay
    from ..link.transport import TransportError, parse_spec

    if o.pipe_rate is not None and not 0 < o.pipe_rate < float("inf"):
        raise Fail("--pipe-rate must be a positive number of bytes per second")
    if o.pipe_listen is None and o.pipe_to is None:
        if o.pipe_drops or o.pipe_stalls:
            raise Fail(f"{'--pipe-drop' if o.pipe_drops else '--pipe-stall'} needs a pipeline: --pipe-listen and "
                       f"--pipe-to")
        return None
    if o.pipe_listen is None or o.pipe_to is None:
        raise Fail("a pipeline needs both --pipe-listen (the tablet side) and --pipe-to (the onboard side)")
    try:
        text = o.pipe_listen.strip()
        listen = parse_spec("tcpin:" + text[4:] if text.lower().startswith("tcp:") else text, allowed=("tcpin",))
        to = parse_spec(o.pipe_to.replace("tcpout:", "tcp:", 1), allowed=("tcp",))
    except TransportError as e:
        raise Fail(f"{e} (the pipeline is a TCP stream: tcp:HOST:PORT)") from None
    if (listen.host, listen.port) == (to.host, to.port):
        raise Fail(f"--pipe-to {o.pipe_to} is the relay's own --pipe-listen address")
    rate = o.pipe_rate if o.pipe_rate is not None else (prof.pipe.rate_Bps if prof.pipe is not None else None)
    if rate is None:
        raise Fail(f"profile {prof.name!r} has no pipeline: use --profile mop, or give --pipe-rate")
    if not 0 < rate < float("inf"):
        raise Fail("--pipe-rate must be a positive number of bytes per second")
    latency = prof.pipe.latency_s if prof.pipe is not None else 0.02
    drops = [_outage(t, "--pipe-drop") for t in o.pipe_drops] + [_outage(t) for t in o.outages]
    stalls = [_outage(t, "--pipe-stall") for t in o.pipe_stalls]
    return PipeRelay(listen, to, rate, latency, drops, log, stalls)


class FrameCheck:
    """Who is behind a UDP source, judged only by valid MAVLink frames of the link's dialect: one
    packet receiver per source (so packets from two sources never mix), the least recently heard
    forgotten first."""

    def __init__(self, bindings: Any, limit: int = 64) -> None:
        self.b = bindings
        self.limit = limit
        self._rxs: OrderedDict[Hashable, Any] = OrderedDict()

    def __call__(self, packet: bytes, source: Hashable) -> set[tuple[int, int]]:
        from ..wire.packets import PacketReceiver

        rx = self._rxs.get(source)
        if rx is None:
            rx = self._rxs[source] = PacketReceiver(self.b)
            if len(self._rxs) > self.limit:
                self._rxs.popitem(last=False)
        else:
            self._rxs.move_to_end(source)
        return {(m.get_srcSystem(), m.get_srcComponent()) for m in rx.feed(packet)}


def _same_place(a: Any, b: Any) -> bool:
    """Whether sending to `b` would reach the socket listening at `a` (the relay would talk to
    itself)."""
    if a.port != b.port:
        return False

    def addrs(host: str) -> set[str]:
        with contextlib.suppress(OSError):
            return {str(info[4][0]) for info in socket.getaddrinfo(host, None, type=socket.SOCK_DGRAM)}
        return {host}

    mine, theirs = addrs(a.host), addrs(b.host)
    if mine & theirs:
        return True
    wildcard = {"0.0.0.0", "::"}
    local = {"127.0.0.1", "::1", "localhost"}
    return bool(mine & wildcard) and bool(theirs & local or theirs & addrs(socket.gethostname()))


def relay(o: RelayOptions) -> int:
    from ..link.model import Impairments, ProfileError, load_profile
    from ..link.relay import Relay, with_rate
    from ..link.transport import TransportError, parse_spec

    try:
        listen = parse_spec(o.listen, udp="udpin", allowed=("udpin",))
        to = parse_spec(o.to, udp="udpout", allowed=("udpout",))
    except TransportError as e:
        raise Fail(f"{e} (the relay carries DTT packets: UDP only)") from None
    if _same_place(listen, to):
        raise Fail(f"--to {o.to} is the relay's own --listen address: it would relay to itself")
    from .dialect import load_bindings

    b = load_bindings(o.dialect, o.include_dirs)
    if o.distance < 0:
        raise Fail("--distance must not be negative")
    if o.stats_interval < 0:
        raise Fail("--stats-interval must not be negative")
    try:
        prof = load_profile(o.profile, str(o.profile_file) if o.profile_file else None)
        if o.rate is not None:
            if o.rate <= 0:
                raise Fail("--rate must be a positive number of bytes per second")
            prof = with_rate(prof, o.rate)
        imp = Impairments(loss=o.loss, loss_model=o.loss_model, burst_mean=o.burst_mean, corrupt=o.corrupt,
                          duplicate=o.duplicate, reorder=o.reorder, outages=[_outage(text) for text in o.outages])
        imp.check()
        r = Relay(listen, to, prof, o.distance, imp, seed=o.seed, log=lambda text: err(f"relay: {text}"),
                  validate=FrameCheck(b))
    except ProfileError as e:
        raise Fail(str(e)) from None
    note = prof.extrapolated(o.distance)
    if note:
        err(f"warning: {note}")
    for d in ("up", "down"):  # a burst that outlasts any run is an outage: say so
        dp = prof.direction(d)
        mean = imp.burst_mean or dp.burst_mean
        seconds = mean * prof.mtu / prof.capacity_Bps(d, o.distance)
        if (imp.loss_model or dp.loss_model) == "burst" and seconds > 60:
            lasts = f"about {seconds:.3g} s" if seconds < 1e9 else "longer than any run"
            err(f"warning: a mean loss burst of {mean:g} packets lasts {lasts} on the {d}link: "
                f"once lost, the link stays lost for the rest of the run")
            break
    pipe = _pipe_relay(o, prof, lambda text: err(f"relay: {text}"))

    async def main() -> None:
        loop = asyncio.get_running_loop()
        wake = asyncio.Event()
        sigs = Signals(loop, wake)
        try:
            from ..link.relay import run_relay

            if pipe is not None:
                try:
                    await pipe.open()
                except OSError as e:
                    raise Fail(f"--pipe-listen {o.pipe_listen}: {e.strerror or e}") from None
                err(f"relay: {pipe.describe()}")
            await run_relay(r, sigs.stop, o.stats_interval, lambda text: print(text, file=sys.stderr, flush=True),
                            extra=pipe.stats_text if pipe is not None else None)
        except TransportError as e:
            raise Fail(str(e)) from None
        finally:
            sigs.remove()
            if pipe is not None:
                pipe.close()

    try:
        asyncio.run(main())
    except KeyboardInterrupt:  # before the signal handlers were in place
        err("relay: stopped")
    return 0
