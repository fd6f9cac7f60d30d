"""`ttctl bench transfer`: file transfer over the link model in virtual time.

Rows: {"protocol","direction","loss","loss_model","file_bytes","seconds","goodput_Bps",
"capacity_Bps","efficiency"} where capacity is what the model delivers with back-to-back full
packets and no protocol, and efficiency = goodput / capacity. seconds runs from the moment the
sender starts until the verified file is in place at the receiver. Each case runs with several
fixed seeds; the row reports the median. Latency rows {"case","p50_ms","p95_ms"} time
TT_ACTION_COMMAND -> TT_COMMAND_ACK round trips, idle and during a bulk upload. "compressed"
rows (not with --quick): text files deflated and as they are, see transfer_text.py; "sharing"
rows (not with --quick): five senders at once to one receiver, see sharing.py.

"ttctl-signed" is ttctl with MAVLink 2 signing on both ends (as `send-file --key` and `recv-file
--key`): every frame carries a 13-byte signature (MAVLink 2 specification, "Message Signing"), so
the one-packet frame is a TT_FILE_DATA_FIT of 66 file bytes in a 100-byte packet (94 in 128), a
TT_FILE_DATA_WIDE 280 bytes. Its rows are judged against that ceiling (signed_ceiling), not the
unsigned one. Every ceiling follows the profile's packet size (proto/transfer.py's Geometry).
"""

from __future__ import annotations

import json
import os
import random
import statistics
import tempfile
from collections.abc import Callable
from dataclasses import asdict, dataclass
from typing import Any

from ..link.model import Channel, Impairments, Profile
from ..link.sim import Simulation
from ..proto.endpoint import Endpoint
from ..proto.storage import BytesSource, ReceiveDir
from ..proto.transfer import WIDE, Geometry, TransferConfig
from . import shipped
from .latency import bound_s as latency_bound_s  # one rule with `ttctl bench latency`
from .latency import percentile

TABLET = (255, 190)
ONBOARD = (1, 240)
MAX_BULK = 8 << 20  # bytes of the file behind the commands (lan's 1 MB/s would otherwise need 400 MB)
NO_FEEDBACK_PACING = 1.0  # the model's capacity is known exactly here; see README for real links
BENCH_KEY = bytes(range(32))  # the signed rows' shared secret (any 32 bytes: both ends hold it)
SIGNED_FLOOR = 0.95  # of the signed ceiling
PIPE_FILE = 2_000_000  # bytes of each file over a profile's pipeline (mop): 20 s at its modelled rate


@dataclass
class Row:
    protocol: str
    direction: str
    loss: float
    loss_model: str
    file_bytes: int
    seconds: float
    goodput_Bps: float
    capacity_Bps: float
    efficiency: float
    ok: bool = True
    seeds: int = 1
    realised_loss: float = 0.0  # median over the seeds of the loss the data's direction actually had
    of_frame_ceiling: float | None = None  # ttctl: median of efficiency / ceiling (at the realised loss)
    ceiling: float | None = None  # ttctl: the frames' ceiling at the median realised loss (signed: signed_ceiling)


@dataclass
class Case:
    direction: str
    loss: float
    loss_model: str


def default_cases() -> list[Case]:
    cases = []
    for direction in ("up", "down"):
        cases.append(Case(direction, 0.0, "random"))
        for loss in (0.1, 0.3):
            for model in ("random", "burst"):
                cases.append(Case(direction, loss, model))
    return cases


def channels(profile: Profile, distance: float, case: Case, seed: int) -> tuple[Channel, Channel]:
    up = Channel(profile, "up", distance, Impairments(loss=case.loss, loss_model=case.loss_model), seed=seed * 2 + 1)
    down = Channel(profile, "down", distance, Impairments(loss=case.loss, loss_model=case.loss_model),
                   seed=seed * 2 + 2)
    return up, down


def pace(ch: Channel) -> float:
    return ch.capacity_Bps() * (1.0 if ch.dir.feedback else NO_FEEDBACK_PACING)


def run_ttctl(profile: Profile, distance: float, case: Case, data: bytes, seed: int,
              limit: float = 7200.0, signed: bool = False) -> tuple[float, bool, float]:
    """Seconds until the file is in place at the receiver (limit if it never is), whether it
    is, and the loss the data's direction realised. `signed`: MAVLink 2 signing at both ends."""
    up, down = channels(profile, distance, case, seed)
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-") as d:
        done: dict[str, float] = {}

        def on_event(what: str, obj: Any) -> None:
            if what == "file-complete":
                done["t"] = obj.finished_at

        store = ReceiveDir(d)
        cfg = TransferConfig()
        b = shipped.bindings()
        tablet = Endpoint(b, *TABLET, mtu=profile.mtu, rate_Bps=pace(up), config=cfg, rng=random.Random(seed),
                          receive_dir=store if case.direction == "down" else None, on_event=on_event,
                          signing=b.signing(BENCH_KEY) if signed else None)
        onboard = Endpoint(b, *ONBOARD, mtu=profile.mtu, rate_Bps=pace(down), config=cfg,
                           rng=random.Random(seed + 1),
                           receive_dir=store if case.direction == "up" else None, on_event=on_event,
                           signing=b.signing(BENCH_KEY) if signed else None)
        sender, target = (tablet, ONBOARD) if case.direction == "up" else (onboard, TABLET)
        s = sender.send_file("bench.bin", target, source=BytesSource(data, "bench.bin"))
        sim = Simulation(tablet, onboard, up, down)
        sim.run(limit, stop=lambda: "t" in done or s.done)
        ok = "t" in done
        if ok:
            with open(os.path.join(d, "bench.bin"), "rb") as fh:
                ok = fh.read() == data
        tablet.close()
        onboard.close()
        ch = up if case.direction == "up" else down
        return (done.get("t", limit), ok, ch.stats.lost / max(1, ch.stats.submitted))


def run_ttctl_signed(profile: Profile, distance: float, case: Case, data: bytes, seed: int,
                     limit: float = 7200.0) -> tuple[float, bool, float]:
    return run_ttctl(profile, distance, case, data, seed, limit, signed=True)


def signed_ceiling(p: float, mtu: int = 100) -> float:
    """What signed frames allow at packet loss p, with the frames the sender uses there (as the
    unsigned ceiling is one-packet frames'): under loss a signed TT_FILE_DATA_FIT that fills one
    packet, 66 file bytes per 100 of air (94 per 128); on a clean link TT_FILE_DATA_WIDE, signed
    280 bytes: 247 per 280."""
    g = Geometry(mtu, signed=True)
    if p <= 0.0:
        return WIDE / g.wide_frame
    return g.narrow_cap / g.narrow_frame * (1.0 - p)


def unsigned_ceiling(p: float, mtu: int = 100) -> float:
    """One-packet frames' ceiling at packet loss p: 80/100 (1 - p) on DJI's DTT (TT_FILE_DATA),
    107/128 (1 - p) on the Payload SDK channel (TT_FILE_DATA_FIT)."""
    g = Geometry(mtu)
    return g.narrow_cap / g.narrow_frame * (1.0 - p)


def frame_ceiling(protocol: str, case: Case, p: float, mtu: int = 100) -> float:
    """ttctl's ceiling at realised loss p: one-packet frames', or signed frames'."""
    if protocol == "ttctl-signed":
        return signed_ceiling(p, mtu)
    return unsigned_ceiling(p, mtu)


def run_case(protocol: str, profile: Profile, distance: float, case: Case, file_bytes: int,
             seeds: list[int]) -> Row:
    runner = PROTOCOLS[protocol]
    capacity = profile.capacity_Bps(case.direction, distance)
    times, oks, lost, ceiling = [], [], [], []
    for seed in seeds:
        data = _data(file_bytes, seed)
        t, ok, p = runner(profile, distance, case, data, seed)
        times.append(t)
        oks.append(ok)
        lost.append(p)
        best = frame_ceiling(protocol, case, p, profile.mtu)
        ceiling.append(file_bytes / t / capacity / best if t > 0 and p < 1 else 0.0)
    t = statistics.median(times)
    goodput = file_bytes / t if t > 0 else 0.0
    judged = protocol == "ttctl-signed" or (protocol == "ttctl" and case.loss > 0)
    p_mid = statistics.median(lost)
    return Row(protocol, case.direction, case.loss, case.loss_model, file_bytes, round(t, 3), round(goodput, 1),
               round(capacity, 1), round(goodput / capacity, 4), all(oks), len(seeds), round(p_mid, 4),
               round(statistics.median(ceiling), 4) if judged else None,
               round(frame_ceiling(protocol, case, p_mid, profile.mtu), 4) if judged else None)


def _data(n: int, seed: int) -> bytes:
    import random

    return random.Random(seed).randbytes(n)


# -- command latency ---------------------------------------------------------------------------

def command_latency(profile: Profile, distance: float, busy: bool, count: int = 200, seed: int = 7,
                    interval: float = 2.0) -> list[float]:
    """Round trips of TT_ACTION_COMMAND -> TT_COMMAND_ACK, idle or while the tablet uploads a
    file (one that lasts past the last command), issued every `interval` seconds (at a random
    phase within it): `ttctl bench latency`'s model phases."""
    from .latency import model_commands

    size = min(int(profile.capacity_Bps("up", distance) * interval * (count + 5)), MAX_BULK)
    cmds, _, _ = model_commands(profile, distance, "upload" if busy else "idle", count, seed, interval, size,
                                restart=True)  # a fast link finishes the (capped) file early: it starts again
    return [c.latency for c in cmds if c.latency is not None]


PROTOCOLS: dict[str, Callable[..., tuple[float, bool, float]]] = {"ttctl": run_ttctl,
                                                                   "ttctl-signed": run_ttctl_signed}


def _register_baselines() -> None:
    from . import baselines

    PROTOCOLS["thesis"] = baselines.run_thesis
    PROTOCOLS["mavftp"] = baselines.run_mavftp


def run(profile: Profile, distance: float, file_bytes: int, seeds: int, protocols: list[str],
        as_json: bool, plot: str | None, quick: bool) -> int:
    """The report; 1 if a transfer failed or a floor or ceiling was missed, else 0."""
    from ..errors import Fail

    _register_baselines()
    if plot:
        from .plots import require_matplotlib

        try:
            require_matplotlib(plot)  # fail now, not after minutes of simulation
        except RuntimeError as e:
            raise Fail(str(e)) from None
    for p in protocols:
        if p not in PROTOCOLS:
            raise Fail(f"unknown protocol {p!r} (choose from {', '.join(PROTOCOLS)})")
    extrapolated = profile.extrapolated(distance)
    if extrapolated:
        import sys

        print(f"ttctl: warning: {extrapolated}", file=sys.stderr, flush=True)
    seed_list = list(range(1, seeds + 1))
    cases = default_cases() if not quick else [Case("up", 0.0, "random"), Case("up", 0.1, "random")]
    rows: list[Row] = []
    progress = _progress(as_json, len(cases) * len(protocols))
    for case in cases:
        for p in protocols:
            rows.append(run_case(p, profile, distance, case, file_bytes, seed_list))
            progress()
    idle = command_latency(profile, distance, busy=False, count=60 if quick else 200)
    busy = command_latency(profile, distance, busy=True, count=60 if quick else 200)
    latency = [{"case": "idle", "p50_ms": round(1000 * percentile(idle, 0.5), 1),
                "p95_ms": round(1000 * percentile(idle, 0.95), 1), "count": len(idle)},
               {"case": "during_upload", "p50_ms": round(1000 * percentile(busy, 0.5), 1),
                "p95_ms": round(1000 * percentile(busy, 0.95), 1), "count": len(busy)}]
    bounds = checks(rows, latency, latency_bound_s(profile, distance), profile.mtu)
    from . import transfer_text  # deflate's rows: text files, 10 % loss (not in --quick)

    text = [] if quick else transfer_text.rows(profile, distance, seed_list[:3])
    bounds += transfer_text.checks(text)
    from . import sharing  # several senders at once to one receiver (not in --quick)

    shared = [] if quick else sharing.rows(profile, distance, seed_list[:5])
    bounds += sharing.checks(shared)
    from . import pipeline  # the profile's MOP pipeline (mop), with and without drops

    piped = pipeline.rows(profile, distance, PIPE_FILE, seed_list[:1] if quick else seed_list[:3])
    bounds += pipeline.checks(piped)
    report = {"profile": profile.name, "distance_m": distance, "extrapolated": extrapolated,
              "file_bytes": file_bytes, "seeds": seed_list,
              "mtu": profile.mtu,
              "frame_efficiency": _frame_efficiency(profile.mtu),
              "rows": [asdict(r) for r in rows], "latency": latency, "compressed": transfer_text.as_dicts(text),
              "sharing": sharing.as_dicts(shared), "pipeline": pipeline.as_dicts(piped), "checks": bounds}
    if plot:
        from .plots import plot_transfer

        plot_transfer(report, plot)
    if as_json:
        print(json.dumps(report, indent=2))
    else:
        _print_tables(report)
    return 0 if all(r.ok for r in rows) and all(c["ok"] for c in bounds) else 1


def _frame_efficiency(mtu: int) -> dict[str, float]:
    g, s = Geometry(mtu), Geometry(mtu, signed=True)
    return {"narrow": round(g.narrow_cap / g.narrow_frame, 4), "wide": round(WIDE / g.wide_frame, 4),
            "narrow_signed": round(s.narrow_cap / s.narrow_frame, 4), "wide_signed": round(WIDE / s.wide_frame, 4)}


def checks(rows: list[Row], latency: list[dict[str, Any]], bound_s: float | None = None,
           mtu: int = 100) -> list[dict[str, Any]]:
    """The issue's floors, evaluated on this run."""
    g = Geometry(mtu)
    out: list[dict[str, Any]] = []
    ours = [r for r in rows if r.protocol == "ttctl"]
    for r in ours:
        need = 0.88 if r.loss == 0 else 0.80 * (1 - r.loss)
        out.append({"check": f"efficiency {r.direction} {r.loss:.0%} {r.loss_model}", "value": r.efficiency,
                    "floor": round(need, 4), "ok": r.ok and r.efficiency >= need})
        best = max(g.narrow_cap / g.narrow_frame * (1 - r.loss), WIDE / g.wide_frame * g.survival_wide(r.loss)) \
            / (1 - r.loss) if r.loss < 1 else 1.0
        limit = 1.15 * r.file_bytes / (r.capacity_Bps * (1 - r.loss) * best)
        out.append({"check": f"time {r.direction} {r.loss:.0%} {r.loss_model}", "value": r.seconds,
                    "ceiling": round(limit, 2), "ok": r.seconds <= limit})
    for r in ours:
        if r.of_frame_ceiling is not None:
            out.append({"check": f"{r.direction} {r.loss:.0%} {r.loss_model} of its ceiling",
                        "value": r.of_frame_ceiling, "floor": SIGNED_FLOOR,
                        "ok": r.ok and r.of_frame_ceiling >= SIGNED_FLOOR})
    for r in rows:
        if r.protocol == "ttctl-signed" and r.of_frame_ceiling is not None:
            out.append({"check": f"signed {r.direction} {r.loss:.0%} {r.loss_model} of its ceiling",
                        "value": r.of_frame_ceiling, "floor": SIGNED_FLOOR,
                        "ok": r.ok and r.of_frame_ceiling >= SIGNED_FLOOR})
    for base in ("thesis", "mavftp"):
        for r in ours:
            peer = next((b for b in rows if b.protocol == base and b.direction == r.direction and b.loss == r.loss
                         and b.loss_model == r.loss_model), None)
            if peer is None:
                continue
            if base == "thesis" and r.loss == 0.1:
                ratio = r.goodput_Bps / max(peer.goodput_Bps, 1e-9)
                out.append({"check": f"vs thesis {r.direction} 10% {r.loss_model}", "value": round(ratio, 2),
                            "floor": 3.0, "ok": ratio >= 3.0})
            if base == "mavftp":
                out.append({"check": f"vs mavftp {r.direction} {r.loss:.0%} {r.loss_model}",
                            "value": round(r.goodput_Bps / max(peer.goodput_Bps, 1e-9), 2), "floor": 1.0,
                            "ok": r.goodput_Bps > peer.goodput_Bps})
    if len(latency) == 2 and bound_s is not None:  # the rule `bench latency` judges by, on the model
        budget = latency[0]["p95_ms"] + 1000 * bound_s
        out.append({"check": "command p95 during upload", "value": latency[1]["p95_ms"],
                    "ceiling": round(budget, 1), "ok": latency[1]["p95_ms"] <= budget})
    return out


def _progress(quiet: bool, total: int) -> Callable[[], None]:
    if quiet:
        return lambda: None
    from rich.progress import Progress

    bar = Progress(transient=True)
    task = bar.add_task("simulating transfers", total=total)
    bar.start()

    def step() -> None:
        bar.advance(task)
        if bar.finished:
            bar.stop()

    return step


def _print_tables(report: dict[str, Any]) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console()
    failed = any(not r["ok"] for r in report["rows"])
    signed = any(r["protocol"] == "ttctl-signed" for r in report["rows"])
    notes = (["signed: ttctl-signed, MAVLink 2 signing at both ends"] if signed else []) + \
        (["* the transfer failed (did not deliver the file)"] if failed else [])
    t = Table(title=f"{report['file_bytes'] // 1024} KiB over {report['profile']} at {report['distance_m']:g} m, "
                    f"virtual time, median of {len(report['seeds'])} seeds; rates in B/s",
              caption="\n".join(notes) or None)
    for col in ("protocol", "dir", "loss", "model", "seconds", "goodput", "capacity", "efficiency"):
        t.add_column(col, justify="right" if col not in ("protocol", "dir", "model") else "left")
    for r in report["rows"]:
        name = "signed" if r["protocol"] == "ttctl-signed" else r["protocol"]
        t.add_row(name, r["direction"], f"{r['loss']:.0%}", r["loss_model"], f"{r['seconds']:.1f}",
                  f"{r['goodput_Bps']:.0f}", f"{r['capacity_Bps']:.0f}", f"{r['efficiency']:.3f}" +
                  ("" if r["ok"] else "*"))
    console.print(t)
    lt = Table(title="command latency (TT_ACTION_COMMAND -> TT_COMMAND_ACK)")
    for col in ("case", "p50 ms", "p95 ms", "count"):
        lt.add_column(col)
    for r in report["latency"]:
        lt.add_row(r["case"], f"{r['p50_ms']:.0f}", f"{r['p95_ms']:.0f}", str(r["count"]))
    console.print(lt)
    if report.get("compressed"):
        from .transfer_text import print_table

        print_table(report["compressed"])
    if report.get("sharing"):
        from .sharing import print_table as print_sharing

        print_sharing(report["sharing"])
    if report.get("pipeline"):
        from .pipeline import print_table as print_pipeline

        print_pipeline(report["pipeline"])
    mtu = report.get("mtu", 100)
    g, sg = Geometry(mtu), Geometry(mtu, signed=True)
    titles = {"ttctl": f"ttctl against one-packet frames' ceiling, {g.narrow_cap}/{g.narrow_frame} x (1 - the loss "
                       f"each seed realised)",
              "ttctl-signed": f"signed ttctl against signed frames' ceiling: {sg.narrow_cap} file bytes in "
                              f"{sg.narrow_frame} (one packet) under loss, {WIDE} in {sg.wide_frame} (wide) on a clean "
                              f"link, at the loss each seed realised"}
    for protocol, title in titles.items():
        rt = Table(title=title)
        for col in ("dir", "loss", "model", "realised loss", "efficiency", "ceiling", "of the ceiling"):
            rt.add_column(col, justify="left" if col in ("dir", "model") else "right")
        for r in report["rows"]:
            if r["protocol"] == protocol and r.get("of_frame_ceiling") is not None:
                rt.add_row(r["direction"], f"{r['loss']:.0%}", r["loss_model"], f"{r['realised_loss']:.3f}",
                           f"{r['efficiency']:.3f}", f"{r['ceiling']:.3f}", f"{r['of_frame_ceiling']:.1%}")
        if rt.row_count:
            console.print(rt)
    ct = Table(title="floors and ceilings set for ttctl")
    for col in ("check", "value", "bound", "ok"):
        ct.add_column(col)
    for c in report["checks"]:
        bound = c.get("floor", c.get("ceiling"))
        ct.add_row(c["check"], str(c["value"]), ("≥ " if "floor" in c else "≤ ") + str(bound),
                   "[green]yes[/]" if c["ok"] else "[red]no[/]")
    console.print(ct)
