"""`ttctl bench latency`: command round trips (TT_ACTION_COMMAND -> TT_COMMAND_ACK), idle, during
an upload and during a download; on the link model in virtual time, or live against a real
onboard end.

Commands are issued every `interval` seconds, each at a random moment in the first half of its
slot (so they do not lock onto the packet clock). In the transfer phases the file (64 KiB of
random bytes by default) is sent again under a new name whenever it completes before the last
command, so every command meets a busy link; the phase ends when every command has ended, and
the transfer still running is cancelled. Latency runs from the moment the command is issued to
its ack, retries included; `retries` counts the extra sends.
"""

from __future__ import annotations

import asyncio
import json
import random
import sys
import tempfile
import uuid
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from typing import Any

from ..link.model import Profile
from ..link.sim import PipeModel, Simulation
from ..proto.endpoint import Endpoint
from ..proto.storage import BytesSource, ReceiveDir
from ..wire.contract import TtAction
from . import shipped

TABLET = (255, 190)
ONBOARD = (1, 240)
PHASES = ("idle", "upload", "download")
HOVER = int(TtAction.TT_ACTION_HOVER)
SYNC_TIME = int(TtAction.TT_ACTION_SYNC_TIME)  # changes nothing on the vehicle: what live mode sends
BENCH_FOLDER = "ttctl-bench"
RETRIES, TIMEOUT = 5, 3.0  # per command: 3 + 6 + 12 + ... s of waiting before it gives up


@dataclass
class Phase:
    phase: str
    count: int  # commands acknowledged
    failed: int  # commands that got no ack
    retries: int  # extra sends, over all commands
    p50_ms: float | None
    p95_ms: float | None
    max_ms: float | None
    transfers: int = 0  # files started during the phase
    transfer_bytes: int = 0  # bytes the receiver acknowledged during the phase
    note: str | None = None
    latencies_ms: list[float] = field(default_factory=list, repr=False)


def percentile(xs: list[float], q: float) -> float:
    xs = sorted(xs)
    if not xs:
        return float("nan")
    k = (len(xs) - 1) * q
    lo = int(k)
    hi = min(lo + 1, len(xs) - 1)
    return xs[lo] + (xs[hi] - xs[lo]) * (k - lo)


def summarise(phase: str, cmds: list[Any], transfers: int = 0, transfer_bytes: int = 0,
              note: str | None = None) -> Phase:
    lat = [c.latency for c in cmds if c.latency is not None]
    ms = [round(1000 * x, 1) for x in lat]

    def q(p: float) -> float | None:
        return round(1000 * percentile(lat, p), 1) if lat else None

    return Phase(phase, len(lat), sum(1 for c in cmds if c.latency is None),
                 sum(max(0, len(c.sent_at) - 1) for c in cmds), q(0.5), q(0.95),
                 round(1000 * max(lat), 1) if lat else None, transfers, transfer_bytes, note, ms)


def _data(n: int, seed: int) -> bytes:
    return random.Random(seed).randbytes(n)


# -- the link model, in virtual time -------------------------------------------------------------

def model_commands(profile: Profile, distance: float, phase: str, count: int, seed: int, interval: float,
                   file_bytes: int, restart: bool = True, action: int = HOVER) -> tuple[list[Any], int, int]:
    """`count` commands from the tablet to the onboard end over the profile's channels (no
    extra loss), idle or while a file of `file_bytes` goes up ("upload") or down ("download");
    with `restart`, the file starts again whenever it completes before the last command.
    Returns the commands, the files started and the bytes acknowledged."""
    from .transfer import Case, channels, pace

    rng = random.Random(seed)
    up, down = channels(profile, distance, Case("up", 0.0, "random"), seed)
    b = shipped.bindings()
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-") as d:
        tablet = Endpoint(b, *TABLET, mtu=profile.mtu, rate_Bps=pace(up), rng=random.Random(seed),
                          receive_dir=ReceiveDir(d) if phase == "download" else None)
        onboard = Endpoint(b, *ONBOARD, mtu=profile.mtu, rate_Bps=pace(down), rng=random.Random(seed + 1),
                           receive_dir=ReceiveDir(d) if phase != "download" else None)
        # with the profile's pipeline (mop) open throughout: file data on it, commands on the packets
        pipe = PipeModel(profile.pipe.rate_Bps, profile.pipe.latency_s) if profile.pipe is not None else None
        sim = Simulation(tablet, onboard, up, down, pipe=pipe)
        senders: list[Any] = []

        def start_file() -> None:
            sender, target = (tablet, ONBOARD) if phase == "upload" else (onboard, TABLET)
            sender.now = sim.now
            name = f"bulk{len(senders)}.bin" if senders else "bulk.bin"
            senders.append(sender.send_file(name, target, source=BytesSource(_data(file_bytes, seed), name)))

        if phase != "idle":
            start_file()
        t = 1.0
        pending: list[Any] = []
        for _ in range(count):
            t += interval
            issue = t + rng.uniform(0, interval / 2)
            sim.run(issue)
            if restart and senders and senders[-1].done:
                start_file()
            tablet.now = sim.now
            pending.append(tablet.command(b.TtActionCommand(action=action), ONBOARD, retries=RETRIES,
                                          timeout=TIMEOUT))
        sim.run(t + 30 + 60 * RETRIES, stop=lambda: all(c.done for c in pending))
        moved = sum(s.acked_bytes for s in senders)
        tablet.close()
        onboard.close()
    return pending, len(senders), moved


def run_model(profile: Profile, distance: float, count: int, seed: int, interval: float,
              file_bytes: int) -> list[Phase]:
    out = []
    for phase in PHASES:
        cmds, files, moved = model_commands(profile, distance, phase, count, seed, interval, file_bytes)
        out.append(summarise(phase, cmds, files, moved))
    return out


def packet_time(profile: Profile, distance: float) -> float:
    """Seconds a full packet holds the uplink: what a command may wait behind file data."""
    return profile.up.service_time(profile.mtu, distance)


MODEL_MARGIN = 0.05  # s over a packet time: the scheduler's promise, in virtual time
LIVE_MARGIN = 0.2  # s over a packet time: the same, with two processes, a relay and the OS's timers


def bound_s(profile: Profile, distance: float, live: bool = False) -> float:
    """The one rule for a command's p95 while a file moves (`bench latency` and `bench transfer`
    both judge by it): at most idle p95 + one full packet's time on the uplink + a margin."""
    return packet_time(profile, distance) + (LIVE_MARGIN if live else MODEL_MARGIN)


def report(phases: list[Phase], meta: dict[str, Any], bound_s: float) -> dict[str, Any]:
    """The report: phases, during/idle ratios, and the check the scheduler promises (a command
    waits at most for the packet on the air: during p95 <= idle p95 + `bound_s`)."""
    idle = phases[0]
    rows = []
    checks = []
    for p in phases:
        row = asdict(p)
        row.pop("latencies_ms")
        ratio = None
        if p.phase != "idle" and p.p95_ms is not None and idle.p95_ms:
            ratio = round(p.p95_ms / idle.p95_ms, 2)
        row["p95_ratio_to_idle"] = ratio
        row["p50_ratio_to_idle"] = (round(p.p50_ms / idle.p50_ms, 2)
                                    if p.phase != "idle" and p.p50_ms is not None and idle.p50_ms else None)
        rows.append(row)
        if p.phase != "idle" and p.p95_ms is not None and idle.p95_ms is not None:
            ceiling = round(idle.p95_ms + 1000 * bound_s, 1)
            checks.append({"check": f"command p95 during {p.phase}", "value": p.p95_ms, "ceiling": ceiling,
                           "ok": p.p95_ms <= ceiling and p.failed == 0})
    return {**meta, "phases": rows, "checks": checks}


# -- live, against a real onboard end -------------------------------------------------------------

@dataclass
class LiveOptions:
    to: str
    count: int
    interval: float
    file_bytes: int
    pace_Bps: float | None
    quiet: float | None
    fetch: str | None
    timeout: float
    seed: int | None = None
    bindings: Any = None  # the link's dialect (None: ttctl's shipped ttapi)
    mtu: int = 100  # the link's packet size (the profile's)


class Unreachable(Exception):
    pass


def run_live(o: LiveOptions, progress: Callable[[str], None]) -> tuple[list[Phase], dict[str, Any]]:
    return asyncio.run(_live(o, progress))


async def _live(o: LiveOptions, progress: Callable[[str], None]) -> tuple[list[Phase], dict[str, Any]]:
    from ..ends.runtime import Runner, hello
    from ..link.transport import make_transport, parse_spec

    spec = parse_spec(o.to, udp="udpout")
    b = o.bindings or shipped.bindings()
    rng = random.Random(o.seed)
    loop = asyncio.get_running_loop()
    wake = asyncio.Event()
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-") as d:
        store = ReceiveDir(d)
        transport = make_transport(spec, log=lambda text: None, mtu=o.mtu if spec.udp else None)
        ep = Endpoint(b, *TABLET, mtu=transport.mtu, rate_Bps=o.pace_Bps, receive_dir=store, unsolicited=False,
                      on_event=lambda what, obj: wake.set())
        runner = Runner(ep, transport, quiet=o.quiet, hello=hello(TABLET[0], spec, b))
        await runner.start()
        store.prepare()
        try:
            # the peer first: one command, acknowledged within the timeout, or nobody is there
            runner.sync()
            probe = ep.command(b.TtActionCommand(action=SYNC_TIME), ONBOARD, retries=100, timeout=0.5)
            runner.kick()
            end = loop.time() + o.timeout
            while not probe.done and loop.time() < end:
                await asyncio.sleep(0.02)
            if probe.latency is None:
                raise Unreachable(f"no answer from {ONBOARD[0]}/{ONBOARD[1]} at {spec} within {o.timeout:g} s "
                                  "(is `ttctl emulate onboard` or `ttctl recv-file` running there?)")
            tag = uuid.uuid4().hex[:12]
            phases = []
            for phase in PHASES:
                phases.append(await _live_phase(o, phase, ep, runner, rng, tag, progress))
            meta = {"endpoint": transport.describe(), "upload_name": f"{BENCH_FOLDER}/latency-{tag}-*.bin"}
            return phases, meta
        finally:
            for s in list(ep.senders.values()):
                if not s.done:
                    s.cancel(runner.now())
            ep.close()
            await runner.close()
            store.release(failed=True)


async def _live_phase(o: LiveOptions, phase: str, ep: Endpoint, runner: Any, rng: random.Random, tag: str,
                      progress: Callable[[str], None]) -> Phase:
    loop = asyncio.get_running_loop()
    senders: list[Any] = []
    requests: list[Any] = []
    note = None
    if phase == "download" and o.fetch is None:
        progress("download: skipped (give --fetch NAME, a file the peer serves)")
        return Phase(phase, 0, 0, 0, None, None, None, note="skipped: no --fetch NAME (a file the peer serves)")

    def start_file() -> None:
        runner.sync()
        if phase == "upload":
            name = f"{BENCH_FOLDER}/latency-{tag}-{len(senders)}.bin"
            data = random.Random(rng.random()).randbytes(o.file_bytes)
            senders.append(ep.send_file(name, ONBOARD, source=BytesSource(data, name)))
        else:
            assert o.fetch is not None and ep.receiver is not None
            local = ep.receiver.store.final_path(o.fetch)
            if local.exists():
                local.unlink()  # fetched already: again, for as long as the phase lasts
            requests.append(ep.request_file(o.fetch, ONBOARD))
        runner.kick()

    def busy_done() -> bool:
        if phase == "upload":
            return senders[-1].done
        r = requests[-1]
        return r.answered and r.key is not None and not any(
            t.key == r.key and t.finished_at is None for t in _incoming(ep))

    if phase != "idle":
        start_file()
        await asyncio.sleep(min(2.0, 4 * o.interval))  # let the transfer get going
    cmds: list[Any] = []
    t = loop.time()
    for i in range(o.count):
        t += o.interval
        issue = t + rng.uniform(0, o.interval / 2)
        await asyncio.sleep(max(0.0, issue - loop.time()))
        if requests and requests[-1].code is not None:
            note = f"the fetch of {o.fetch} failed: {requests[-1].error}"
            break
        if phase != "idle" and busy_done():
            start_file()
        runner.sync()
        cmds.append(ep.command(ep.b.TtActionCommand(action=SYNC_TIME), ONBOARD, retries=RETRIES, timeout=TIMEOUT))
        runner.kick()
        progress(f"{phase}: command {i + 1}/{o.count}")
    end = loop.time() + 60
    while not all(c.done for c in cmds) and loop.time() < end:
        await asyncio.sleep(0.02)
    if runner.failed is not None:
        raise runner.failed
    moved = sum(s.acked_bytes for s in senders) + sum(
        t.partial.ranges.total() if t.partial is not None else t.size
        for t in _incoming(ep) if any(r.key == t.key for r in requests))
    if phase == "upload" and moved == 0:
        note = "the peer took no data: does it take files (emulate onboard needs --inbox DIR)?"
    for s in senders:
        if not s.done:
            s.cancel(runner.now())
    return summarise(phase, cmds, len(senders) + len(requests), moved, note)


def _incoming(ep: Endpoint) -> list[Any]:
    rx = ep.receiver
    if rx is None:
        return []
    return list(getattr(rx, "transfers", {}).values())


# -- output ----------------------------------------------------------------------------------------

def print_report(rep: dict[str, Any], out: Any = None) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console(file=out or sys.stdout)
    where = (f"live through {rep['endpoint']}" if rep["mode"] == "live"
             else f"{rep['profile']} at {rep['distance_m']:g} m, virtual time, seed {rep['seed']}")
    t = Table(title=f"command latency (TT_ACTION_COMMAND -> TT_COMMAND_ACK), {where}; "
                    f"{rep['count']} commands a phase, one every {rep['interval_s']:g} s, "
                    f"{rep['file_bytes'] // 1024} KiB files")
    for col in ("phase", "acked", "failed", "retries", "p50 ms", "p95 ms", "max ms", "p95 / idle"):
        t.add_column(col, justify="left" if col == "phase" else "right")

    def f(x: float | None) -> str:
        return "-" if x is None else f"{x:.0f}"

    for r in rep["phases"]:
        ratio = r["p95_ratio_to_idle"]
        t.add_row(r["phase"], str(r["count"]), str(r["failed"]), str(r["retries"]), f(r["p50_ms"]), f(r["p95_ms"]),
                  f(r["max_ms"]), "" if ratio is None else f"{ratio:.2f}")
    console.print(t)
    for r in rep["phases"]:
        if r.get("note"):
            console.print(f"{r['phase']}: {r['note']}")
    for c in rep["checks"]:
        mark = "[green]ok[/]" if c["ok"] else "[red]over[/]"
        console.print(f"{c['check']}: {c['value']:.0f} ms, ceiling {c['ceiling']:.0f} ms "
                      f"(idle p95 + {rep['bound_ms']:.0f} ms) {mark}")
    if rep.get("upload_name"):
        console.print(f"uploads went to {rep['upload_name']} at the receiver (cancelled ones leave a partial in "
                      "its .ttctl-partial folder)", markup=False)


def dumps(rep: dict[str, Any]) -> str:
    return json.dumps(rep, indent=2)
