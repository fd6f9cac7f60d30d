"""The emulated MOP pipeline inside `ttctl link relay`, in real time: a reliable byte stream at a
modelled rate and latency that closes when told to.

The tablet side connects to `listen` (as the app's `connectPipeline` reaches the aircraft); the
relay then connects to `to` (the onboard end's `--pipeline tcpin:`, as the onboard computer's
`DjiMopChannel_Accept` returns). Bytes each way are serialised at `rate_Bps` and delivered
`latency_s` after they leave; reading stops while a chunk waits its turn, so the bytes held here
are at most a chunk each way. At each drop (START:SECONDS, from the relay's start) both
connections close and what they had in flight is lost; for SECONDS nothing listens for the tablet
side (its attempts are refused: the pipeline cannot open, as after DJI's send timeouts and
disconnects), then it may connect again. During a stall (START:SECONDS) the connections stay
open but nothing moves either way: DJI's send timeouts, which the ends must notice themselves.
"""

from __future__ import annotations

import asyncio
import contextlib
import socket
from collections.abc import Callable

from .transport import Spec, _os_reason

CHUNK = 4096
SOCKET_BUFFER = 16 * 1024  # per socket: a MOP pipeline holds little in flight, a kernel's TCP buffers megabytes


class PipeRelay:
    def __init__(self, listen: Spec, to: Spec, rate_Bps: float, latency_s: float,
                 drops: list[tuple[float, float]], log: Callable[[str], None],
                 stalls: list[tuple[float, float]] | None = None) -> None:
        self.stalls = sorted(stalls or [])
        self.listen = listen
        self.to = to
        self.rate_Bps = rate_Bps
        self.latency_s = latency_s
        self.drops = sorted(drops)
        self.log = log
        self.connection = 0
        self.bytes = {"up": 0, "down": 0}
        self.lost = {"up": 0, "down": 0}  # bytes in flight when a drop closed the pipeline
        self.refused = 0
        self.closes = 0
        self._pair: tuple[asyncio.StreamWriter, asyncio.StreamWriter] | None = None
        self._in_flight = {"up": 0, "down": 0}
        self._server: asyncio.base_events.Server | None = None
        self._t0 = 0.0
        self._timers: list[asyncio.TimerHandle] = []

    def describe(self) -> str:
        return (f"pipeline tcp:{self.listen.host}:{self.listen.port} -> tcp:{self.to.host}:{self.to.port} at "
                f"{self.rate_Bps:.0f} B/s each way")

    async def open(self) -> None:
        loop = asyncio.get_running_loop()
        self._t0 = loop.time()
        self._server = await asyncio.start_server(self._tablet, self.listen.host, self.listen.port)
        for start, seconds in self.drops:
            self._timers.append(loop.call_at(self._t0 + start, self._drop, seconds))
            self._timers.append(loop.call_at(self._t0 + start + seconds, self._relisten))

    def _relisten(self) -> None:
        if self._server is None or self._server.is_serving() or self._down_now():
            return
        self._server = None
        asyncio.get_running_loop().create_task(self._listen_again())

    async def _listen_again(self) -> None:
        try:
            self._server = await asyncio.start_server(self._tablet, self.listen.host, self.listen.port)
        except OSError as e:
            self.log(f"pipeline: cannot listen on tcp:{self.listen.host}:{self.listen.port} again "
                     f"({_os_reason(e)})")

    def close(self) -> None:
        for t in self._timers:
            t.cancel()
        if self._server is not None:
            self._server.close()
        self._close_pair()

    def stats_text(self) -> str:
        return (f"pipeline {self.bytes['up']} B up, {self.bytes['down']} B down, {self.closes} closed "
                f"({self.lost['up'] + self.lost['down']} B in flight lost), {self.refused} refused")

    def _stalled_for(self) -> float:
        now = asyncio.get_running_loop().time() - self._t0
        return max((start + seconds - now for start, seconds in self.stalls if start <= now < start + seconds),
                   default=0.0)

    def _down_now(self) -> bool:
        now = asyncio.get_running_loop().time() - self._t0
        return any(start <= now < start + seconds for start, seconds in self.drops)

    def _drop(self, seconds: float) -> None:
        if self._server is not None:
            self._server.close()  # refused meanwhile
        if self._pair is not None:
            self.closes += 1
            lost = self._in_flight["up"] + self._in_flight["down"]
            self.lost["up"] += self._in_flight["up"]
            self.lost["down"] += self._in_flight["down"]
            self.log(f"pipeline closed (dropped for {seconds:g} s, {lost} B in flight lost)")
        self._close_pair()

    def _close_pair(self) -> None:
        pair, self._pair = self._pair, None
        self.connection += 1  # what the old pair still has scheduled is not delivered
        self._in_flight = {"up": 0, "down": 0}
        if pair is not None:
            for w in pair:
                with contextlib.suppress(Exception):
                    w.transport.abort()

    async def _tablet(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        if self._down_now():
            self.refused += 1
            writer.transport.abort()
            return
        try:
            o_reader, o_writer = await asyncio.open_connection(self.to.host, self.to.port)
        except OSError as e:
            self.refused += 1
            self.log(f"pipeline: the onboard side at tcp:{self.to.host}:{self.to.port} cannot be reached "
                     f"({_os_reason(e)})")
            writer.transport.abort()
            return
        for w in (writer, o_writer):  # what waits here is a chunk, not what a kernel would buffer
            sock = w.get_extra_info("socket")
            if sock is not None:
                with contextlib.suppress(OSError):
                    sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, SOCKET_BUFFER)
                    sock.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, SOCKET_BUFFER)
        self._close_pair()  # a newer pipeline replaces an older one
        self._pair = (writer, o_writer)
        conn = self.connection
        self.log("pipeline open")
        await asyncio.gather(self._pump(reader, o_writer, "up", conn), self._pump(o_reader, writer, "down", conn),
                             return_exceptions=True)

    async def _pump(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter, way: str, conn: int) -> None:
        loop = asyncio.get_running_loop()
        free_at = loop.time()
        while self.connection == conn:
            try:
                data = await reader.read(CHUNK)
            except OSError:
                break
            if not data or self.connection != conn:
                break
            if (left := self._stalled_for()) > 0:  # a stall: this chunk (and all behind it) waits
                await asyncio.sleep(left)
                free_at = loop.time()
                if self.connection != conn:
                    break
            self._in_flight[way] += len(data)
            free_at = max(loop.time(), free_at) + len(data) / self.rate_Bps
            await asyncio.sleep(max(0.0, free_at - loop.time()))  # serialised: read no more meanwhile
            loop.call_later(self.latency_s, self._deliver, writer, data, way, conn)
        if self.connection == conn:
            # an end closed: the other learns after what was sent before the close arrived
            loop.call_later(self.latency_s, self._end, conn)

    def _deliver(self, writer: asyncio.StreamWriter, data: bytes, way: str, conn: int) -> None:
        if self.connection != conn:
            return  # dropped with the connection it was in flight on
        self._in_flight[way] -= len(data)
        self.bytes[way] += len(data)
        with contextlib.suppress(Exception):
            writer.write(data)

    def _end(self, conn: int) -> None:
        if self.connection == conn:
            self.closes += 1
            self.log("pipeline closed by an end")
            self._close_pair()
