"""Discrete-event simulation of two ends and the link between them, in virtual time: no
sleeping, so an hour of radio time runs in a second.

An end is anything with the sans-IO node interface: `receive(now, packet)`, `poll(now)`
returning the next packet to send now (or None), and `wakeup()` returning the next time it
needs attention (or None). Ends on a direction with per-packet feedback (the tablet) are only
polled when the radio is free, as DJI's completion callback allows; the others pace themselves.

With a `PipeModel`, the ends also share a pipeline (DJI's MOP: a reliable byte stream) beside
the packets: frames an end's `pipe.poll(now)` lets go arrive whole, in order, after the
pipeline's serialisation and latency, through `receive_stream(now, data, ("pipe", n))`, where n
numbers the connection. At each drop (the pipeline closes, or times out) what is still in flight
is lost, both ends are told (`pipe.close(now)`), and the pipeline opens again after the drop's
seconds (`pipe.open(now, rate)`).
"""

from __future__ import annotations

import heapq
from collections.abc import Callable
from typing import Protocol

from .model import Channel


class Node(Protocol):
    def receive(self, now: float, packet: bytes) -> object: ...

    def poll(self, now: float) -> bytes | None: ...

    def wakeup(self) -> float | None: ...


class PipeModel:
    """A pipeline at `rate_Bps` each way with `latency_s`, open from `opens_at`, closed for each
    (start, seconds) in `drops`."""

    def __init__(self, rate_Bps: float, latency_s: float = 0.02, drops: list[tuple[float, float]] | None = None,
                 opens_at: float = 0.0) -> None:
        self.rate_Bps = rate_Bps
        self.latency_s = latency_s
        self.drops = sorted(drops or [])
        self.opens_at = opens_at
        self.connection = 0  # 0: not open yet
        self.open = False
        self.free_at = [0.0, 0.0]  # per direction: when the pipeline has sent what it was given
        self.bytes = [0, 0]
        self.lost_in_flight = [0, 0]  # bytes given to the pipeline and lost with a drop

    def next_change(self) -> float | None:
        if not self.open:
            return self.opens_at
        return self.drops[0][0] if self.drops else None


class Simulation:
    def __init__(self, a: Node, b: Node, a_to_b: Channel, b_to_a: Channel, pipe: PipeModel | None = None) -> None:
        self.nodes = (a, b)
        self.channels = (a_to_b, b_to_a)
        self.pipe = pipe
        self.now = 0.0
        # (time, seq, destination, data, pipeline connection or 0 for a packet)
        self._events: list[tuple[float, int, int, bytes, int]] = []
        self._seq = 0
        self.steps = 0

    def _send_ready(self) -> None:
        for i, (node, ch) in enumerate(zip(self.nodes, self.channels, strict=True)):
            while True:
                if ch.dir.feedback and ch.free_at() > self.now + 1e-12:
                    break
                pkt = node.poll(self.now)
                if pkt is None:
                    break
                for t, data in ch.submit(self.now, pkt):
                    self._seq += 1
                    heapq.heappush(self._events, (t, self._seq, 1 - i, data, 0))
        pipe = self.pipe
        if pipe is None or not pipe.open:
            return
        for i, node in enumerate(self.nodes):
            while True:
                frame = node.pipe.poll(self.now)  # type: ignore[attr-defined]
                if frame is None:
                    break
                left = max(self.now, pipe.free_at[i]) + len(frame) / pipe.rate_Bps
                pipe.free_at[i] = left
                pipe.bytes[i] += len(frame)
                self._seq += 1
                heapq.heappush(self._events, (left + pipe.latency_s, self._seq, 1 - i, frame, pipe.connection))

    def _pipe_change(self) -> None:
        pipe = self.pipe
        assert pipe is not None
        if not pipe.open:
            pipe.open = True
            pipe.connection += 1
            pipe.free_at = [self.now, self.now]
            for node in self.nodes:
                node.pipe.open(self.now, pipe.rate_Bps)  # type: ignore[attr-defined]
            return
        start, seconds = pipe.drops.pop(0)
        pipe.open = False
        pipe.opens_at = start + seconds
        kept = []
        for ev in self._events:
            if ev[4] == pipe.connection:
                pipe.lost_in_flight[1 - ev[2]] += len(ev[3])
            else:
                kept.append(ev)
        heapq.heapify(kept)
        self._events = kept
        for node in self.nodes:
            node.pipe.close(self.now)  # type: ignore[attr-defined]
            node.forget_source(("pipe", pipe.connection))  # type: ignore[attr-defined]

    def _next_time(self) -> float | None:
        times = [self._events[0][0]] if self._events else []
        if self.pipe is not None and (t := self.pipe.next_change()) is not None:
            times.append(max(t, self.now))
        for node, ch in zip(self.nodes, self.channels, strict=True):
            w = node.wakeup()
            if w is not None:
                if ch.dir.feedback:
                    w = max(w, ch.free_at())
                times.append(max(w, self.now))
        return min(times) if times else None

    def run(self, until: float, stop: Callable[[], bool] | None = None, max_steps: int = 50_000_000) -> float:
        """Advance until `stop()` is true, nothing is left to happen, or `until` seconds."""
        stuck, last = 0, -1.0
        while self.steps < max_steps:
            self.steps += 1
            stuck = stuck + 1 if self.now == last else 0
            last = self.now
            if stuck > 10_000:
                raise RuntimeError(f"simulation stuck at t={self.now:.6f}: an end keeps asking to wake up now "
                                   f"(wakeups {[n.wakeup() for n in self.nodes]})")
            self._send_ready()
            if stop is not None and stop():
                break
            t = self._next_time()
            if t is None or t > until:
                self.now = until if t is not None else self.now
                break
            self.now = max(self.now, t)
            pipe = self.pipe
            if pipe is not None and (c := pipe.next_change()) is not None and c <= self.now:
                self._pipe_change()
                continue
            while self._events and self._events[0][0] <= self.now:
                _, _, dest, data, conn = heapq.heappop(self._events)
                if conn:
                    self.nodes[dest].receive_stream(self.now, data, ("pipe", conn))  # type: ignore[attr-defined]
                else:
                    self.nodes[dest].receive(self.now, data)
        return self.now
