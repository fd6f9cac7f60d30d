"""Discrete-event simulation of two ends and the link between them, in virtual time: no
sleeping, so an hour of radio time runs in a second.

An end is anything with the sans-IO node interface: `receive(now, packet)`, `poll(now)`
returning the next packet to send now (or None), and `wakeup()` returning the next time it
needs attention (or None). Ends on a direction with per-packet feedback (the tablet) are only
polled when the radio is free, as DJI's completion callback allows; the others pace themselves.
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


class Simulation:
    def __init__(self, a: Node, b: Node, a_to_b: Channel, b_to_a: Channel) -> None:
        self.nodes = (a, b)
        self.channels = (a_to_b, b_to_a)
        self.now = 0.0
        self._events: list[tuple[float, int, int, bytes]] = []  # (time, seq, destination, packet)
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
                    heapq.heappush(self._events, (t, self._seq, 1 - i, data))

    def _next_time(self) -> float | None:
        times = [self._events[0][0]] if self._events else []
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
            while self._events and self._events[0][0] <= self.now:
                _, _, dest, data = heapq.heappop(self._events)
                self.nodes[dest].receive(self.now, data)
        return self.now
