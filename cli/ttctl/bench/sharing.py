"""`ttctl bench transfer`'s sharing rows: several senders, each its own process, uploading equal
files at once to one receiver over the link model, in virtual time.

Each sender is an endpoint of its own (its own scheduler and pacer at the uplink's rate) and
none gets the radio's per-packet completion callback, as processes behind `ttctl link relay`
do not: what they offer together beyond the uplink's rate overflows its buffer. The receiver
knows its inbound capacity and grants each transfer a share (proto/sharing.py). A sixth process,
the app, sends a command every `interval` seconds, idle before the files and during them (a
run of its own: the efficiencies come from runs without commands). In the same run one sender
alone moves the same file, for the ratio, and the senders go again to a receiver that grants
nothing, as before grants.

Rows (SharingRow, medians over the seeds): each sender's time runs from its start to its
verified file; aggregate efficiency is all file bytes / the last one's time / capacity; the
retransmitted share is bytes sent again / file bytes; overflow counts packets the uplink's
buffer dropped; "ungranted" is the same run to a receiver that grants nothing (as before grants).
"""

from __future__ import annotations

import dataclasses
import random
import statistics
import tempfile
from dataclasses import asdict, dataclass
from typing import Any

from ..link.model import Channel, Impairments, Profile
from ..link.sim import Simulation
from ..proto.endpoint import Endpoint
from ..proto.storage import BytesSource, ReceiveDir
from . import shipped
from .latency import RETRIES, SYNC_TIME, TIMEOUT, bound_s, percentile

TABLET = (255, 190)
ONBOARD = (1, 240)
# the bounds for equal files: every one verified, the slowest within 1.5x the fastest,
# under 0.3 of the file bytes sent again, the aggregate at least 0.9 of one sender's efficiency
SLOWEST_OVER_FASTEST = 1.5
RETRANSMITTED_SHARE = 0.3
RATIO_TO_SINGLE = 0.9


class Processes:
    """Several endpoints behind one radio, as processes behind a relay: each hears everything
    that comes back (each takes what is its own), and what they send goes on the air in the
    order they offer it (round-robin among those with a packet ready)."""

    def __init__(self, ends: list[Endpoint]) -> None:
        self.ends = ends
        self._rr = 0

    def receive(self, now: float, packet: bytes) -> None:
        for e in self.ends:
            e.receive(now, packet)

    def poll(self, now: float) -> bytes | None:
        n = len(self.ends)
        for k in range(n):
            i = (self._rr + k) % n
            pkt = self.ends[i].poll(now)
            if pkt is not None:
                self._rr = (i + 1) % n
                return pkt
        return None

    def wakeup(self) -> float | None:
        times = [t for e in self.ends if (t := e.wakeup()) is not None]
        return min(times) if times else None


def _no_feedback(profile: Profile) -> Profile:
    """The profile with its uplink's completion callback taken away (processes behind a relay)."""
    return dataclasses.replace(profile, up=dataclasses.replace(profile.up, feedback=False))


def run_senders(profile: Profile, distance: float, n: int, loss: float | None, loss_model: str, file_bytes: int,
                seed: int, commands: bool = False, interval: float = 1.0, grants: bool = True,
                limit: float = 3600.0) -> dict[str, Any]:
    """n senders at once (and, with `commands`, the app's commands idle before and during;
    without `grants`, a receiver that gives none, as before them). Returns each sender's seconds
    and result, retransmitted bytes, overflow and command latencies."""
    prof = _no_feedback(profile)
    imp = Impairments(loss=loss, loss_model=loss_model)
    up = Channel(prof, "up", distance, imp, seed=seed * 2 + 1)
    down = Channel(prof, "down", distance, Impairments(loss=loss, loss_model=loss_model), seed=seed * 2 + 2)
    b = shipped.bindings()
    rate = up.capacity_Bps()
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-") as d:
        store = ReceiveDir(d)
        onboard = Endpoint(b, *ONBOARD, mtu=prof.mtu, rate_Bps=down.capacity_Bps(), rng=random.Random(seed + 1),
                           receive_dir=store,
                           inbound_Bps=rate if grants else None)
        ends = [Endpoint(b, *TABLET, mtu=prof.mtu, rate_Bps=rate, rng=random.Random(seed * 100 + i)) for i in range(n)]
        app = Endpoint(b, *TABLET, mtu=prof.mtu, rate_Bps=rate, rng=random.Random(seed * 100 + n),
                       accept_commands=False)
        sim = Simulation(Processes([*ends, app]), onboard, up, down)
        rng = random.Random(seed)
        idle: list[Any] = []
        t = 0.0
        if commands:
            for _ in range(10):  # idle: the link to itself
                t += interval
                sim.run(t + rng.uniform(0, interval / 2))
                app.now = sim.now
                idle.append(app.command(b.TtActionCommand(action=SYNC_TIME), ONBOARD, retries=RETRIES,
                                        timeout=TIMEOUT))
            sim.run(t + interval, stop=lambda: all(c.done for c in idle))
        start = sim.now
        datas = [random.Random(seed * 1000 + i).randbytes(file_bytes) for i in range(n)]
        senders = []
        for i, e in enumerate(ends):
            e.now = sim.now
            name = f"share{i}.bin"
            senders.append(e.send_file(name, ONBOARD, source=BytesSource(datas[i], name)))
        during: list[Any] = []
        t = sim.now
        while not all(s.done for s in senders) and sim.now < start + limit:
            t += interval
            sim.run(t + (rng.uniform(0, interval / 2) if commands else 0.0), stop=lambda: all(s.done for s in senders))
            if commands and not all(s.done for s in senders):
                app.now = sim.now
                during.append(app.command(b.TtActionCommand(action=SYNC_TIME), ONBOARD, retries=RETRIES,
                                          timeout=TIMEOUT))
        sim.run(sim.now + 60 * RETRIES, stop=lambda: all(c.done for c in during))
        verified = []
        for i in range(n):
            try:
                verified.append((store.final_path(f"share{i}.bin")).read_bytes() == datas[i])
            except OSError:
                verified.append(False)
        out = {
            "seconds": [round((s.stats.finished or sim.now) - start, 3) for s in senders],
            "ok": [bool(s.result and s.result.ok) and v for s, v in zip(senders, verified, strict=True)],
            "retransmitted": sum(s.stats.bytes_retransmitted for s in senders),
            "overflow": up.stats.overflow,
            "capacity": rate,
            "idle": [c.latency for c in idle],
            "during": [c.latency for c in during],
        }
        for e in [*ends, app, onboard]:
            e.close()
    return out


CASES = ((None, "random"), (0.1, "random"), (0.1, "burst"))  # loss None: the profile's own


@dataclass
class SharingRow:
    senders: int
    loss: float | None  # None: the profile's own at that distance
    loss_model: str
    file_bytes: int
    seeds: int
    slowest_over_fastest: float  # medians over the seeds
    aggregate_efficiency: float
    single_efficiency: float
    ratio_to_single: float
    retransmitted_share: float
    overflow: int
    ungranted_efficiency: float  # the same senders to a receiver that grants nothing
    ungranted_retransmitted_share: float
    idle_p95_ms: float | None
    during_p95_ms: float | None
    latency_ceiling_ms: float | None
    ok: bool  # every file verified in every run


def rows(profile: Profile, distance: float, seeds: list[int], n: int = 5, file_bytes: int = 4096) -> list[SharingRow]:
    out = []
    for loss, model in CASES:
        many = [run_senders(profile, distance, n, loss, model, file_bytes, s) for s in seeds]
        busy = [run_senders(profile, distance, n, loss, model, file_bytes, s, commands=True) for s in seeds]
        free = [run_senders(profile, distance, n, loss, model, file_bytes, s, grants=False) for s in seeds]
        one = [run_senders(profile, distance, 1, loss, model, file_bytes, s) for s in seeds]
        cap = many[0]["capacity"]
        agg = statistics.median(n * file_bytes / max(r["seconds"]) / cap for r in many)
        single = statistics.median(file_bytes / r["seconds"][0] / cap for r in one)
        idle = [x for r in busy for x in r["idle"] if x is not None]
        during = [x for r in busy for x in r["during"] if x is not None]
        idle95 = round(1000 * percentile(idle, 0.95), 1) if idle else None
        out.append(SharingRow(
            n, loss, model, file_bytes, len(seeds),
            round(statistics.median(max(r["seconds"]) / min(r["seconds"]) for r in many), 3), round(agg, 4),
            round(single, 4), round(agg / single, 3),
            round(statistics.median(r["retransmitted"] / (n * file_bytes) for r in many), 3),
            int(statistics.median(r["overflow"] for r in many)),
            round(statistics.median(n * file_bytes / max(r["seconds"]) / cap for r in free), 4),
            round(statistics.median(r["retransmitted"] / (n * file_bytes) for r in free), 3),
            idle95, round(1000 * percentile(during, 0.95), 1) if during else None,
            round(idle95 + 1000 * bound_s(profile, distance), 1) if idle95 is not None else None,
            all(all(r["ok"]) for r in many + busy + free + one)))
    return out


def checks(rows: list[SharingRow]) -> list[dict[str, Any]]:
    """The issue's bounds for equal files at once: the shares, the retransmitted bytes, the
    aggregate against one sender alone; command latency where the loss is the link's own (at 10 %
    a retry's timer, not the sharing, sets the p95)."""
    out: list[dict[str, Any]] = []
    for r in rows:
        case = f"{r.senders} senders {'link loss' if r.loss is None else f'{r.loss:.0%}'} {r.loss_model}"
        out.append({"check": f"{case}: slowest / fastest", "value": r.slowest_over_fastest,
                    "ceiling": SLOWEST_OVER_FASTEST, "ok": r.ok and r.slowest_over_fastest <= SLOWEST_OVER_FASTEST})
        out.append({"check": f"{case}: retransmitted / file bytes", "value": r.retransmitted_share,
                    "ceiling": RETRANSMITTED_SHARE, "ok": r.retransmitted_share < RETRANSMITTED_SHARE})
        out.append({"check": f"{case}: aggregate / one sender's efficiency", "value": r.ratio_to_single,
                    "floor": RATIO_TO_SINGLE, "ok": r.ratio_to_single >= RATIO_TO_SINGLE})
        if r.loss is None and r.during_p95_ms is not None and r.latency_ceiling_ms is not None:
            out.append({"check": f"{case}: command p95 (another process)", "value": r.during_p95_ms,
                        "ceiling": r.latency_ceiling_ms, "ok": r.during_p95_ms <= r.latency_ceiling_ms})
    return out


def as_dicts(rs: list[SharingRow]) -> list[dict[str, Any]]:
    return [asdict(r) for r in rs]


def print_table(rs: list[dict[str, Any]]) -> None:
    from rich.console import Console
    from rich.table import Table

    if not rs:
        return
    first = rs[0]
    t = Table(title=f"{first['senders']} senders in {first['senders']} processes, {first['file_bytes']} B each, at "
                    f"once to one receiver that grants each a share; median of {first['seeds']} seeds",
              caption="alone: one sender by itself; ratio: aggregate / alone; resent: bytes sent again / file "
                      "bytes; ovf: packets the uplink buffer dropped; no grants: the same senders to a receiver "
                      "that grants nothing; cmd p95: a command from a sixth process, idle / during")
    for col in ("loss", "max/min", "aggregate", "alone", "ratio", "resent", "ovf", "no grants", "resent",
                "cmd p95 ms"):
        t.add_column(col, justify="left" if col == "loss" else "right")
    for r in rs:
        loss = "link's" if r["loss"] is None else f"{r['loss']:.0%} {r['loss_model']}"
        t.add_row(loss, f"{r['slowest_over_fastest']:.2f}",
                  f"{r['aggregate_efficiency']:.3f}" + ("" if r["ok"] else "*"),
                  f"{r['single_efficiency']:.3f}", f"{r['ratio_to_single']:.2f}", f"{r['retransmitted_share']:.2f}",
                  str(r["overflow"]), f"{r['ungranted_efficiency']:.3f}", f"{r['ungranted_retransmitted_share']:.2f}",
                  f"{_ms(r['idle_p95_ms'])}/{_ms(r['during_p95_ms'])}")
    Console().print(t)


def _ms(x: float | None) -> str:
    return "" if x is None else f"{x:.0f}"


__all__ = ["CASES", "Processes", "SharingRow", "as_dicts", "checks", "print_table", "rows", "run_senders"]
