"""The asyncio driver of a sans-IO Endpoint over a transport, in real time.

The clock is the event loop's (`loop.time()`). Received datagrams (or stream chunks) go to
`Endpoint.receive` (or `receive_stream`) as they arrive, with where they came from; the
senders of valid frames are confirmed to the transport, which answers only such peers. One
task, the pump, sends every packet
`Endpoint.poll` lets go, then sleeps until the endpoint's next wake-up (its pacer, a status, an
offer retry, ...) or until something arrives, whichever is first. After a few packet times of
silence from a source with a long frame half received, it calls `Endpoint.flush` so that
frames in the packets taken for it are not held back. It never spins: a wake-up time that produces nothing
costs a millisecond's sleep, not a busy loop.

With a `pipe` (link/pipe.py: a MOP pipeline's byte stream), the pump also writes the file data
`Endpoint.pipe` lets go onto it, whole frames, while the pipeline holds less than PIPE_BACKLOG
unsent; each of its connections opens and closes the endpoint's pipeline path
(proto/pipeline.py) and is parsed as a source of its own.
"""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import Callable, Hashable
from dataclasses import dataclass
from typing import Any

from ..link.transport import Transport, addr_text
from ..proto.endpoint import Endpoint

BURST = 16  # packets sent without yielding to the loop (receives and timers get their turn)
SPIN_GUARD = 0.001  # least sleep when a wake-up time is already past but nothing went out
CATCH_UP = 0.002  # a late wake-up by up to this much keeps the pacer's schedule (timer granularity)
QUIET_MIN, QUIET_MAX = 0.02, 2.0
PIPE_BACKLOG = 32 * 1024  # bytes on a pipeline not yet taken by the peer (at least; rate x 0.1 s on a fast one)
PIPE_WAIT = 0.005  # s between looks at a pipeline that is behind
PIPE_TIMEOUT = 2.0  # s a pipeline may stay behind before it counts as timed out (closed, then reconnected)


@dataclass
class RunnerStats:
    packets_in: int = 0
    packets_out: int = 0
    bytes_in: int = 0
    bytes_out: int = 0
    flushes: int = 0
    pipe_frames: int = 0
    wakeups: int = 0
    idle_wakeups: int = 0  # wake-ups that sent nothing (timers, status checks)


class Runner:
    """Drives `endpoint` over `transport`. `quiet` is the silence (seconds) after which a
    half-received frame is given up; None measures it: three times the usual gap between
    packets."""

    def __init__(self, endpoint: Endpoint, transport: Transport, quiet: float | None = None,
                 hello: Callable[[], Any] | None = None, hello_interval: float = 1.0,
                 probes: Any = None, pipe: Any = None, pipe_rate_Bps: float | None = None) -> None:
        self.ep = endpoint
        self.pipe = pipe  # a link.pipe.PipeLink, or None
        self.pipe_rate_Bps = pipe_rate_Bps
        self._pipe_behind_since: float | None = None
        # what may be on its way on a pipeline at once: what a drop or a timeout can cost
        self.pipe_window = max(PIPE_BACKLOG, int(0.1 * (pipe_rate_Bps or 0)))
        # something that may take a datagram before the endpoint does (`take(data, source) ->
        # bool`): ttctl.link.probes.LinkProbes beside an onboard end
        self.probes = probes
        self.transport = transport
        self.quiet = quiet
        # a message to send every hello_interval s until the peer is heard: an end that reaches
        # out (udpout) and would otherwise wait for the peer to speak first makes itself known
        self.hello = hello
        self.hello_interval = hello_interval
        self._hello_due: float | None = None
        self._error: BaseException | None = None
        self.stats = RunnerStats()
        self.last_rx: float | None = None
        self._gap = 0.05  # EWMA of the time between arriving packets
        self._waiter: asyncio.Future[None] | None = None
        self._task: asyncio.Task[None] | None = None
        self._closed = False
        self._last_now = 0.0
        self._loop: asyncio.AbstractEventLoop | None = None
        transport.on_receive = self._on_data
        transport.on_close = endpoint.forget_source
        if pipe is not None:
            pipe.on_open = self._pipe_open
            pipe.on_close = self._pipe_close
            pipe.on_data = self._pipe_data
            pipe.on_forget = lambda n: endpoint.forget_source(("pipe", n))
            pipe.on_connect = self._pipe_hello

    # -- the clock ------------------------------------------------------------------------------
    def now(self) -> float:
        """The current time on the endpoint's clock (never going backwards)."""
        loop = self._loop or asyncio.get_running_loop()
        t = max(loop.time(), self._last_now)
        self._last_now = t
        return t

    def sync(self) -> float:
        """Bring the endpoint's clock to now: call before send_file / request_file / command,
        which stamp what they create with the endpoint's time."""
        t = self.now()
        self.ep.now = t
        return t

    # -- life cycle -----------------------------------------------------------------------------
    async def start(self) -> None:
        """Open the transport (TransportError if it cannot) and start the pump."""
        self._loop = asyncio.get_running_loop()
        self.sync()
        await self.transport.open()
        if self.pipe is not None:
            try:
                await self.pipe.open()
            except BaseException:
                self.transport.close()
                raise
        self._task = self._loop.create_task(self._pump())

    def kick(self) -> None:
        """Something changed (a file was queued, a command submitted): reconsider now."""
        w = self._waiter
        if w is not None and not w.done():
            w.set_result(None)

    async def drain(self, timeout: float) -> None:
        """Wait (at most `timeout`) until what the endpoint has to say now (a last status, say)
        has left: nothing queued and nothing due within the next moment."""
        loop = self._loop or asyncio.get_running_loop()
        end = loop.time() + timeout
        self.kick()
        await asyncio.sleep(0.02)  # the pump's turn: statuses due now are built when it polls
        while loop.time() < end and self._task is not None and not self._task.done():
            w = self.ep.wakeup()
            if not self.ep.scheduler.busy and (w is None or w > loop.time() + 0.1):
                break
            await asyncio.sleep(0.01)

    async def close(self) -> None:
        self._closed = True
        self.kick()
        if self._task is not None:
            self._task.cancel()
            with contextlib.suppress(asyncio.CancelledError, Exception):
                await self._task
        self.transport.close()
        if self.pipe is not None:
            self.pipe.close()

    @property
    def failed(self) -> BaseException | None:
        """The exception the pump died of, or the first one the endpoint raised on receive."""
        if self._error is not None:
            return self._error
        t = self._task
        if t is None or not t.done() or t.cancelled():
            return None
        return t.exception()

    # -- receiving ------------------------------------------------------------------------------
    def _on_data(self, data: bytes, source: Hashable = None) -> None:
        now = self.now()
        if self.last_rx is not None:
            self._gap = 0.9 * self._gap + 0.1 * min(1.0, now - self.last_rx)
        self.last_rx = now
        self.stats.packets_in += 1
        self.stats.bytes_in += len(data)
        try:
            if self.probes is not None and not self.transport.stream and self.probes.take(data, source):
                return
            if self.transport.stream:
                ids = self.ep.receive_stream(now, data, source)
            else:
                ids = self.ep.receive(now, data, source)
            if ids:
                self.transport.confirm(source, ids)
        except Exception as e:  # a bug, not bad input (the parsers take anything): report it once
            self._error = self._error or e
        self.kick()

    # -- the pipeline ---------------------------------------------------------------------------
    def _pipe_open(self, n: int) -> None:
        self.ep.pipe.open(self.now(), self.pipe_rate_Bps or 0.0)
        self.kick()

    def _pipe_close(self, n: int, words: str) -> None:
        self.ep.pipe.close(self.now())
        self.ep.forget_source(("pipe", n))
        self.kick()

    def _pipe_data(self, data: bytes, n: int) -> None:
        try:
            if self.ep.receive_stream(self.now(), data, ("pipe", n)):
                self.pipe.confirm(n)  # a valid frame: the peer is on it (tcpin)
        except Exception as e:  # a bug, not bad input
            self._error = self._error or e
        self.kick()

    def _check_pipe(self, real: float) -> None:
        """A pipeline whose socket takes nothing for PIPE_TIMEOUT timed out: closed (file data
        back on the link at once), and connected again (tcpout) or awaited (tcpin)."""
        assert self.pipe is not None
        if self.pipe.backlog() < self.pipe_window:
            self._pipe_behind_since = None
        elif self._pipe_behind_since is None:
            self._pipe_behind_since = real
        elif real - self._pipe_behind_since >= PIPE_TIMEOUT:
            self._pipe_behind_since = None
            self.pipe.drop(f"timed out: nothing sent for {PIPE_TIMEOUT:g} s")

    def _pipe_hello(self, write: Callable[[bytes], None]) -> None:
        """The first frame on a pipeline we connected: the accepting side takes the connection
        as the pipeline once a valid frame came on it."""
        b = self.ep.b
        kind = b.MavType.MAV_TYPE_GCS if self.ep.sysid == 255 else b.MavType.MAV_TYPE_ONBOARD_CONTROLLER
        frame = self.ep.encoder.encode(b.Heartbeat(type=int(kind), autopilot=int(b.MavAutopilot.MAV_AUTOPILOT_INVALID)))
        write(self.ep.pipe.sign(frame))

    def _quiet(self) -> float:
        """Three packet times of the link (`quiet`, when the caller knows the rate) or of what
        actually arrives, whichever is longer; never below the OS's scheduling jitter."""
        q = max(QUIET_MIN, 3 * self._gap, self.quiet or 0.0)
        return min(q, max(QUIET_MAX, self.quiet or 0.0))

    # -- sending --------------------------------------------------------------------------------
    async def _pump(self) -> None:
        loop = self._loop or asyncio.get_running_loop()
        target: float | None = None
        while not self._closed:
            real = loop.time()
            now = self.now()
            if target is not None and target <= real < target + CATCH_UP:
                # woken a little late by the timer: keep the pacer's schedule rather than
                # losing the lateness on every packet (the clock still never goes back)
                now = max(target, self.ep.now)
            if self.hello is not None and self.last_rx is None and (self._hello_due is None or now >= self._hello_due):
                msg = self.hello()
                if msg is not None:
                    self.ep.send_message(msg)
                self._hello_due = now + self.hello_interval
            sent = 0
            while sent < BURST:
                pkt = self.ep.poll(now)
                if pkt is None:
                    break
                self.transport.send(pkt)
                sent += 1
                self.stats.packets_out += 1
                self.stats.bytes_out += len(pkt)
            pipe = self.pipe
            if pipe is not None and pipe.is_open:
                self._check_pipe(real)
            while pipe is not None and pipe.is_open and pipe.backlog() < self.pipe_window and sent < 4 * BURST:
                frame = self.ep.pipe.poll(now)
                if frame is None:
                    break
                pipe.write(frame)
                sent += 1
                self.stats.pipe_frames += 1
            self.stats.wakeups += 1
            if sent == 0:
                self.stats.idle_wakeups += 1
            flush_at = None
            since = self.ep.pending_since()
            if since is not None:
                flush_at = since + self._quiet()
                if flush_at <= real:
                    self.ep.flush(max(now, real), self._quiet())
                    self.stats.flushes += 1
                    continue  # send what the frames it released called for
            if sent >= BURST:
                target = None
                await asyncio.sleep(0)
                continue
            hello_at = self._hello_due if self.hello is not None and self.last_rx is None else None
            times = [t for t in (self.ep.wakeup(), flush_at, hello_at) if t is not None]
            if pipe is not None and pipe.is_open and pipe.backlog() >= self.pipe_window:
                # the pipeline's socket is behind: look again shortly rather than at the pacer's time
                times = [max(t, real + PIPE_WAIT) for t in times]
            target = min(times) if times else None
            if target is not None and target <= loop.time() and sent == 0:
                target = loop.time() + SPIN_GUARD  # due but nothing to do: do not spin
            await self._sleep_until(loop, target)

    async def _sleep_until(self, loop: asyncio.AbstractEventLoop, when: float | None) -> None:
        if when is not None and when <= loop.time():
            await asyncio.sleep(0)
            return
        self._waiter = loop.create_future()
        handle = loop.call_at(when, self.kick) if when is not None else None
        try:
            await self._waiter
        finally:
            self._waiter = None
            if handle is not None:
                handle.cancel()


def hello(sysid: int, spec: Any, b: Any) -> Callable[[], Any] | None:
    """For an end that reaches out over UDP: a HEARTBEAT each second until the peer is heard,
    so that a peer listening with udpin learns where to answer (`b`: the link's Bindings;
    sysid 255 is the tablet, a ground station; anything else an onboard controller)."""
    if spec.kind != "udpout":
        return None
    kind = b.MavType.MAV_TYPE_GCS if sysid == 255 else b.MavType.MAV_TYPE_ONBOARD_CONTROLLER
    return lambda: b.Heartbeat(type=int(kind), autopilot=int(b.MavAutopilot.MAV_AUTOPILOT_INVALID))


def unknown_note(b: Any, event: tuple[Any, int, tuple[int, int]]) -> str:
    """The words for an "unknown-message" event: once per msgid, never an error."""
    source, msgid, (sysid, compid) = event
    where = f" at {addr_text(source)}" if source is not None else ""
    return (f"{sysid}/{compid}{where} sends msgid {msgid}, which dialect {b.name} does not have: counted and "
            "ignored (do both ends use the same --dialect?)")


__all__ = ["Runner", "RunnerStats", "hello", "unknown_note"]
