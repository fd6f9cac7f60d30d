"""`ttctl bench link --to ENDPOINT`: the thesis's measurement against a live `ttctl bench serve`.

The protocol is in ttctl.link.probes. The run, in real time:

1. Latency: ECHOES round-trip probes, one at a time; RTT p50/p95 and the server clock's offset
   (NTP-style: the median offset of the echoes with the shortest round trips). Like NTP's, the
   estimate assumes both ways take as long: on DTT's asymmetric link it carries half the
   asymmetry (uplink delays read that much low, downlink ones that much high). No answer
   within UNREACHABLE_S: the peer is unreachable (exit 2).
2. Uplink, per size: open a run, send --count probes paced at --rate bytes per second (default:
   the --profile's uplink capacity at 10 m; a UDP sender has no completion callback, so it
   cannot send "as fast as the link takes them"). Paced above the link's rate it measures the
   link's capacity (rx_rate_Bps: what arrives per second) and the buffer's overflow; below
   it, the radio's own loss. Then the server's report: what arrived, as ranges of sequence
   numbers, from which come the loss runs (lengths of consecutive losses).
3. Downlink, per rate: the server sends --count 100-byte probes at that rate; the client counts.

Rows: sent, received, lost, loss runs (count, mean, max), seconds, throughput_Bps (what the
sender pushed per second), goodput_Bps (what arrived, per second of sending), rx_rate_Bps (the
receiver's rate between its first and last arrival, as the model's downlink throughput),
capacity_Bps (size / the median gap between consecutive arrivals: the link's rate when the sender
outpaces it, robust to loss below one half; else just the sender's pace), one-way
delay p50/p95 (receive - send - clock offset). A peer that stops answering ends the run: the
rows so far are kept, marked partial, exit 1.

Before anything is sent through a relay the client sends a MAVLink HEARTBEAT: `ttctl link relay`
answers only addresses that sent a valid MAVLink frame; the server ignores it.
"""

from __future__ import annotations

import asyncio
import contextlib
import csv
import io
import itertools
import json
import math
import random
import statistics
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ..errors import Fail
from ..link import probes as P
from ..link.probes import loss_runs
from ..link.probes import pct as _pct
from ..link.probes import ranges as _ranges

ECHOES = 20
UNREACHABLE_S = 3.0
PATIENCE_S = 10.0
HELLO_S = 10.0
DOWN_SIZE = 100
CSV_FIELDS = ("direction", "size", "rate_hz", "sent", "received", "lost", "loss", "loss_runs", "loss_run_mean",
              "loss_run_max", "seconds", "throughput_Bps", "goodput_Bps", "rx_rate_Bps", "capacity_Bps", "owd_p50_ms",
              "owd_p95_ms", "owd_min_ms", "partial", "label", "endpoint", "time", "ttctl_version")


class Silent(Exception):
    """The peer stopped answering."""


@dataclass
class Options:
    to: str
    direction: str = "both"
    sizes: list[int] = field(default_factory=lambda: [10, 50, 100])
    rates: list[float] = field(default_factory=lambda: [5.0, 10.0, 20.0])
    count: int = 100
    rate: float | None = None
    profile: str | None = None
    label: str = ""
    as_json: bool = False
    output: str | None = None
    plot: str | None = None
    profile_file: str | None = None
    distance: float | None = None  # metres, kept in the conditions (for `ttctl link fit`)


def parse_list(text: str, what: str, kind: Callable[[str], Any]) -> list[Any]:
    try:
        out = [kind(x.strip()) for x in text.split(",") if x.strip()]
    except ValueError:
        raise Fail(f"{what} wants comma-separated numbers, not {text!r}") from None
    if not out:
        raise Fail(f"{what} is empty")
    return out


def check(o: Options) -> tuple[Any, float]:
    """Everything that can be refused, refused before measuring: (endpoint spec, pace B/s)."""
    from ..link.model import ProfileError, load_profile
    from ..link.transport import TransportError, parse_spec
    from ..safeio import output_problem

    try:
        spec = parse_spec(o.to, udp="udpout", allowed=("udpout",))
    except TransportError as e:
        raise Fail(f"--to: {e} (bench serve speaks plain UDP datagrams)") from None
    if o.direction not in ("up", "down", "both"):
        raise Fail(f"--direction must be up, down or both, not {o.direction!r}")
    for s in o.sizes:
        if not P.PROBE_HDR <= s <= P.MTU:
            raise Fail(f"--sizes: {s} is not a probe size: {P.PROBE_HDR}..{P.MTU} bytes (the DTT MTU is {P.MTU}; "
                       f"a probe's header is {P.PROBE_HDR})")
    for r in o.rates:
        if not 0 < r <= P.MAX_RATE_HZ:
            raise Fail(f"--rates: {r:g} Hz is not in (0, {P.MAX_RATE_HZ:g}]")
    if not 1 <= o.count <= P.MAX_COUNT:
        raise Fail(f"--count must be in 1..{P.MAX_COUNT}")
    if o.distance is not None and not (0 <= o.distance < 1e6):
        raise Fail("--distance must be a number of metres >= 0")
    if o.rate is not None and o.rate <= 0:
        raise Fail("--rate must be a positive number of bytes per second")
    try:
        pace = o.rate or load_profile(o.profile, o.profile_file).capacity_Bps("up", o.distance or 10.0)
    except ProfileError as e:
        raise Fail(str(e)) from None
    if o.output is not None:
        if not o.output.endswith((".json", ".csv")):
            raise Fail(f"-o {o.output}: the name must end in .json or .csv")
        problem = output_problem(o.output)
        if problem:
            raise Fail(problem)
    if o.plot is not None:
        from .plots import require_matplotlib

        require_matplotlib(o.plot)
    return spec, pace


class _Proto(asyncio.DatagramProtocol):
    def __init__(self, owner: Client) -> None:
        self.owner = owner

    def datagram_received(self, data: bytes, addr: Any) -> None:
        self.owner.received(data)

    def error_received(self, exc: Exception) -> None:
        pass  # ICMP port unreachable: nobody there (yet); the timeouts tell


class Client:
    def __init__(self) -> None:
        self.tr: asyncio.DatagramTransport | None = None
        self.waiters: dict[tuple[bytes, int, int], asyncio.Future[tuple[bytes, int]]] = {}
        self.down_run: int | None = None
        self.down_seen: dict[int, int] = {}  # seq -> receive stamp - send stamp (raw)
        self.down_first = self.down_last = 0.0
        self.down_bytes = 0
        self.down_times: list[float] = []
        self.on_down: Callable[[], None] = lambda: None
        self.used: set[int] = set()
        self.last_hello = -HELLO_S

    async def open(self, host: str, port: int) -> None:
        loop = asyncio.get_running_loop()
        try:
            tr, _ = await loop.create_datagram_endpoint(lambda: _Proto(self), remote_addr=(host, port))
        except OSError as e:
            from ..link.transport import _os_reason

            raise Fail(f"cannot send to udpout:{host}:{port}: {_os_reason(e)}") from None
        self.tr = tr

    def send(self, data: bytes) -> None:
        if self.tr is not None and not self.tr.is_closing():
            self.tr.sendto(data)

    def keepalive(self) -> None:
        """A HEARTBEAT every HELLO_S: a relay forgets addresses silent for a minute."""
        if time.monotonic() - self.last_hello >= HELLO_S:
            self.hello()

    def hello(self) -> None:
        """A HEARTBEAT (common.xml's, the same bytes in every dialect on the link): a relay or an
        onboard end learns this address from a valid frame; the probes themselves are not MAVLink."""
        from .shipped import bindings

        b = bindings()
        self.last_hello = time.monotonic()
        hb = b.Heartbeat(type=int(b.MavType.MAV_TYPE_GCS), autopilot=int(b.MavAutopilot.MAV_AUTOPILOT_INVALID))
        self.send(b.encoder(255, 190).encode(hb))

    def new_run(self) -> int:
        while True:
            r = random.randrange(1, 1 << 16)
            if r not in self.used:
                self.used.add(r)
                return r

    def received(self, data: bytes) -> None:
        t = P.now_us()
        msg = P.parse(data)
        if msg is None:
            return
        kind, run, seq = msg
        if kind == b"P" and run == self.down_run and len(data) >= P.PROBE_HDR:
            if seq not in self.down_seen:
                (t_send,) = P.STAMP.unpack_from(data, P.HDR.size)
                self.down_seen[seq] = P.signed(t - t_send)
                now = time.monotonic()
                if len(self.down_seen) == 1:
                    self.down_first = now
                self.down_last = now
                self.down_times.append(now)
                self.down_bytes += len(data)
                self.on_down()
            return
        fut = self.waiters.get((kind, run, seq))
        if fut is not None and not fut.done():
            fut.set_result((data, t))

    async def ask(self, request: bytes, reply: tuple[bytes, int, int], timeout: float, tries: int,
                  copies: int = 2) -> tuple[bytes, int]:
        loop = asyncio.get_running_loop()
        for _ in range(tries):
            fut: asyncio.Future[tuple[bytes, int]] = loop.create_future()
            self.waiters[reply] = fut
            for _ in range(copies):  # a lossy link loses in bursts: each copy moves it on
                self.send(request)
            try:
                return await asyncio.wait_for(fut, timeout)
            except TimeoutError:
                continue
            finally:
                self.waiters.pop(reply, None)
        raise Silent

    def close(self) -> None:
        if self.tr is not None:
            self.tr.close()


def _loss_fields(runs: list[int], sent: int, received: int) -> dict[str, Any]:
    return {"lost": sent - received, "loss": round((sent - received) / sent, 4), "loss_runs": len(runs),
            "loss_run_mean": round(statistics.mean(runs), 2) if runs else 0.0, "loss_run_max": max(runs, default=0)}


class Measure:
    def __init__(self, o: Options, pace: float, client: Client, bar: Any) -> None:
        self.o, self.pace, self.c, self.bar = o, pace, client, bar
        self.offset_us = 0.0
        self.rtt_p95 = 0.1
        self.done = 0
        self.total = 0

    def _timeout(self) -> float:
        return max(0.5, 3 * self.rtt_p95)

    def _tries(self) -> int:
        """Requests and answers are lost too (in bursts, on a bad link): keep asking for
        PATIENCE_S, or 10 round trips if longer, before calling the peer silent."""
        return max(4, math.ceil(max(PATIENCE_S, 10 * self._timeout()) / self._timeout()))

    async def latency(self) -> dict[str, Any]:
        c = self.c
        run = c.new_run()
        loop = asyncio.get_running_loop()
        samples: list[tuple[float, float]] = []  # (rtt us, offset us)
        end = loop.time() + UNREACHABLE_S
        seq = 0
        while len(samples) < ECHOES:
            if not samples and loop.time() >= end:
                raise Fail(f"no answer from {self.o.to} within {UNREACHABLE_S:g} s: is `ttctl bench serve` "
                           f"running there, and the link up?")
            if samples and seq > 3 * ECHOES:
                break
            if seq % 5 == 0:
                c.hello()
            t1 = P.now_us()
            req = (P.header(b"E", run, seq) + P.STAMP.pack(t1)).ljust(P.ECHO_REPLY.size, b"\x55")
            with contextlib.suppress(Silent):
                data, t4 = await c.ask(req, (b"e", run, seq), 0.5 if not samples else self._timeout(), 1, 1)
                _, _, _, _, t1r, t2, t3 = P.ECHO_REPLY.unpack(data)
                rtt = P.signed(t4 - t1r) - P.signed(t3 - t2)
                off = (P.signed(t2 - t1r) + P.signed(t3 - t4)) / 2
                samples.append((rtt, off))
                self.rtt_p95 = _pct([s[0] for s in samples], 0.95) / 1e6
            seq += 1
            self.bar.update(len(samples), ECHOES, "latency")
        rtts = [s[0] for s in samples]
        best = sorted(samples)[:max(1, len(samples) // 4)]
        self.offset_us = statistics.median(s[1] for s in best)
        return {"echoes": len(samples), "sent": seq, "rtt_p50_ms": round(_pct(rtts, 0.5) / 1e3, 2),
                "rtt_p95_ms": round(_pct(rtts, 0.95) / 1e3, 2), "rtt_min_ms": round(min(rtts) / 1e3, 2),
                "owd_rtt_half_ms": round(_pct(rtts, 0.5) / 2e3, 2),
                "clock_offset_ms": round(self.offset_us / 1e3, 2)}

    async def uplink(self, size: int) -> dict[str, Any]:
        c, n = self.c, self.o.count
        run = c.new_run()
        c.hello()
        await c.ask(P.header(b"O", run, n), (b"o", run, n), self._timeout(), self._tries())
        loop = asyncio.get_running_loop()
        interval = size / self.pace
        start = loop.time()
        for i in range(n):
            delay = start + i * interval - loop.time()
            if delay > 0:
                await asyncio.sleep(delay)
            c.send(P.probe(run, i, size, P.now_us()))
            c.keepalive()
            self.done += 1
            if i % 5 == 0 or i == n - 1:
                self.bar.update(self.done, self.total, f"up {size} B")
        seconds = n * interval  # the sender's time: n probes, one interval each
        await asyncio.sleep(2 * self.rtt_p95 + 0.3)  # the last probes drain through the link
        c.keepalive()
        data, _ = await c.ask(P.header(b"Q", run, 0), (b"R", run, 0), self._timeout(), self._tries())
        (_, _, _, _, received, pages, first_rx, last_rx, d0, dp50, dp95, dmin, _nbytes,
         gap) = P.SUMMARY.unpack(data)
        ranges: list[tuple[int, int]] = []
        for page in range(1, pages + 1):
            body, _ = await c.ask(P.header(b"Q", run, page), (b"R", run, page), self._timeout(), self._tries())
            ranges += [P.RANGE.unpack_from(body, k) for k in range(P.HDR.size, len(body), P.RANGE.size)]
        span = P.signed(last_rx - first_rx) / 1e6
        row: dict[str, Any] = {"direction": "up", "size": size, "sent": n, "received": received}
        row.update(_loss_fields(loss_runs(ranges, n), n, received))
        row.update({"seconds": round(seconds, 3), "throughput_Bps": round(n * size / seconds, 1),
                    "goodput_Bps": round(received * size / seconds, 1),
                    "rx_rate_Bps": round((received - 1) * size / span, 1) if span > 0 and received > 1 else 0.0,
                    "capacity_Bps": round(size * 1e6 / gap, 1) if gap > 0 else 0.0})
        if received:
            row["owd_p50_ms"] = round((P.signed(d0 + dp50) - self.offset_us) / 1e3, 2)
            row["owd_p95_ms"] = round((P.signed(d0 + dp95) - self.offset_us) / 1e3, 2)
            row["owd_min_ms"] = round((P.signed(d0 + dmin) - self.offset_us) / 1e3, 2)
        return row

    async def downlink(self, rate: float) -> dict[str, Any]:
        c, n = self.c, self.o.count
        run = c.new_run()
        c.down_run, c.down_seen, c.down_bytes, c.down_times = run, {}, 0, []
        base = self.done

        def progress() -> None:
            k = len(c.down_seen)
            if k % 5 == 0 or k == n:
                self.bar.update(base + k, self.total, f"down {rate:g} Hz")

        c.on_down = progress
        c.hello()
        req = P.DOWN_REQ.pack(P.MAGIC, b"D", run, n, DOWN_SIZE, round(rate * 1000))
        try:
            await c.ask(req, (b"d", run, n), self._timeout(), self._tries())
        except Silent:
            if not c.down_seen:
                raise
        loop = asyncio.get_running_loop()
        end = loop.time() + n / rate + 2 * self.rtt_p95 + 1.0
        while loop.time() < end and len(c.down_seen) < n:
            await asyncio.sleep(0.05)
            c.keepalive()
        c.down_run = None
        self.done = base + n
        got = len(c.down_seen)
        if got == 0:
            raise Silent
        delays = list(c.down_seen.values())
        d0 = delays[0]
        rel = [P.signed(d - d0) for d in delays]
        span = c.down_last - c.down_first
        times = sorted(c.down_times)
        gaps = [b - a for a, b in itertools.pairwise(times)]
        gap = statistics.median(gaps) if gaps else 0.0
        row: dict[str, Any] = {"direction": "down", "size": DOWN_SIZE, "rate_hz": rate, "sent": n, "received": got}
        row.update(_loss_fields(loss_runs(_ranges(list(c.down_seen)), n), n, got))
        seconds = n / rate
        row.update({"seconds": round(seconds, 3), "throughput_Bps": round(n * DOWN_SIZE / seconds, 1),
                    "goodput_Bps": round(got * DOWN_SIZE / seconds, 1),
                    "rx_rate_Bps": round((got - 1) * DOWN_SIZE / span, 1) if got > 1 and span > 0 else 0.0,
                    "capacity_Bps": round(DOWN_SIZE / gap, 1) if gap > 0 else 0.0,
                    "owd_p50_ms": round((P.signed(d0 + _pct(rel, 0.5)) + self.offset_us) / 1e3, 2),
                    "owd_p95_ms": round((P.signed(d0 + _pct(rel, 0.95)) + self.offset_us) / 1e3, 2),
                    "owd_min_ms": round((P.signed(d0 + min(rel)) + self.offset_us) / 1e3, 2)})
        return row


def _version() -> str:
    try:
        from importlib.metadata import version

        return version("ttctl")
    except Exception:  # an uninstalled tree
        return "unknown"


def write_atomically(path: str, text: str) -> None:
    from .plots import write_atomically as write_file

    write_file(path, lambda fh: fh.write(text.encode("utf-8")))


def to_csv(report: dict[str, Any]) -> str:
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=CSV_FIELDS, extrasaction="ignore")
    w.writeheader()
    cond = report["conditions"]
    for row in report["uplink"]["rows"] + report["downlink"]["rows"]:
        w.writerow({**row, "partial": report["partial"], "label": cond["label"], "endpoint": cond["endpoint"],
                    "time": cond["time"], "ttctl_version": cond["ttctl_version"]})
    return buf.getvalue()


def plot_live(report: dict[str, Any], path: str) -> None:
    from .plots import _figure, save_atomically

    fig = _figure(figsize=(10, 4), layout="constrained")
    ax1, ax2 = fig.subplots(1, 2)
    up = report["uplink"]["rows"]
    ax1.plot([r["size"] for r in up], [r["rx_rate_Bps"] for r in up], "o-", label="received B/s")
    ax1.plot([r["size"] for r in up], [r["loss"] * 100 for r in up], "s--", label="lost %")
    ax1.set(title=f"uplink, paced at {report['uplink']['pace_Bps']:.0f} B/s", xlabel="probe size (bytes)")
    ax1.legend()
    down = report["downlink"]["rows"]
    ax2.plot([r["rate_hz"] for r in down], [r["rx_rate_Bps"] for r in down], "o-", label="received B/s")
    ax2.plot([r["rate_hz"] for r in down], [r["loss"] * 100 for r in down], "s--", label="lost %")
    ax2.set(title=f"downlink, {DOWN_SIZE}-byte probes", xlabel="send rate (Hz)")
    ax2.legend()
    fig.suptitle(f"{report['conditions']['endpoint']} {report['conditions']['label']}".strip())
    save_atomically(fig, path)


def run(o: Options) -> int:
    from ..commands.common import Bar, Signals

    spec, pace = check(o)
    ups = o.sizes if o.direction in ("up", "both") else []
    downs = o.rates if o.direction in ("down", "both") else []
    report: dict[str, Any] = {
        "conditions": {"label": o.label, "endpoint": str(spec), "time": time.strftime("%Y-%m-%dT%H:%M:%SZ",
                                                                                      time.gmtime()),
                       "ttctl_version": _version(), "count": o.count, "distance_m": o.distance},
        "partial": False, "latency": None,
        "uplink": {"pace_Bps": round(pace, 1), "sizes": ups, "rows": []},
        "downlink": {"size": DOWN_SIZE, "rates_hz": downs, "rows": []},
    }
    bar = Bar(f"bench link {spec}", ECHOES)
    stopped = False

    async def main() -> None:
        nonlocal stopped
        loop = asyncio.get_running_loop()
        wake = asyncio.Event()
        sigs = Signals(loop, wake)
        c = Client()
        m = Measure(o, pace, c, bar)
        m.total = o.count * (len(ups) + len(downs))
        try:
            await c.open(spec.host, spec.port)

            async def body() -> None:
                report["latency"] = await m.latency()
                bar.log(f"latency: RTT p50 {report['latency']['rtt_p50_ms']} ms, p95 "
                        f"{report['latency']['rtt_p95_ms']} ms")
                for size in ups:
                    row = await m.uplink(size)
                    report["uplink"]["rows"].append(row)
                    bar.log(f"up {size} B: {row['received']}/{row['sent']} arrived, {row['rx_rate_Bps']:.0f} B/s")
                for rate in downs:
                    row = await m.downlink(rate)
                    report["downlink"]["rows"].append(row)
                    bar.log(f"down {rate:g} Hz: {row['received']}/{row['sent']} arrived, "
                            f"{row['rx_rate_Bps']:.0f} B/s")

            task = loop.create_task(body())
            stop = loop.create_task(sigs.stop.wait())
            await asyncio.wait({task, stop}, return_when=asyncio.FIRST_COMPLETED)
            if not task.done():
                stopped = True
                task.cancel()
                with contextlib.suppress(asyncio.CancelledError):
                    await task
            else:
                stop.cancel()
                try:
                    task.result()
                except Silent:
                    report["partial"] = True
        finally:
            c.close()
            sigs.remove()
            bar.stop()

    asyncio.run(main())
    report["partial"] = report["partial"] or stopped
    rows = report["uplink"]["rows"] + report["downlink"]["rows"]
    if o.output is not None:
        write_atomically(o.output, to_csv(report) if o.output.endswith(".csv") else json.dumps(report, indent=2) + "\n")
    if o.plot is not None and rows:
        plot_live(report, o.plot)
    if o.as_json:
        print(json.dumps(report, indent=2))
    else:
        _print(report)
    if report["partial"]:
        why = "interrupted" if stopped else f"{o.to} stopped answering"
        print(f"ttctl: error: {why}: {len(rows)} row(s) measured, marked partial", file=sys.stderr, flush=True)
        return 1
    return 0


def _print(report: dict[str, Any]) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console()
    lat = report["latency"]
    if lat:
        console.print(f"{report['conditions']['endpoint']}: RTT p50 {lat['rtt_p50_ms']} ms, "
                      f"p95 {lat['rtt_p95_ms']} ms, "
                      f"clock offset {lat['clock_offset_ms']} ms ({lat['echoes']} echoes)", highlight=False)
    cols = ("sent", "lost", "loss_run_mean", "loss_run_max", "throughput_Bps", "rx_rate_Bps", "capacity_Bps",
            "owd_p50_ms", "owd_p95_ms")
    heads = ("sent", "lost", "run mean", "run max", "sent B/s", "recv B/s", "cap. B/s", "delay p50 ms", "p95")
    for name, key, first in (("uplink", "size", "size B"), ("downlink", "rate_hz", "rate Hz")):
        rows = report[name]["rows"]
        if not rows:
            continue
        extra = f", paced at {report['uplink']['pace_Bps']:g} B/s" if name == "uplink" else \
            f", {DOWN_SIZE}-byte probes"
        t = Table(title=f"{name} to {report['conditions']['endpoint']}{extra}"
                        + (" (partial)" if report["partial"] else ""))
        for h in (first, *heads):
            t.add_column(h, justify="right")
        for r in rows:
            t.add_row(f"{r[key]:g}", *(_num(r.get(k)) for k in cols))
        console.print(t)


def _num(v: Any) -> str:
    if v is None:
        return "-"
    if isinstance(v, float) and abs(v) >= 100:
        return f"{v:.0f}"
    return f"{v:g}" if isinstance(v, float) else str(v)
