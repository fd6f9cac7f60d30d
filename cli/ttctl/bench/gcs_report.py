"""The figures of `ttctl bench gcs`, the floors of issue 22 next to them, and the table."""

from __future__ import annotations

import sys
from typing import Any

# The floors, at m100, 10 m, 10 % loss: the bridge's figure, and at least RATIO times better than
# the naive forwarder's (or the naive forwarder fails outright).
FLOORS = {"connect_s": 10.0, "upload_s": 5.0, "age_p95_ms": 500.0}
APP_BOUND_MS = 200.0  # app command p95 with a ground station <= idle p95 + this
RATIO = 3.0
FLOOR_DISTANCE, FLOOR_LOSS = 10.0, 0.1

# (key, label, unit): lower is better for every one
ROWS = (
    ("connect_s", "connect, QGC-like", "s"),
    ("params_s", " of which parameters", "s"),
    ("upload_s", "mission upload, {items} items", "s"),
    ("download_s", "mission download, {items} items", "s"),
    ("age_p50_ms", "position age p50", "ms"),
    ("age_p95_ms", "position age p95", "ms"),
    ("idle_p50_ms", "app command p50, idle", "ms"),
    ("idle_p95_ms", "app command p95, idle", "ms"),
    ("gcs_p50_ms", "app command p50, GCS on", "ms"),
    ("gcs_p95_ms", "app command p95, GCS on", "ms"),
)
FTP_ROWS = (  # with --ftp KB: the ground station's view of the vehicle while it downloads, against idle
    ("ftp_s", "MAVLink FTP download, {ftp} KB", "s"),
    ("hb_gap_idle_s", "longest HEARTBEAT gap, idle", "s"),
    ("hb_gap_ftp_s", "longest HEARTBEAT gap, FTP on", "s"),
    ("gpi_idle_hz", "positions a second, idle", "Hz"),
    ("gpi_ftp_hz", "positions a second, FTP on", "Hz"),
)
HIGHER_BETTER = {"gpi_idle_hz", "gpi_ftp_hz"}
STEP_OF = {"connect_s": "connect", "params_s": "connect", "upload_s": "upload", "download_s": "download",
           "age_p50_ms": "connect", "age_p95_ms": "connect", "ftp_s": "ftp", "hb_gap_ftp_s": "ftp",
           "gpi_ftp_hz": "ftp"}


SUMMED = ("param_reads", "upload_restarts", "ages", "idle_failed", "gcs_failed", "gcs_commands", "sticks")
POOLED = {"idle": ("idle_p50_ms", "idle_p95_ms"), "gcs": ("gcs_p50_ms", "gcs_p95_ms")}


def _median(xs: list[float]) -> float | None:
    if not xs:
        return None
    xs = sorted(xs)
    mid = len(xs) // 2
    return xs[mid] if len(xs) % 2 else (xs[mid - 1] + xs[mid]) / 2


def combine(samples: list[dict[str, Any]], seeds: list[int]) -> list[dict[str, Any]]:
    """`--repeat`: the runs of each mode and distance (one per seed, in `seeds`' order) as one
    run whose figures are their medians, a step that failed counting as slower than any that
    finished (more than half failed: no figure); the app commands' percentiles from every
    command of every run; counts summed; failures and notes kept, each with its seed."""
    from .gcs import percentile

    out = []
    keys = sorted({(r["distance_m"], r["mode"]) for r in samples}, key=lambda k: (k[0], k[1] != "bridge"))
    for d, mode in keys:
        group = [(seed, r) for seed, r in zip(seeds, [r for r in samples if (r["distance_m"], r["mode"]) == (d, mode)],
                                              strict=False)]
        started = [(seed, r) for seed, r in group if r["started"]]
        first = dict(group[0][1])
        if not started:
            out.append(first)
            continue
        c = dict(started[0][1])
        c["samples"] = len(started)
        c["failed"] = {step: f"{why} (seed {seed})" for seed, r in started for step, why in r["failed"].items()}
        c["notes"] = [f"seed {seed}: {n}" for seed, r in group for n in r["notes"]] + [
            f"seed {seed}: not measured: {r['why_not']}" for seed, r in group if not r["started"]]
        for key, value in c.items():
            if key in SUMMED:
                c[key] = sum(int(r[key] or 0) for _, r in started)
            elif isinstance(value, float | None) and key.endswith(("_s", "_ms", "_hz")):
                vals = [r[key] for _, r in started]
                if all(v is None for v in vals):
                    continue
                inf = float("-inf") if key in HIGHER_BETTER else float("inf")  # a failed step: the worst
                m = _median([v if v is not None else inf for v in vals])
                c[key] = None if m is None or abs(m) == float("inf") else round(m, 3)
        for pool, (p50, p95) in POOLED.items():
            every = [x for _, r in started for x in r[f"{pool}_ms"]]
            c[f"{pool}_ms"] = every
            c[p50], c[p95] = percentile(every, 0.5), percentile(every, 0.95)
        c["items_checked"] = all(r["items_checked"] for _, r in started)
        c["param_count"] = max(int(r["param_count"] or 0) for _, r in started)
        c["each"] = {key: [r[key] for _, r in started] for key in ("connect_s", "upload_s", "download_s")}
        out.append(c)
    return out


def _pair(runs: list[dict[str, Any]], distance: float) -> tuple[dict[str, Any] | None, dict[str, Any] | None]:
    by = {r["mode"]: r for r in runs if r["distance_m"] == distance}
    return by.get("bridge"), by.get("naive")


def _value(r: dict[str, Any] | None, key: str) -> float | None:
    if r is None or not r["started"]:
        return None
    return r.get(key)


def _naive_failed(n: dict[str, Any] | None, key: str) -> bool:
    if n is None:
        return False
    if not n["started"]:
        return False  # not measured (its set-up failed): no ratio
    if key.startswith("gcs_"):
        return n["gcs_failed"] > 0 and n[key] is None
    return n.get(key) is None and (STEP_OF.get(key, "") in n["failed"] or "ground station" in n["failed"])


# frame sizes on the wire (MAVLink 2, unsigned, trailing zeros trimmed: the least a frame can be,
# for a bound that nothing beats)
FEW_SAMPLES = 20  # commands under which a p95 is about the largest one: a retry decides it
# MISSION_ITEM_INT (the peer's), MISSION_REQUEST_INT, GLOBAL_POSITION_INT
ITEM_FRAME, REQUEST_FRAME, POSITION_FRAME = 49, 20, 42
APP_FRAME, HEARTBEAT_FRAME = 41, 21  # the app's TT_ACTION_COMMAND (hover), a HEARTBEAT
PARAM_FRAME = 37  # PARAM_VALUE (its last byte, the type, is never zero: nothing trimmed)
CONNECT_TRIPS = 3  # AUTOPILOT_VERSION, the parameter list, the mission list: each waits for the one before


def app_load_Bps(rep: dict[str, Any], run: dict[str, Any] | None) -> float:
    """The uplink the run's own other traffic takes while the ground station uploads, at the
    least: the app's commands (one every --interval s, or its latency if longer: each waits for
    its answer) and the tablet's and the station's HEARTBEATs at 1 Hz."""
    interval = float(rep.get("interval_s") or 0.0)
    p50 = (run or {}).get("gcs_p50_ms")
    every = max(interval, (p50 or 0.0) / 1000.0)
    return (APP_FRAME / every if every > 0 else 0.0) + 2 * HEARTBEAT_FRAME


def physical_best(profile: str, distance: float, key: str, items: int, loss: float = 0.0,
                  load_Bps: float = 0.0, params: int = 0) -> tuple[float, str] | None:
    """The least a figure can be on this link whatever a bridge does, and why (None: no bound
    computed): a mission upload moves its items' bytes up the link, at random loss `loss` each
    sent 1 / (1 - loss) times on average, in what the run's other traffic (`load_Bps`) leaves of
    the uplink, and needs the vehicle's last answer back (a bridge that pipelines the items pays
    one round trip, not one per item); a connect is QGroundControl's three requests one after
    the other (AUTOPILOT_VERSION, the parameter list, the mission list), each a round trip, and the
    `params` values' frames down (the vehicle's HEARTBEAT, which it waits for first, taken as
    heard at once); a position's age is its frame's time on the downlink and the downlink's
    latency."""
    from ..link.model import load_profile

    try:
        p = load_profile(profile)
    except Exception:  # a profile from a file the report cannot load: no bound
        return None
    up, down = p.direction("up"), p.direction("down")
    if key == "upload_s":
        rate = up.rate_at(distance)
        free = max(1.0, rate - load_Bps)
        sent = ITEM_FRAME * items / (1.0 - min(loss, 0.9))
        best = max(sent / free, up.service_time(round(sent), distance)) + up.latency_s \
            + down.service_time(REQUEST_FRAME, distance) + down.latency_s
        why = f"{items} items are {ITEM_FRAME * items} bytes up at {rate:.0f} B/s"
        if loss > 0:
            why += f", {sent:.0f} with the {loss:.0%} lost sent again (on average)"
        if load_Bps > 0:
            why += f", in the {free:.0f} B/s the app's commands and the heartbeats ({load_Bps:.0f} B/s) leave"
        return best, why + ", and a round trip" + ("" if loss > 0 else ", with no loss")
    if key == "connect_s":
        trip = up.service_time(REQUEST_FRAME, distance) + up.latency_s + down.service_time(REQUEST_FRAME, distance) \
            + down.latency_s
        best = CONNECT_TRIPS * trip + down.service_time(PARAM_FRAME * params, distance)
        return best, (f"{CONNECT_TRIPS} requests one after the other, a {1000 * trip:.0f} ms round trip each, and "
                      f"{params} parameters' {PARAM_FRAME * params} bytes down at {down.rate_at(distance):.0f} B/s, "
                      "with no loss")
    if key == "age_p95_ms":
        best = 1000 * (down.service_time(POSITION_FRAME, distance) + down.latency_s)
        return best, f"a position takes {best:.0f} ms down this link (its frame's time and the latency) with no loss"
    return None


def checks(rep: dict[str, Any]) -> list[dict[str, Any]]:
    """Each floor at each distance: the bridge's figure against its floor, and against the naive
    forwarder's. Only those at the issue's conditions count for the exit status."""
    out = []
    distances = sorted({r["distance_m"] for r in rep["runs"]})
    for d in distances:
        b, n = _pair(rep["runs"], d)
        counts = d == FLOOR_DISTANCE and abs(rep["loss"] - FLOOR_LOSS) < 1e-9 and rep["loss_model"] == "random"
        if b is None:
            continue
        limits = dict(FLOORS)
        idle = _value(b, "idle_p95_ms")
        limits["gcs_p95_ms"] = idle + APP_BOUND_MS if idle is not None else float("nan")
        for key, floor in limits.items():
            v = _value(b, key)
            fc = {"distance_m": d, "check": key, "kind": "floor", "value": v, "floor": round(floor, 1),
                  "ok": v is not None and v <= floor, "counts": counts}
            few = min(len(b.get("idle_ms") or []), len(b.get("gcs_ms") or []))
            if key == "gcs_p95_ms" and not fc["ok"] and v is not None and few < FEW_SAMPLES:
                tries = [round(x) for x in sorted(b["gcs_ms"])[-2:]]
                fc["limit"] = (f"a p95 of {few} commands is about their largest: a command whose try or ack the "
                               f"{rep['loss']:.0%} loss took waits for the app's retry (the largest here: "
                               f"{', '.join(map(str, tries))} ms); run without --quick for more")
            out.append(fc)
            nv = _value(n, key)
            if n is None:
                continue
            if _naive_failed(n, key):
                out.append({"distance_m": d, "check": key, "kind": "vs naive", "value": None, "floor": RATIO,
                            "ok": v is not None, "naive": "failed", "counts": counts})
            else:
                ratio = round(nv / v, 2) if v and nv is not None else None
                c = {"distance_m": d, "check": key, "kind": "vs naive", "value": ratio, "floor": RATIO,
                     "ok": ratio is not None and ratio >= RATIO, "naive": "measured", "counts": counts}
                random_loss = rep["loss"] if rep["loss_model"] == "random" else 0.0  # (burst: no mean here)
                best = physical_best(rep["profile"], d, key, rep.get("items", 0), random_loss, app_load_Bps(rep, b),
                                     params=int(b.get("param_count") or 0))
                unit = "ms" if key.endswith("_ms") else "s"
                if best is not None:
                    best = (best[0], f"the {_fmt(best[0], unit)} {unit} physics allows: {best[1]}")
                if key == "gcs_p95_ms" and idle is not None:
                    best = (idle, f"the {_fmt(idle, unit)} ms the same commands took with no ground station at all "
                                  "(idle p95, this run): a ground station adds to the link's load, it cannot take "
                                  "its loss away")
                if not c["ok"] and nv is not None and best is not None and nv / RATIO < best[0]:
                    c["limit"] = (f"{RATIO:g}x the naive forwarder's {_fmt(nv, unit)} {unit} would be "
                                  f"{_fmt(nv / RATIO, unit)} {unit}, under {best[1]}")
                out.append(c)
    return out


def _fmt(v: float | None, unit: str) -> str:
    if v is None:
        return "-"
    return f"{v:.1f}" if unit in ("s", "Hz") else f"{v:.0f}"


def print_report(rep: dict[str, Any], out: Any = None) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console(file=out or sys.stdout, width=100)
    for d in sorted({r["distance_m"] for r in rep["runs"]}):
        b, n = _pair(rep["runs"], d)
        sticks = f", MANUAL_CONTROL at {rep['sticks_hz']:g} Hz" if rep.get("sticks_hz") else ""
        seeds = rep.get("seeds") or [rep["seed"]]
        runs = f", median of {len(seeds)} runs (seeds {seeds[0]}-{seeds[-1]})" if len(seeds) > 1 else ""
        t = Table(title=f"a ground station ({rep['gcs_id']}{sticks}) through the tablet end, bridge against naive "
                        f"forwarder: {rep['profile']} at {d:g} m, {rep['loss']:.0%} {rep['loss_model']} loss{runs}")
        for col in ("figure", "bridge", "naive", "naive/bridge", "floor", "holds"):
            t.add_column(col, justify="left" if col == "figure" else "right")
        ch = {(c["check"], c["kind"]): c for c in rep["checks"] if c["distance_m"] == d}
        for key, label, unit in ROWS + (FTP_ROWS if rep.get("ftp_kb") else ()):
            bv, nv = _value(b, key), _value(n, key)
            nfail = _naive_failed(n, key)
            ratio = "naive failed" if nfail else (f"{nv / bv:.1f}x" if bv and nv is not None else "-")
            if key in HIGHER_BETTER:
                ratio = "-"
            floor = ch.get((key, "floor"))
            floor_text = "" if floor is None else f"<= {floor['floor']:.0f}, {RATIO:g}x"
            holds = ""
            if floor is not None:
                vs = ch.get((key, "vs naive"))
                oks = [floor["ok"]] + ([vs["ok"]] if vs is not None else [])
                holds = "[green]yes[/]" if all(oks) else "[red]no[/]"
                if not floor["counts"]:
                    holds += " (ref.)"
            t.add_row(f"{label.format(items=rep['items'], ftp=rep.get('ftp_kb'))} ({unit})", _fmt(bv, unit),
                      "failed" if nfail else _fmt(nv, unit), ratio, floor_text, holds)
        console.print(t)
        for r in (b, n):
            if r is None:
                continue
            words = []
            if not r["started"]:
                words.append(f"not measured: {r['why_not']}")
            words += [f"{step} failed: {why}" for step, why in r["failed"].items()]
            if r["connect_s"] is not None:
                words.append(f"connect: vehicle heard after {r['heartbeat_s']:.1f} s, AUTOPILOT_VERSION "
                             f"{r['version_s']:.1f} s, parameters {r['params_s']:.1f} s, mission list "
                             f"{r['mission_list_s']:.1f} s")
            if r.get("ack_wait_s") is not None:
                late = " (QGroundControl gives up after 1.5 s)" if r["ack_wait_s"] > 1.5 else ""
                words.append(f"upload: the MISSION_ACK came {r['ack_wait_s']:.1f} s after the last item first "
                             f"went{late}")
            if r["started"]:
                words.append(f"{r['param_count']} parameters, {r['param_reads']} re-read by index; "
                             f"{r['upload_restarts']} upload(s) started over after a lost MISSION_ACK; "
                             f"{r['ages']} positions; app commands {r['idle_failed']} + {r['gcs_failed']} "
                             f"unanswered of {rep['commands'] * r.get('samples', 1)} + {r['gcs_commands']}"
                             + (f"; {r['sticks']} MANUAL_CONTROL sent" if r.get("sticks") else ""))
            if r.get("samples", 1) > 1:
                words.append(f"median of {r['samples']} runs; each: " + "; ".join(
                    f"{k.removesuffix('_s')} " + " ".join(_fmt(v, "s") for v in vs) + " s"
                    for k, vs in r["each"].items()))
            words += r["notes"]
            for w in words:
                console.print(f"{r['mode']}: {w}", markup=False, highlight=False)
    for c in rep["checks"]:
        if c.get("limit"):
            console.print(f"limit ({c['check']}, {c['distance_m']:g} m): {c['limit']}", markup=False, highlight=False)
    method = next((r["age_method"] for r in rep["runs"] if r["age_method"]), "")
    console.print("connect: HEARTBEAT, AUTOPILOT_VERSION, parameters, mission list; the ground station is "
                  "pymavlink with QGroundControl's timeouts and retries (missions by pymavlink, not MAVSDK); "
                  f"position: GLOBAL_POSITION_INT, age = {method or 'no positions'}", markup=False, highlight=False)
    console.print(f"floors (issue 22) count at {FLOOR_DISTANCE:g} m, {FLOOR_LOSS:.0%} random loss: app command p95 "
                  f"with a ground station <= idle p95 + {APP_BOUND_MS:g} ms; each >= {RATIO:g}x the naive "
                  "forwarder's, or the naive forwarder fails", markup=False, highlight=False)
