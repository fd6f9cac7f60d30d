"""`ttctl link fit`: a link profile fitted from `ttctl bench link --to` measurements.

The model (ttctl.link.model) has, per direction: a rate against distance, optional DJI-style
pacing, an SDK buffer of queue_packets, a fixed latency, and loss against distance, random or
Gilbert-Elliott bursts. Each is read off the measurement where it shows:

- rate: rows where the sender outpaced the link (ttctl.bench.replay.saturated) give a service
  time per packet, size / capacity_Bps; per distance, the least-squares fit of size / rate.
  Pacing (a floor of ceil(size / pacing_bytes) x pacing_interval_s) is kept only where three or
  more sizes show it: it must halve the error of the plain rate, and that error must be over
  8 %. A direction never outpaced keeps the base profile's rate if that is above every rate
  offered, else 1.5 x the highest offered (a lower bound, said so in the notes).
- latency: the echoes' round trip p50, less the service times of an echo each way, split
  evenly between the two directions (one-way delays need synchronised clocks; the split is the
  assumption, the sum is measured).
- buffer depth: in a saturated row every packet waits behind a full buffer, so its one-way
  delay grows by a service time per buffered packet. The depth (1..MAX_QUEUE) whose replay puts
  the saturated rows' median delay where it was measured, the measured delay corrected for the
  NTP-style offset's error under the fitted rates and latency (ttctl.bench.replay.offset_error);
  the base's without such rows.
- loss per distance: 1 - received / what the buffer lets through, the latter from replaying the
  rows with no loss (so overflow is not counted as the radio's loss).
- bursts: in rows that did not saturate (overflow drops are periodic, not the radio's), the runs
  of lost packets. The model's bursts are in time (ttctl.link.model): its Gilbert-Elliott chain
  steps once per slot, one full packet's time at the fitted rate, and burst_mean is the mean
  burst in slots (the mean run of lost packets on a saturated link). A row's probes go out
  n = interval / slot slots apart (interval: size / pace_Bps up, 1 / rate_hz down), so a lost
  probe's successor is lost with q(n) = p + (1 - p) lam^n, lam = 1 - b / (1 - p), b = 1 /
  burst_mean: a run of lost probes is geometric with mean 1 / (1 - q(n)), and a row of L lost
  probes in R runs shows L - R continuations and R ends. lam is the maximum-likelihood value over
  the rows together (each at its own n), so runs measured at any probe spacing convert to slots;
  burst_mean = 1 / ((1 - p) (1 - lam)). Random loss is lam = 0 (runs of mean 1 / (1 - p)); the
  loss is Gilbert-Elliott when lam > 0 is better by a likelihood ratio over 4 (about two standard
  errors), over at least MIN_RUNS runs, and burst_mean is over 1.2. A direction with fewer runs is
  judged on both directions' together (the same radio), each row at its own direction's slot.

Then every measurement is replayed on the fitted profile and compared figure by figure
(ttctl.bench.replay.compare): those are the residuals.
"""

from __future__ import annotations

import dataclasses
import json
import math
import re
import statistics
import time
from dataclasses import dataclass, field
from typing import Any

from ..errors import Fail
from ..link.model import DIRECTIONS, DirectionProfile, Profile, ProfileError, load_profile
from . import replay as R

MAX_QUEUE = 32
MIN_RUNS = 5
MAX_FILE = 16 << 20
_DIST = re.compile(r"(\d+(?:\.\d+)?)\s*m\b")
_ROW_NUMBERS = ("sent", "received", "loss", "capacity_Bps", "throughput_Bps")


@dataclass
class Measurement:
    path: str
    report: dict[str, Any]
    distance: float | None

    @property
    def label(self) -> str:
        return str(self.report["conditions"].get("label") or "")


@dataclass
class Fit:
    profile: Profile
    notes: list[str] = field(default_factory=list)
    residuals: list[dict[str, Any]] = field(default_factory=list)  # replay.compare rows, plus "file"


def _bad(path: str, why: str) -> Fail:
    return Fail(f"{path}: not a `ttctl bench link --to ... -o FILE.json` measurement: {why}")


def _number(v: Any) -> bool:
    return isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)


def load_measurement(path: str) -> Measurement:
    """A measurement file, checked field by field; anything else is one line of Fail."""
    if path.endswith(".csv"):
        raise Fail(f"{path}: link fit reads the JSON report (bench link --to ... -o FILE.json): the CSV has no "
                   f"round trips or pacing")
    from ..safeio import read_capped

    raw = read_capped(path, path, MAX_FILE)
    try:
        report = json.loads(raw)
    except (UnicodeDecodeError, json.JSONDecodeError) as e:
        raise _bad(path, f"not JSON ({e})") from None
    except RecursionError:  # the decoder recurses once per level
        raise _bad(path, "nested too deeply to be a measurement") from None
    if not isinstance(report, dict):
        raise _bad(path, "not a JSON object")
    for key in ("conditions", "uplink", "downlink"):
        if not isinstance(report.get(key), dict):
            raise _bad(path, f"no {key!r} object")
    cond = report["conditions"]
    if not (isinstance(cond.get("count"), int) and cond["count"] >= 1):
        raise _bad(path, "conditions.count is missing or not a positive whole number")
    if not (_number(report["uplink"].get("pace_Bps")) and report["uplink"]["pace_Bps"] > 0):
        raise _bad(path, "uplink.pace_Bps is missing or not positive")
    lat = report.get("latency")
    if lat is not None and not (isinstance(lat, dict) and _number(lat.get("rtt_p50_ms"))
                                and isinstance(lat.get("echoes"), int)):
        raise _bad(path, "latency has no rtt_p50_ms or echoes")
    if lat is not None and not (lat["rtt_p50_ms"] > 0 and lat["echoes"] >= 0):
        raise _bad(path, f"latency.rtt_p50_ms is {lat['rtt_p50_ms']:g}: a round trip takes a positive time")
    for k, v in (lat or {}).items():
        if k.endswith("_ms") and k != "clock_offset_ms" and _number(v) and v < 0:  # an offset has a sign
            raise _bad(path, f"latency.{k} is {v:g}: a time cannot be negative")
    for d in ("uplink", "downlink"):
        rows = report[d].get("rows")
        if not isinstance(rows, list):
            raise _bad(path, f"{d}.rows is not a list")
        for i, row in enumerate(rows):
            where = f"{d}.rows[{i}]"
            if not isinstance(row, dict):
                raise _bad(path, f"{where} is not an object")
            for k in ("size", *_ROW_NUMBERS) + (("rate_hz",) if d == "downlink" else ()):
                if not _number(row.get(k)):
                    raise _bad(path, f"{where}.{k} is missing or not a number")
            if not (isinstance(row["sent"], int) and row["sent"] >= 1 and 0 <= row["received"] <= row["sent"]
                    and 1 <= row["size"] <= 100 and 0 <= row["loss"] <= 1 and row["throughput_Bps"] > 0
                    and row["capacity_Bps"] >= 0):
                raise _bad(path, f"{where} has impossible values (sent, received, size, loss or throughput)")
            if d == "downlink" and row["rate_hz"] <= 0:
                raise _bad(path, f"{where}.rate_hz must be positive")
    if not report["uplink"]["rows"] and not report["downlink"]["rows"]:
        raise _bad(path, "no rows measured")
    dist = cond.get("distance_m")
    if dist is not None and not (_number(dist) and dist >= 0):
        raise _bad(path, "conditions.distance_m is not a number of metres >= 0")
    if dist is None:
        m = _DIST.search(str(cond.get("label") or ""))
        dist = float(m.group(1)) if m else None
    return Measurement(path, report, float(dist) if dist is not None else None)


def _rows(ms: list[Measurement], direction: str) -> list[tuple[Measurement, dict[str, Any]]]:
    key = "uplink" if direction == "up" else "downlink"
    return [(m, row) for m in ms for row in m.report[key]["rows"]]


def _dist(m: Measurement) -> float:
    return m.distance if m.distance is not None else 0.0


def _rate_fit(points: list[tuple[int, float]]) -> tuple[float, int, float, float]:
    """(rate, pacing_bytes, pacing_interval_s, rms relative error) for service times t(size)."""
    def err(rate: float, pb: int, pi: float) -> float:
        rel = []
        for s, t in points:
            model = s / rate
            if pb:
                model = max(model, math.ceil(s / pb) * pi)
            rel.append((model - t) / t)
        return math.sqrt(statistics.mean(r * r for r in rel))

    rate = sum(s * s for s, _ in points) / sum(s * t for s, t in points)
    best = (rate, 0, 0.0, err(rate, 0, 0.0))
    if len({s for s, _ in points}) >= 3 and best[3] > 0.08:
        for pb in range(1, 101):
            for s0, t0 in points:
                pi = t0 / math.ceil(s0 / pb)
                for s1, t1 in points:
                    r = s1 / t1
                    e = err(r, pb, pi)
                    if e < best[3] * 0.5 and (best[1] == 0 or e < best[3]):
                        best = (r, pb, pi, e)
    return best


def _zero_loss(dp: DirectionProfile) -> DirectionProfile:
    return dataclasses.replace(dp, loss=[[0.0, 0.0]], loss_model="random")


def _replay_row(prof: Profile, direction: str, m: Measurement, row: dict[str, Any], seed: int) -> dict[str, Any]:
    if direction == "up":
        return R.uplink_once(prof, _dist(m), int(row["size"]), int(row["sent"]),
                             float(m.report["uplink"]["pace_Bps"]), seed)
    return R.downlink_once(prof, _dist(m), float(row["rate_hz"]), int(row["sent"]), seed, int(row["size"]))


Rows = list[tuple[Measurement, dict[str, Any]]]


def _by_distance(rows: Rows) -> dict[float, Rows]:
    out: dict[float, Rows] = {}
    for m, row in rows:
        out.setdefault(_dist(m), []).append((m, row))
    return dict(sorted(out.items()))


def fit_rate(ms: list[Measurement], direction: str, base: DirectionProfile, notes: list[str]) -> DirectionProfile:
    """Stage 1: rate per distance (and pacing) from the rows the sender saturated."""
    rows = _rows(ms, direction)
    if not rows:
        notes.append(f"{direction}: not measured: the base profile's figures are kept")
        return base
    rate_pts: list[list[float]] = []
    pacing = (0, 0.0)
    for d, drows in _by_distance(rows).items():
        pts = [(int(r["size"]), r["size"] / r["capacity_Bps"]) for _, r in drows if R.saturated(r)]
        if pts:
            rate, pb, pi, _ = _rate_fit(pts)
            if pb:
                pacing = (pb, pi)
                notes.append(f"{direction} at {d:g} m: pacing {pb} B every {pi * 1e3:.1f} ms fits the sizes")
        else:
            offered = max(float(r["throughput_Bps"]) for _, r in drows)
            keep = base.rate_at(d)
            rate = keep if keep > offered else 1.5 * offered
            notes.append(f"{direction} at {d:g} m: never outpaced (it carried every rate offered, up to "
                         f"{offered:.0f} B/s): rate_Bps set to {rate:.0f}, a lower bound; measure at a higher "
                         f"{'--rate' if direction == 'up' else '--rates'} to fit it")
        rate_pts.append([d, round(rate, 1)])
    return dataclasses.replace(base, rate_Bps=rate_pts, pacing_bytes=pacing[0],
                               pacing_interval_s=round(pacing[1], 6), loss_model="random")


def fit_queue(ms: list[Measurement], direction: str, up: DirectionProfile, down: DirectionProfile,
              notes: list[str]) -> int | None:
    """Stage 3 (after rates and latency): the buffer depth whose replay puts the saturated rows'
    median one-way delay where it was measured (corrected for the clock offset's error)."""
    rows = [(m, r) for m, r in _rows(ms, direction) if R.saturated(r) and r.get("owd_p50_ms") is not None]
    if not rows:
        notes.append(f"{direction}: no saturated rows: the buffer depth is the base's")
        return None
    mine = up if direction == "up" else down

    def cost(q: int) -> float:
        d = dataclasses.replace(_zero_loss(mine), queue_packets=q)
        prof = Profile("trial", "", 100, d if direction == "up" else up, d if direction == "down" else down)
        total = 0.0
        for m, r in rows:
            measured = R.true_delay_ms(r, R.offset_error(prof, _dist(m))) or 0.0
            total += abs(float(_replay_row(prof, direction, m, r, 1)["owd_p50_ms"]) - measured)
        return total

    costs = {q: cost(q) for q in range(1, MAX_QUEUE + 1)}
    q = min(costs, key=lambda k: (round(costs[k], 1), k))
    notes.append(f"{direction}: buffer {q} packets (the median delay of saturated rows off by "
                 f"{costs[q] / len(rows):.1f} ms a row)")
    return q


def fit_loss(ms: list[Measurement], direction: str, prof: Profile, notes: list[str],
             other_runs: list[RunRow] | None) -> DirectionProfile:
    """Stage 4: loss per distance (received over what the buffer lets through) and bursts."""
    rows = _rows(ms, direction)
    mine = prof.direction(direction)
    if not rows:
        return mine
    clean = Profile("trial", "", prof.mtu, _zero_loss(prof.up), _zero_loss(prof.down))
    loss_pts = []
    for d, drows in _by_distance(rows).items():
        through = sum(_replay_row(clean, direction, m, r, 1)["received"] for m, r in drows)
        got = sum(int(r["received"]) for _, r in drows)
        p = min(0.999, max(0.0, 1.0 - got / through)) if through else 1.0
        loss_pts.append([d, round(p, 4)])
    runs = _runs(ms, direction, prof)
    n_mine = sum(r[2] for r in runs)
    if n_mine < MIN_RUNS and other_runs:
        # the same radio both ways: judge on both directions' runs together
        notes.append(f"{direction}: {n_mine} loss runs in rows that did not saturate: bursts judged on both "
                     f"directions' ({n_mine + sum(r[2] for r in other_runs)} runs; the same radio)")
        runs = runs + other_runs
    model, mean = _burstiness(runs, direction, notes)
    return dataclasses.replace(mine, loss=loss_pts, loss_model=model, burst_mean=round(mean, 2))


RunRow = tuple[int, int, int, float]  # sent, lost, loss runs, slots between probes


def _runs(ms: list[Measurement], direction: str, prof: Profile) -> list[RunRow]:
    """Per unsaturated row: (sent, lost, loss runs, probe spacing in slots of `prof`'s rate)."""
    dp = prof.direction(direction)
    out = []
    for m, r in _rows(ms, direction):
        if R.saturated(r) or "loss_runs" not in r:
            continue
        interval = float(r["size"]) / float(m.report["uplink"]["pace_Bps"]) if direction == "up" \
            else 1.0 / float(r["rate_hz"])
        slot = dp.service_time(prof.mtu, _dist(m))
        out.append((int(r["sent"]), int(r["sent"]) - int(r["received"]), int(r["loss_runs"]),
                    max(interval, 1e-9) / slot))
    return out


def _log_likelihood(runs: list[RunRow], p: float, lam: float) -> float:
    total = 0.0
    for _, lost, n, step in runs:
        q = min(1.0 - 1e-12, max(1e-12, p + (1.0 - p) * lam ** step))
        total += (lost - n) * math.log(q) + n * math.log(1.0 - q)
    return total


def _best_lam(runs: list[RunRow], p: float) -> float:
    """The lam in [0, 1) that explains the runs best (a grid, then a golden-section refinement
    around its best point; the likelihood is smooth and single-peaked in lam)."""
    grid = [k / 200 for k in range(200)]
    best = max(grid, key=lambda x: _log_likelihood(runs, p, x))
    lo, hi = max(0.0, best - 0.005), min(0.9999, best + 0.005)
    g = (math.sqrt(5) - 1) / 2
    for _ in range(40):
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        if _log_likelihood(runs, p, a) < _log_likelihood(runs, p, b):
            lo = a
        else:
            hi = b
    mid = (lo + hi) / 2
    return mid if _log_likelihood(runs, p, mid) >= _log_likelihood(runs, p, best) else best


def _burstiness(runs: list[RunRow], direction: str, notes: list[str]) -> tuple[str, float]:
    n = sum(r[2] for r in runs)
    if n < MIN_RUNS:
        notes.append(f"{direction}: too few losses to tell bursts from random loss (need {MIN_RUNS} loss runs in "
                     f"rows that did not saturate): random")
        return "random", 3.0
    sent, lost = sum(r[0] for r in runs), sum(r[1] for r in runs)
    p = lost / sent
    seen = lost / n
    expect = 1 / (1 - p)
    se = math.sqrt(p / (1 - p) ** 2 / n)  # a run's length is geometric under random loss
    step = sum(r[3] * r[2] for r in runs) / n
    lam = _best_lam(runs, p)
    mean = 1.0 / ((1.0 - p) * (1.0 - lam))
    ratio = 2.0 * (_log_likelihood(runs, p, lam) - _log_likelihood(runs, p, 0.0))
    spacing = f"probes {step:.2f} slots apart"
    if ratio > 4.0 and mean > 1.2:
        notes.append(f"{direction}: loss comes in bursts: mean run {seen:.2f} packets over {n} runs, {spacing} "
                     f"(random loss would give {expect:.2f} +- {se:.2f}): Gilbert-Elliott, burst_mean {mean:.2f} "
                     f"slots")
        return "burst", mean
    notes.append(f"{direction}: loss looks random: mean run {seen:.2f} packets over {n} runs, {spacing} (random "
                 f"would give {expect:.2f} +- {se:.2f})")
    return "random", 3.0


def _latency(ms: list[Measurement], up: DirectionProfile, down: DirectionProfile, notes: list[str],
             base: float) -> float:
    """One-way latency: (echo RTT p50 - an echo's service time each way) / 2, median over files."""
    each = []
    for m in ms:
        lat = m.report.get("latency")
        if not lat:
            continue
        d = _dist(m)
        rest = lat["rtt_p50_ms"] / 1e3 - up.service_time(R.ECHO_SIZE, d) - down.service_time(R.ECHO_SIZE, d)
        each.append(max(0.0, rest / 2))
    if not each:
        notes.append(f"latency: no echoes measured: kept from the base ({base * 1e3:g} ms)")
        return base
    value = statistics.median(each)
    notes.append(f"latency: {value * 1e3:.1f} ms each way (echo round trips less service times, split evenly)")
    return round(value, 4)


def check_distances(ms: list[Measurement]) -> None:
    known = [m for m in ms if m.distance is not None]
    if known and len(known) < len(ms):
        m = next(m for m in ms if m.distance is None)
        raise Fail(f"{m.path}: no distance (measure with `bench link --to ... --distance METRES`, or put e.g. "
                   f"'150 m' in --label): the other files have one")


def fit(ms: list[Measurement], base: Profile, name: str) -> Fit:
    check_distances(ms)
    notes: list[str] = []
    up = fit_rate(ms, "up", base.up, notes)
    down = fit_rate(ms, "down", base.down, notes)
    if any(m.report.get("latency") for m in ms):
        latency = _latency(ms, up, down, notes, base.up.latency_s)
        up, down = dataclasses.replace(up, latency_s=latency), dataclasses.replace(down, latency_s=latency)
    else:
        notes.append("latency: no echoes measured: the base's")
    for d in DIRECTIONS:
        q = fit_queue(ms, d, up, down, notes)
        if q is not None and d == "up":
            up = dataclasses.replace(up, queue_packets=q)
        elif q is not None:
            down = dataclasses.replace(down, queue_packets=q)
    labels = "; ".join(sorted({m.label for m in ms if m.label})) or "no label"
    desc = f"fitted by ttctl link fit from {len(ms)} measurement(s) ({labels}); base {base.name}"
    trial = Profile(name, desc, base.mtu, up, down)
    up_runs, down_runs = _runs(ms, "up", trial), _runs(ms, "down", trial)
    prof = Profile(name, desc, base.mtu, fit_loss(ms, "up", trial, notes, down_runs),
                   fit_loss(ms, "down", trial, notes, up_runs))
    result = Fit(prof, notes)
    for m in ms:
        model = R.replay(prof, m.report, _dist(m))
        result.residuals += [{"file": m.path, **c} for c in R.compare(m.report, model, prof, _dist(m))]
    return result


def _toml_value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int | float):
        return repr(float(v)) if isinstance(v, float) else str(v)
    if isinstance(v, str):
        return json.dumps(v)  # JSON's escapes are a subset of a TOML basic string's
    if isinstance(v, list):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise TypeError(f"no TOML for {type(v).__name__}")


def to_toml(f: Fit, sources: list[str]) -> str:
    """The profile as TOML in profiles.toml's schema, with where it came from in comments.
    (Checked by reading it back: what tomllib reads is the fitted profile.)"""
    import tomllib

    p = f.profile
    when = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    ok = sum(r["ok"] for r in f.residuals)
    lines = [f"# Link profile {p.name!r}, fitted by `ttctl link fit` on {when}",
             "# from: " + ", ".join(sources),
             f"# replayed on the model it reproduces {ok} of {len(f.residuals)} measured figures within tolerance",
             "# Use it with --profile-file FILE wherever --profile is accepted.", "#"]
    lines += [f"# {n}" for n in f.notes]
    lines += ["", f"[{p.name}]", f"description = {_toml_value(p.description)}", f"mtu = {p.mtu}"]
    table: dict[str, Any] = {"description": p.description, "mtu": p.mtu}
    for d in DIRECTIONS:
        entry = {k: v for k, v in dataclasses.asdict(p.direction(d)).items() if v is not None}
        if entry.get("loss_model") == "random":
            entry.pop("burst_mean", None)
        table[d] = entry
        lines += ["", f"[{p.name}.{d}]"] + [f"{k} = {_toml_value(v)}" for k, v in entry.items()]
    text = "\n".join(lines) + "\n"
    back = tomllib.loads(text)[p.name]
    if json.dumps(back, sort_keys=True) != json.dumps(table, sort_keys=True):
        raise RuntimeError(f"internal error: the profile's TOML reads back differently: {back} != {table}")
    return text


def base_profile(name: str) -> Profile:
    try:
        return load_profile(name)
    except ProfileError as e:
        raise Fail(f"--base: {e}") from None
