"""The probe protocol of link measurements (`ttctl bench serve`, `ttctl bench link --to`), sans IO.

The wire protocol is plain UDP: each datagram is one DTT packet of at most 100 bytes (not a
MAVLink frame; `ttctl link relay` and DJI's link carry any datagram up to 100 bytes). Every
message starts with the same 6-byte header, big-endian:

    magic 0xB7 | type (1 byte, ASCII) | run id (u16) | seq (u16)

Times are microseconds of the sender's own wall clock modulo 2**32 (u32); only differences of
stamps of one clock are trusted, plus the NTP-style offset estimate below.

client -> server                           server -> client
- `E` echo:  hdr + t1                      `e`: hdr + t1 + t2 (server receive) + t3 (server send)
- `O` open an uplink run of `seq` probes   `o`: hdr (acknowledged; repeats are harmless)
- `P` probe: hdr + t_send + padding        (nothing: counted, for the run's report)
- `Q` report page `seq` of a run           `R`: page 0: received, range pages, first and last
                                            receive time, one-way delay (server receive - client
                                            send, raw: the client removes the clock offset) as
                                            d0 + p50/p95/min deltas, bytes, median gap
                                            between arrivals (us); page k >= 1: up to
                                            20 ranges (first, last) of sequence numbers received
- `D` downlink run: hdr(seq = count) +     `d`: hdr (acknowledged), then `seq` probes `P` of
  size (u8) + rate (u32, milli-Hz)          that size at that rate, stamped with the server clock

The round trip of an echo is (t4 - t1) - (t3 - t2) and the offset of the server's clock is
((t2 - t1) + (t3 - t4)) / 2, as NTP estimates them. A probe is 10 bytes of header (magic,
type, run, seq, t_send) padded up to the probe size: probes are 10..100 bytes.

The server answers whoever asks, at the address the request came from. It ignores datagrams
without the magic, of unknown types, too short, and probes or report requests of runs nobody
opened (strangers). Memory is bounded: at most MAX_RUNS uplink runs (the oldest forgotten
first) of at most MAX_COUNT probes each, at most MAX_SENDERS downlink runs at once.
"""

from __future__ import annotations

import asyncio
import struct
import time
from collections import OrderedDict
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any, TypeVar

N = TypeVar("N", int, float)

MAGIC = 0xB7
HDR = struct.Struct(">BcHH")
STAMP = struct.Struct(">I")
PROBE_HDR = HDR.size + STAMP.size  # 10: the smallest probe
ECHO_REPLY = struct.Struct(">BcHHIII")
SUMMARY = struct.Struct(">BcHHHHIIIiiiII")
DOWN_REQ = struct.Struct(">BcHHBI")
RANGE = struct.Struct(">HH")
RANGES_PER_PAGE = 20
MTU = 100
MAX_COUNT = 10_000
MAX_RUNS = 32
MAX_SENDERS = 4
MAX_RATE_HZ = 1000.0
MOD = 1 << 32
DEFAULT_LISTEN = "udpin:0.0.0.0:14570"


def now_us() -> int:
    """This host's clock as the protocol stamps it."""
    return (time.time_ns() // 1000) % MOD


def signed(d: int) -> int:
    """A difference of two u32 stamps as a signed number of microseconds."""
    d %= MOD
    return d - MOD if d >= MOD // 2 else d


def header(kind: bytes, run: int, seq: int) -> bytes:
    return HDR.pack(MAGIC, kind, run, seq)


def probe(run: int, seq: int, size: int, stamp: int) -> bytes:
    return (header(b"P", run, seq) + STAMP.pack(stamp)).ljust(size, b"\x55")


def parse(data: bytes) -> tuple[bytes, int, int] | None:
    """(type, run, seq) of a datagram of this protocol, or None for anything else."""
    if len(data) < HDR.size or len(data) > MTU or data[0] != MAGIC:
        return None
    _, kind, run, seq = HDR.unpack_from(data)
    return kind, run, seq


def pct(values: Sequence[N], q: float) -> N:
    """The q-quantile of `values` (nearest rank; not empty)."""
    s = sorted(values)
    return s[min(len(s) - 1, int(q * (len(s) - 1) + 0.5))]



def loss_runs(received: list[tuple[int, int]], count: int) -> list[int]:
    """Lengths of the runs of consecutive lost sequence numbers of 0..count-1, given the ranges
    (first, last) received."""
    runs = []
    nxt = 0
    for a, b in sorted(received):
        if a > nxt:
            runs.append(a - nxt)
        nxt = max(nxt, b + 1)
    if nxt < count:
        runs.append(count - nxt)
    return runs


def ranges(seqs: Iterable[int]) -> list[tuple[int, int]]:
    """Sequence numbers as sorted ranges (first, last)."""
    out: list[tuple[int, int]] = []
    for s in sorted(seqs):
        if out and s == out[-1][1] + 1:
            out[-1] = (out[-1][0], s)
        else:
            out.append((s, s))
    return out


@dataclass
class UpRun:
    count: int
    seen: bytearray = field(init=False)
    delays: list[int] = field(default_factory=list)  # server receive - client send, raw u32 differences
    gaps: list[int] = field(default_factory=list)  # microseconds between consecutive arrivals
    received: int = 0
    bytes: int = 0
    first_rx: int = 0
    last_rx: int = 0

    def __post_init__(self) -> None:
        self.seen = bytearray(self.count)

    def ranges(self) -> list[tuple[int, int]]:
        out: list[tuple[int, int]] = []
        start = None
        for i, v in enumerate(self.seen):
            if v and start is None:
                start = i
            elif not v and start is not None:
                out.append((start, i - 1))
                start = None
        if start is not None:
            out.append((start, self.count - 1))
        return out


@dataclass
class DownRun:
    count: int
    size: int
    rate_hz: float


class Server:
    """The protocol without IO: `handle` takes a datagram and the receive time, returns the
    replies; `start_down` is called for a new downlink run (the IO layer sends its probes)."""

    def __init__(self, clock: Callable[[], int] = now_us,
                 start_down: Callable[[int, DownRun, Any], bool] | None = None) -> None:
        self.clock = clock
        self.runs: OrderedDict[int, UpRun] = OrderedDict()
        self.down: dict[int, DownRun] = {}
        self.start_down = start_down
        self.ignored = 0
        self.probes = 0

    def handle(self, data: bytes, t_rx: int, source: Any = None) -> list[bytes]:
        msg = parse(data)
        if msg is None:
            self.ignored += 1
            return []
        kind, run, seq = msg
        if kind == b"E" and len(data) >= PROBE_HDR:
            (t1,) = STAMP.unpack_from(data, HDR.size)
            return [ECHO_REPLY.pack(MAGIC, b"e", run, seq, t1, t_rx, self.clock())]
        if kind == b"O" and 1 <= seq <= MAX_COUNT:
            if run not in self.runs or self.runs[run].count != seq:
                self.runs[run] = UpRun(seq)
                while len(self.runs) > MAX_RUNS:
                    self.runs.popitem(last=False)
            return [header(b"o", run, seq)]
        if kind == b"P" and len(data) >= PROBE_HDR:
            r = self.runs.get(run)
            if r is None or seq >= r.count:
                self.ignored += 1
                return []
            self.probes += 1
            if r.seen[seq]:
                return []  # a duplicate: counted once
            r.seen[seq] = 1
            (t_send,) = STAMP.unpack_from(data, HDR.size)
            r.delays.append(signed(t_rx - t_send))
            if not r.received:
                r.first_rx = t_rx
            else:
                r.gaps.append(signed(t_rx - r.last_rx))
            r.received += 1
            r.bytes += len(data)
            r.last_rx = t_rx
            return []
        if kind == b"Q":
            r = self.runs.get(run)
            if r is None:
                self.ignored += 1
                return []
            return [self.report_page(run, r, seq)]
        if kind == b"D" and len(data) >= DOWN_REQ.size:
            _, _, _, count, size, mhz = DOWN_REQ.unpack_from(data)
            rate = mhz / 1000.0
            if not (1 <= count <= MAX_COUNT and PROBE_HDR <= size <= MTU and 0 < rate <= MAX_RATE_HZ):
                self.ignored += 1
                return []
            if run not in self.down:
                if len(self.down) >= MAX_SENDERS:
                    return []  # busy: the client retries
                job = DownRun(count, size, rate)
                self.down[run] = job
                if self.start_down is not None and not self.start_down(run, job, source):
                    del self.down[run]
                    return []
            return [header(b"d", run, count)]
        self.ignored += 1
        return []

    def finished(self, run: int) -> None:
        self.down.pop(run, None)

    @staticmethod
    def report_page(run: int, r: UpRun, page: int) -> bytes:
        ranges = r.ranges()
        pages = (len(ranges) + RANGES_PER_PAGE - 1) // RANGES_PER_PAGE
        if page == 0:
            d0 = r.delays[0] if r.delays else 0
            rel = [d - d0 for d in r.delays] or [0]
            return SUMMARY.pack(MAGIC, b"R", run, 0, r.received, pages, r.first_rx, r.last_rx, d0 % MOD,
                                pct(rel, 0.5), pct(rel, 0.95), min(rel), r.bytes,
                                max(0, pct(r.gaps, 0.5)) if r.gaps else 0)
        part = ranges[(page - 1) * RANGES_PER_PAGE:page * RANGES_PER_PAGE]
        return header(b"R", run, page) + b"".join(RANGE.pack(a, b) for a, b in part)


async def send_down(core: Server, run: int, job: DownRun, send: Callable[[bytes], Any]) -> None:
    """A downlink run: job.count probes at job.rate_hz, then the run is forgotten."""
    loop = asyncio.get_running_loop()
    try:
        await asyncio.sleep(0.05)  # the acknowledgement goes first
        start = loop.time()
        for i in range(job.count):
            delay = start + i / job.rate_hz - loop.time()
            if delay > 0:
                await asyncio.sleep(delay)
            send(probe(run, i, job.size, now_us()))
        await asyncio.sleep(2.0)  # a repeated request for this run is still acknowledged, not re-sent
    finally:
        core.finished(run)


class LinkProbes:
    """The probe service beside a MAVLink node on its DTT link (`ttctl emulate onboard`), so that
    `ttctl bench link --to` measures the link to a running onboard end.

    A packet is taken as a probe when it parses as one and no frame is half-received from its
    source (a frame's continuation may begin with any byte); it then does not go to the MAVLink
    receiver. Replies go to the probe's source alone. A continuation piece whose first packet was
    lost could still parse as a probe (about 5 in 65536); the worst it could do is ask for a
    downlink run, so a run starts only for a source whose echo was answered in the last
    ECHO_FRESH_S seconds, as `bench link` always does first."""

    ECHO_FRESH_S = 600.0

    def __init__(self, send_to: Callable[[bytes, Any], Any], mid_frame: Callable[[Any], bool],
                 log: Callable[[str], None], clock: Callable[[], float] = time.monotonic) -> None:
        self.send_to, self.mid_frame, self.log, self.clock = send_to, mid_frame, log, clock
        self.core = Server(start_down=self._start_down)
        self.echoed: OrderedDict[Any, float] = OrderedDict()
        self.tasks: set[asyncio.Task[None]] = set()

    def take(self, data: bytes, source: Any) -> bool:
        msg = parse(data)
        if msg is None or self.mid_frame(source):
            return False
        for reply in self.core.handle(data, now_us(), source):
            if msg[0] == b"E":
                self.echoed[source] = self.clock()
                self.echoed.move_to_end(source)
                while len(self.echoed) > MAX_RUNS:
                    self.echoed.popitem(last=False)
            self.send_to(reply, source)
        return True

    def _start_down(self, run: int, job: DownRun, source: Any) -> bool:
        heard = self.echoed.get(source)
        if heard is None or self.clock() - heard > self.ECHO_FRESH_S:
            return False
        self.log(f"bench: downlink run {run}: {job.count} x {job.size} B at {job.rate_hz:g} Hz")
        task = asyncio.get_running_loop().create_task(
            send_down(self.core, run, job, lambda data: self.send_to(data, source)))
        self.tasks.add(task)
        task.add_done_callback(self.tasks.discard)
        return True

    def close(self) -> None:
        for t in list(self.tasks):
            t.cancel()
