"""`ttctl bench transfer`'s compressed-text rows: what users send (a mission YAML of a few KB, a
CSV flight log of a few hundred KB: bench/textfiles.py) and random bytes, each sent by ttctl with
deflate and as it is (--no-compress), on the same seeds, in virtual time. Rows give file goodput
over link capacity: above 1 when the file deflates.

Floors: at least 3x on the CSV log and 2x on the YAML at 10 % loss; random bytes within 1 % of
sending them as they are (they do not deflate, so they go as they are: the decision costs CPU, not
link time).
"""

from __future__ import annotations

import os
import random
import statistics
import tempfile
from dataclasses import asdict, dataclass
from typing import Any

from ..link.model import Profile
from ..link.sim import Simulation
from ..proto.endpoint import Endpoint
from ..proto.storage import BytesSource, ReceiveDir
from ..proto.transfer import TransferConfig
from . import shipped
from .textfiles import flight_log_csv, mission_yaml

FLOORS = {"mission.yaml": 2.0, "flight.csv": 3.0}
RANDOM_WITHIN = 0.99


@dataclass
class TextRow:
    file: str
    direction: str
    loss: float
    loss_model: str
    file_bytes: int
    link_bytes: int  # the zlib stream's size, or the file's when it went as it is
    seconds: float  # deflated (median over the seeds)
    seconds_raw: float  # the same file with --no-compress
    goodput_over_capacity: float
    raw_over_capacity: float
    ok: bool


def files() -> dict[str, bytes]:
    return {"mission.yaml": mission_yaml(), "flight.csv": flight_log_csv(),
            "random.bin": random.Random(5).randbytes(64 * 1024)}


def one(profile: Profile, distance: float, direction: str, loss: float, model: str, name: str, data: bytes,
        seed: int, compress: bool, limit: float = 7200.0) -> tuple[float, bool, int]:
    """Seconds until the file is in place, whether it is (intact), bytes on the link per pass."""
    from .transfer import ONBOARD, TABLET, Case, channels, pace

    up, down = channels(profile, distance, Case(direction, loss, model), seed)
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
                           rng=random.Random(seed + 1),
                           receive_dir=store if direction == "up" else None, on_event=on_event)
        sender, target = (tablet, ONBOARD) if direction == "up" else (onboard, TABLET)
        s = sender.send_file(name, target, source=BytesSource(data, name), compress=compress)
        Simulation(tablet, onboard, up, down).run(limit, stop=lambda: "t" in done or s.done)
        ok = "t" in done
        if ok:
            with open(os.path.join(d, name), "rb") as fh:
                ok = fh.read() == data
        size = s.size
        tablet.close()
        onboard.close()
        return done.get("t", limit), ok, size


def rows(profile: Profile, distance: float, seeds: list[int], loss: float = 0.1,
         model: str = "random") -> list[TextRow]:
    out = []
    for name, data in files().items():
        for direction in ("up", "down"):
            cap = profile.capacity_Bps(direction, distance)
            z = [one(profile, distance, direction, loss, model, name, data, s, True) for s in seeds]
            r = [one(profile, distance, direction, loss, model, name, data, s, False) for s in seeds]
            tz = statistics.median(t for t, _, _ in z)
            tr = statistics.median(t for t, _, _ in r)
            out.append(TextRow(name, direction, loss, model, len(data), z[0][2], round(tz, 2), round(tr, 2),
                               round(len(data) / tz / cap, 3), round(len(data) / tr / cap, 3),
                               all(ok for _, ok, _ in z + r)))
    return out


def checks(text: list[TextRow]) -> list[dict[str, Any]]:
    out: list[dict[str, Any]] = []
    for r in text:
        where = f"{r.direction} {r.loss:.0%} {r.loss_model}"
        if r.file in FLOORS:
            out.append({"check": f"deflate {r.file} {where} (goodput / capacity)", "value": r.goodput_over_capacity,
                        "floor": FLOORS[r.file], "ok": r.ok and r.goodput_over_capacity >= FLOORS[r.file]})
        else:
            ratio = round(r.goodput_over_capacity / max(r.raw_over_capacity, 1e-9), 4)
            out.append({"check": f"random bytes {where}: with deflate / without", "value": ratio,
                        "floor": RANDOM_WITHIN, "ok": r.ok and ratio >= RANDOM_WITHIN})
    return out


def as_dicts(text: list[TextRow]) -> list[dict[str, Any]]:
    return [asdict(r) for r in text]


def print_table(text: list[dict[str, Any]]) -> None:
    from rich.console import Console
    from rich.table import Table

    t = Table(title="compressed text: file goodput over link capacity, deflated and as it is (--no-compress)")
    for col in ("file", "dir", "loss", "file B", "on the link B", "seconds", "x capacity", "raw seconds",
                "raw x capacity"):
        t.add_column(col, justify="left" if col in ("file", "dir") else "right")
    for r in text:
        t.add_row(r["file"], r["direction"], f"{r['loss']:.0%} {r['loss_model']}", str(r["file_bytes"]),
                  str(r["link_bytes"]), f"{r['seconds']:.1f}", f"{r['goodput_over_capacity']:.2f}" +
                  ("" if r["ok"] else "*"), f"{r['seconds_raw']:.1f}", f"{r['raw_over_capacity']:.2f}")
    Console().print(t)
