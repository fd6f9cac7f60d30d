"""The naive forwarder `ttctl bench gcs` measures the bridge against: what a plain UDP-to-DTT
bridge does. Every datagram from the ground station is cut into DTT packets of at most 100 bytes
as it comes and queued, first in first out, behind whatever the app queued before it (the app's
own packets come in on --app and share the one queue, as they share the one SDK call); the
queue leaves paced at the uplink rate. Every packet from DTT goes back, as it is, to the ground
station and to the app. No parsing, no priorities, no duplicate suppression, no bound.

Run as a process by the benchmark: python -m ttctl.bench.gcs_naive --app PORT --gcs PORT
--to PORT --rate BYTES_PER_S (all on 127.0.0.1). It prints "naive: ready" on stderr once its
sockets are open and "naive: ... packets up, ... down, queue peak ..." when it ends (SIGTERM).
"""

from __future__ import annotations

import argparse
import asyncio
import collections
import contextlib
import signal
import socket
import sys

MTU = 100
LOCAL = "127.0.0.1"


class Naive:
    def __init__(self, app_port: int, gcs_port: int, to_port: int, rate_Bps: float) -> None:
        self.rate = rate_Bps
        self.app = _sock(app_port)
        self.gcs = _sock(0)
        self.dtt = _sock(0)
        self.gcs_to = (LOCAL, gcs_port)
        self.to = (LOCAL, to_port)
        self.app_peer: tuple[str, int] | None = None
        self.queue: collections.deque[bytes] = collections.deque()
        self.next_free = 0.0
        self.up = self.down = self.peak = 0
        self.wake = asyncio.Event()

    def _from_app(self) -> None:
        for data, addr in _drain(self.app):
            self.app_peer = addr
            self._queue(data)

    def _from_gcs(self) -> None:
        for data, addr in _drain(self.gcs):
            self.gcs_to = addr  # answer where the ground station speaks from
            self._queue(data)

    def _queue(self, data: bytes) -> None:
        for i in range(0, len(data), MTU):
            self.queue.append(data[i:i + MTU])
        self.peak = max(self.peak, len(self.queue))
        self.wake.set()

    def _from_dtt(self) -> None:
        for data, _ in _drain(self.dtt):
            self.down += 1
            for to in (self.gcs_to, self.app_peer):
                if to is not None:
                    with contextlib.suppress(OSError):  # nobody there yet
                        (self.gcs if to is self.gcs_to else self.app).sendto(data, to)

    async def pace(self) -> None:
        loop = asyncio.get_running_loop()
        while True:
            if not self.queue:
                self.wake.clear()
                await self.wake.wait()
            now = loop.time()
            if now < self.next_free:
                await asyncio.sleep(self.next_free - now)
                now = loop.time()
            packet = self.queue.popleft()
            self.next_free = max(now, self.next_free) + len(packet) / self.rate
            try:
                self.dtt.sendto(packet, self.to)
                self.up += 1
            except OSError:
                pass

    async def run(self) -> None:
        loop = asyncio.get_running_loop()
        loop.add_reader(self.app.fileno(), self._from_app)
        loop.add_reader(self.gcs.fileno(), self._from_gcs)
        loop.add_reader(self.dtt.fileno(), self._from_dtt)
        stop = asyncio.Event()
        for sig in (signal.SIGTERM, signal.SIGINT):
            loop.add_signal_handler(sig, stop.set)
        pacer = loop.create_task(self.pace())
        print("naive: ready", file=sys.stderr, flush=True)
        await stop.wait()
        pacer.cancel()
        print(f"naive: {self.up} packets up, {self.down} down, queue peak {self.peak} packets, "
              f"{len(self.queue)} left", file=sys.stderr, flush=True)


def _sock(port: int) -> socket.socket:
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    s.bind((LOCAL, port))
    s.setblocking(False)
    return s


def _drain(s: socket.socket) -> list[tuple[bytes, tuple[str, int]]]:
    out: list[tuple[bytes, tuple[str, int]]] = []
    while True:
        try:
            data, addr = s.recvfrom(65535)
        except (BlockingIOError, InterruptedError):
            return out
        except OSError:  # an ICMP port-unreachable from an earlier send: nothing to read
            return out
        out.append((data, addr))


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m ttctl.bench.gcs_naive")
    p.add_argument("--app", type=int, required=True)
    p.add_argument("--gcs", type=int, required=True)
    p.add_argument("--to", type=int, required=True)
    p.add_argument("--rate", type=float, required=True)
    a = p.parse_args(argv)
    asyncio.run(Naive(a.app, a.gcs, a.to, a.rate).run())
    return 0


if __name__ == "__main__":
    sys.exit(main())
