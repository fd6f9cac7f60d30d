"""The emulated air between two processes: `ttctl link relay`.

Packets arriving on the listening side (the tablet's) go through the model's `up` Channel and
are delivered to the other side after the modelled time, or lost, corrupted, duplicated or
reordered; packets from the other side go through `down` and are sent to every peer of the
listening side: the addresses that sent a valid frame there lately, as `validate` (given by
the layer that knows frames) judges. Anything may go up, as anything may be put on DJI's
link; garbage never becomes a destination. The same Channel objects the virtual-time simulator uses, driven
by the event loop's clock with `call_at`; the model's time (outages included) counts from the
moment the relay opens.
"""

from __future__ import annotations

import asyncio
import dataclasses
from collections.abc import Callable, Hashable

from .model import Channel, Impairments, Profile
from .transport import Spec, UdpTransport


def with_rate(profile: Profile, rate_Bps: float) -> Profile:
    """The profile with both directions at a fixed rate (no DJI pacing increments)."""
    def fix(d: object) -> object:
        return dataclasses.replace(d, rate_Bps=[[0.0, float(rate_Bps)]], pacing_bytes=0,  # type: ignore[type-var]
                                   pacing_interval_s=0.0)

    return dataclasses.replace(profile, up=fix(profile.up), down=fix(profile.down))  # type: ignore[arg-type]


class Relay:
    def __init__(self, listen: Spec, to: Spec, profile: Profile, distance_m: float, impairments: Impairments,
                 seed: int = 0, log: Callable[[str], None] | None = None,
                 validate: Callable[[bytes, Hashable], set[tuple[int, int]]] | None = None) -> None:
        self.listen = listen
        self.to = to
        self.up = Channel(profile, "up", distance_m, dataclasses.replace(impairments), seed=seed * 2 + 1)
        self.down = Channel(profile, "down", distance_m, dataclasses.replace(impairments), seed=seed * 2 + 2)
        # the model refuses packets over its MTU; the sockets take anything
        self.a = UdpTransport(listen, mtu=65535, log=log)
        self.b = UdpTransport(to, mtu=65535, log=log)
        self.a.on_receive = self._from_a
        self.b.on_receive = self._from_b
        self.validate = validate
        self.started = 0.0
        self.undeliverable = 0  # down packets with nobody heard on the listening side yet
        self.in_flight = 0
        self._loop: asyncio.AbstractEventLoop | None = None

    async def open(self) -> None:
        self._loop = asyncio.get_running_loop()
        self.started = self._loop.time()
        await self.a.open()
        try:
            await self.b.open()
        except BaseException:
            self.a.close()
            raise

    def close(self) -> None:
        self.a.close()
        self.b.close()

    def _from_a(self, data: bytes, source: Hashable) -> None:
        self._carry(self.up, data, self._to_b)
        if self.validate is not None:
            ids = self.validate(data, source)
            if ids:
                self.a.confirm(source, ids)

    def _from_b(self, data: bytes, source: Hashable) -> None:
        self._carry(self.down, data, self._to_a)

    def _carry(self, ch: Channel, data: bytes, deliver: Callable[[bytes], None]) -> None:
        loop = self._loop
        assert loop is not None
        for when, pkt in ch.submit(loop.time() - self.started, data):
            self.in_flight += 1
            loop.call_at(self.started + when, deliver, pkt)

    def _to_b(self, pkt: bytes) -> None:
        self.in_flight -= 1
        self.b.send(pkt)

    def _to_a(self, pkt: bytes) -> None:
        self.in_flight -= 1
        if not self.a.send(pkt):
            self.undeliverable += 1

    def stats_line(self) -> str:
        loop = self._loop
        elapsed = (loop.time() - self.started) if loop is not None else 0.0

        def part(name: str, ch: Channel) -> str:
            s = ch.stats
            rate = s.bytes_delivered / elapsed if elapsed > 0 else 0.0
            extra = [f"{n} {getattr(s, n)}" for n in ("overflow", "refused", "corrupted", "duplicated", "reordered")
                     if getattr(s, n)]
            return (f"{name} {s.submitted} in, {s.delivered} out, {s.lost} lost"
                    + "".join(f", {e}" for e in extra) + f", {rate:.0f} B/s")

        tail = f", {self.undeliverable} undeliverable" if self.undeliverable else ""
        return f"relay {elapsed:.1f} s: {part('up', self.up)} | {part('down', self.down)}{tail}"


async def run_relay(relay: Relay, stop: asyncio.Event, stats_interval: float, emit: Callable[[str], None],
                    extra: Callable[[], str] | None = None) -> None:
    """Carry packets until `stop` is set, printing a stats line every `stats_interval` s
    (0: only at the end), with `extra()` appended (the pipeline's)."""
    def line() -> str:
        return relay.stats_line() + (f" | {extra()}" if extra is not None else "")

    await relay.open()
    emit(f"relay: {relay.a.describe()} (up: {relay.up.capacity_Bps():.0f} B/s) <-> {relay.b.describe()} "
         f"(down: {relay.down.capacity_Bps():.0f} B/s), profile {relay.up.profile.name}")
    try:
        while not stop.is_set():
            try:
                await asyncio.wait_for(stop.wait(), stats_interval if stats_interval > 0 else None)
            except TimeoutError:
                emit(line())
    finally:
        emit(line())
        relay.close()


__all__ = ["Relay", "run_relay", "with_rate"]
