"""`ttctl bench transfer` on a profile with a pipeline (mop): files over the MOP pipeline beside
the low-speed channel, in virtual time, with and without drops.

Rows {"direction","drops","seconds","goodput_Bps","pipe_Bps","of_pipe","pipe_share","lost_in_flight",
"retransmitted","ok"}: `of_pipe` = goodput / the pipeline's modelled rate; `pipe_share` = the
file's bytes that went on the pipeline; `lost_in_flight` = the data bytes the drops caught on the
pipeline (frames given to it and never delivered); `retransmitted` = file bytes sent again. The
checks: with the pipeline up all the time, goodput at least PIPE_FLOOR of its rate; with drops,
the file whole and nothing resent beyond what the drops caught (plus a frame per drop for the
one cut in half).
"""

from __future__ import annotations

import os
import random
import statistics
import tempfile
from dataclasses import asdict, dataclass
from typing import Any

from ..link.model import Profile
from ..link.sim import PipeModel, Simulation
from ..proto.endpoint import Endpoint
from ..proto.storage import BytesSource, ReceiveDir
from ..proto.transfer import WIDE, TransferConfig
from . import shipped

TABLET = (255, 190)
ONBOARD = (1, 240)
PIPE_FLOOR = 0.8  # of the pipeline's modelled rate, with it up all the time
FRAME = WIDE + 12  # a wide data frame on the pipeline: the most one drop can cut in half


@dataclass
class PipeRow:
    direction: str
    drops: int
    seconds: float
    goodput_Bps: float
    pipe_Bps: float
    of_pipe: float
    pipe_share: float
    lost_in_flight: int
    retransmitted: int
    ok: bool
    seeds: int


def _drops(n: int, file_bytes: int, rate: float) -> list[tuple[float, float]]:
    """`n` drops spread over the time the file takes on the pipeline: 1 s, 2 s, 1 s, ..."""
    span = file_bytes / rate
    return [(span * (k + 1) / (n + 1) + 0.5 * k, 1.0 + (k % 2)) for k in range(n)]


def run_one(profile: Profile, distance: float, direction: str, drops: int, data: bytes,
            seed: int) -> tuple[float, bool, int, int, int]:
    """Seconds until the file is in place, whether it is, data bytes lost in flight, file bytes
    resent, file bytes that went on the pipeline."""
    from .transfer import Case, channels, pace

    assert profile.pipe is not None
    up, down = channels(profile, distance, Case(direction, 0.0, "random"), seed)
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-") as d:
        done: dict[str, float] = {}

        def on_event(what: str, obj: Any) -> None:
            if what == "file-complete":
                done["t"] = obj.finished_at

        store = ReceiveDir(d)
        b = shipped.bindings()
        cfg = TransferConfig()
        tablet = Endpoint(b, *TABLET, mtu=profile.mtu, rate_Bps=pace(up), config=cfg, rng=random.Random(seed),
                          receive_dir=store if direction == "down" else None, on_event=on_event)
        onboard = Endpoint(b, *ONBOARD, mtu=profile.mtu, rate_Bps=pace(down), config=cfg,
                           rng=random.Random(seed + 1), receive_dir=store if direction == "up" else None,
                           on_event=on_event)
        sender, target = (tablet, ONBOARD) if direction == "up" else (onboard, TABLET)
        s = sender.send_file("bench.bin", target, source=BytesSource(data, "bench.bin"), compress=False)
        pipe = PipeModel(profile.pipe.rate_Bps, profile.pipe.latency_s,
                         drops=_drops(drops, len(data), profile.pipe.rate_Bps))
        sim = Simulation(tablet, onboard, up, down, pipe=pipe)
        sim.run(3600, stop=lambda: "t" in done or s.done)
        ok = "t" in done
        if ok:
            with open(os.path.join(d, "bench.bin"), "rb") as fh:
                ok = fh.read() == data
        way = 0 if direction == "up" else 1
        frames = sender.scheduler.pipe_frames
        on_pipe = round(pipe.bytes[way] * WIDE / FRAME) if frames else 0
        lost = round(pipe.lost_in_flight[way] * WIDE / FRAME)
        tablet.close()
        onboard.close()
        return done.get("t", 3600.0), ok, lost, s.stats.bytes_retransmitted, min(on_pipe, len(data))


def rows(profile: Profile, distance: float, file_bytes: int, seeds: list[int]) -> list[PipeRow]:
    if profile.pipe is None:
        return []
    rate = profile.pipe.rate_Bps
    out = []
    for direction in ("up", "down"):
        for drops in (0, 2):
            runs = [run_one(profile, distance, direction, drops, random.Random(seed).randbytes(file_bytes), seed)
                    for seed in seeds]
            secs = statistics.median(r[0] for r in runs)
            goodput = file_bytes / secs
            out.append(PipeRow(direction, drops, round(secs, 2), round(goodput, 1), rate, round(goodput / rate, 4),
                               round(statistics.median(r[4] for r in runs) / file_bytes, 4),
                               int(statistics.median(r[2] for r in runs)), int(max(r[3] for r in runs)),
                               all(r[1] for r in runs), len(runs)))
    return out


def checks(pipe_rows: list[PipeRow]) -> list[dict[str, Any]]:
    out: list[dict[str, Any]] = []
    for r in pipe_rows:
        if r.drops == 0:
            out.append({"check": f"pipeline {r.direction}: goodput of its rate", "value": r.of_pipe,
                        "floor": PIPE_FLOOR, "ok": r.ok and r.of_pipe >= PIPE_FLOOR})
        else:
            bound = r.lost_in_flight + r.drops * FRAME
            out.append({"check": f"pipeline {r.direction}, {r.drops} drops: bytes resent", "value": r.retransmitted,
                        "ceiling": bound, "ok": r.ok and r.retransmitted <= bound})
    return out


def as_dicts(pipe_rows: list[PipeRow]) -> list[dict[str, Any]]:
    return [asdict(r) for r in pipe_rows]


def print_table(pipe_rows: list[dict[str, Any]]) -> None:
    from rich.console import Console
    from rich.table import Table

    t = Table(title="files over the MOP pipeline (file data on it, control on the low-speed channel); drops lose "
                    "what is in flight")
    for col in ("dir", "drops", "seconds", "goodput", "pipeline B/s", "of it", "on the pipeline",
                "lost in flight", "resent"):
        t.add_column(col, justify="left" if col == "dir" else "right")
    for r in pipe_rows:
        t.add_row(r["direction"], str(r["drops"]), f"{r['seconds']:.1f}", f"{r['goodput_Bps']:.0f}",
                  f"{r['pipe_Bps']:.0f}", f"{r['of_pipe']:.1%}", f"{r['pipe_share']:.1%}",
                  str(r["lost_in_flight"]), str(r["retransmitted"]) + ("" if r["ok"] else "*"))
    Console().print(t)
