"""A `ttctl bench link --to` measurement replayed on the link model, and the two compared.

The live run (ttctl.bench.live) sends, in real time: echoes one at a time (ECHO_SIZE bytes each
way), then per uplink size `count` probes evenly paced at the uplink pace, then per downlink rate
`count` DOWN_SIZE-byte probes at that rate. `replay` sends the same packets at the same moments
through the model's Channels (virtual time) and computes each row the way the live run does:
received, loss runs, capacity (size over the median gap between arrivals), one-way delay and
the echoes' round trip. One-way delays are exact here; live they carry the error of the NTP-style
clock offset, which assumes an echo takes as long each way. Under a profile that error is known,
half the difference of an echo's two one-way times (offset_error), so the measured delays are
corrected by it before they are compared.

Each row is replayed with several seeds and every figure is the median over them. `compare`
puts a measurement and a replay side by side, with the tolerance each figure must meet
(TOLERANCES), so that "the profile reproduces the measurement" is a checked statement.
"""

from __future__ import annotations

import itertools
import math
import random
import statistics
from typing import Any

from ..link import probes as P
from ..link.model import Channel, Impairments, Profile
from ..link.probes import pct as _pct

ECHO_SIZE = P.ECHO_REPLY.size  # an echo request is padded to the size of its answer
DOWN_SIZE = 100
SEEDS = 7

# What "reproduces" means, per figure: measured and replayed must be within these.
TOLERANCES = {
    "capacity": "capacity within 10 % (rows where the sender outpaced the link)",
    "loss": "loss within 3 sigma of the binomial noise of both runs (widened by the loss runs' mean length), "
            "or 0.02",
    "delay": "one-way delay p50 (measured, less the clock offset's error under the profile) within 20 % or 15 ms",
    "rtt": "echo round trip p50 within 10 % or 5 ms",
    "bursts": "mean loss run within 3 standard errors (run lengths geometric) or 0.4 packets (rows with 5 or "
              "more loss runs)",
}


def _row(direction: str, size: int, count: int, seconds: float, sends: list[float],
         arrivals: list[tuple[float, int]]) -> dict[str, Any]:
    """A row as the live run reports it, from send times and (arrival time, seq) pairs."""
    first: dict[int, float] = {}
    for t, seq in sorted(arrivals):
        first.setdefault(seq, t)
    got = len(first)
    times = sorted(first.values())
    runs = P.loss_runs(P.ranges(first), count)
    gaps = [b - a for a, b in itertools.pairwise(times)]
    gap = _pct(gaps, 0.5) if gaps else 0.0
    span = times[-1] - times[0] if got > 1 else 0.0
    delays = [first[s] - sends[s] for s in first]
    row: dict[str, Any] = {
        "direction": direction, "size": size, "sent": count, "received": got, "lost": count - got,
        "loss": round((count - got) / count, 4), "loss_runs": len(runs),
        "loss_run_mean": round(statistics.mean(runs), 2) if runs else 0.0, "loss_run_max": max(runs, default=0),
        "seconds": round(seconds, 3), "throughput_Bps": round(count * size / seconds, 1),
        "goodput_Bps": round(got * size / seconds, 1),
        "rx_rate_Bps": round((got - 1) * size / span, 1) if span > 0 else 0.0,
        "capacity_Bps": round(size / gap, 1) if gap > 0 else 0.0,
    }
    if delays:
        row.update({"owd_p50_ms": round(_pct(delays, 0.5) * 1e3, 2), "owd_p95_ms": round(_pct(delays, 0.95) * 1e3, 2),
                    "owd_min_ms": round(min(delays) * 1e3, 2)})
    return row


def _schedule(count: int, interval: float, seed: int) -> list[float]:
    """Send times as a real sender's: on schedule, but each late by up to a millisecond (the OS's
    timers). Without it a pace of exactly twice the link's rate meets every service completion
    at the same instant, and which comes first is decided by rounding."""
    rng = random.Random(seed)
    late = min(0.001, 0.05 * interval)
    return [i * interval + rng.uniform(0.0, late) for i in range(count)]


def uplink_once(profile: Profile, distance: float, size: int, count: int, pace_Bps: float,
                seed: int) -> dict[str, Any]:
    ch = Channel(profile, "up", distance, Impairments(), seed=seed)
    interval = size / pace_Bps
    sends = _schedule(count, interval, seed)
    payload = bytes(size)
    arrivals = [(t, i) for i, s in enumerate(sends) for t, _ in ch.submit(s, payload)]
    return _row("up", size, count, count * interval, sends, arrivals)


def downlink_once(profile: Profile, distance: float, rate_hz: float, count: int, seed: int,
                  size: int = DOWN_SIZE) -> dict[str, Any]:
    ch = Channel(profile, "down", distance, Impairments(), seed=seed)
    sends = _schedule(count, 1 / rate_hz, seed)
    payload = bytes(size)
    arrivals = [(t, i) for i, s in enumerate(sends) for t, _ in ch.submit(s, payload)]
    row = _row("down", size, count, count / rate_hz, sends, arrivals)
    row["rate_hz"] = rate_hz
    return row


def echoes_once(profile: Profile, distance: float, n: int, seed: int, timeout: float = 0.5) -> list[float]:
    """Round trips of n echoes sent one at a time (the next when the answer came, or after
    `timeout`), in seconds; lost ones are left out, as live."""
    up = Channel(profile, "up", distance, Impairments(), seed=seed * 2 + 1)
    down = Channel(profile, "down", distance, Impairments(), seed=seed * 2 + 2)
    req = bytes(ECHO_SIZE)
    t = 0.0
    rtts = []
    for _ in range(n):
        there = up.submit(t, req)
        back = down.submit(there[0][0], req) if there else []
        if back:
            rtts.append(back[0][0] - t)
            t = back[0][0] + 0.001
        else:
            t += timeout
    return rtts


def _median_row(rows: list[dict[str, Any]]) -> dict[str, Any]:
    out = dict(rows[0])
    for k, v in rows[0].items():
        if isinstance(v, int | float) and not isinstance(v, bool) and k not in ("size", "sent", "rate_hz"):
            vals = [r[k] for r in rows if k in r]
            out[k] = round(statistics.median(vals), 4) if isinstance(v, float) else int(statistics.median(vals))
    return out


def replay(profile: Profile, measurement: dict[str, Any], distance: float, seeds: int = SEEDS) -> dict[str, Any]:
    """The measurement's packets through the model: a report of the same shape (median over
    `seeds` seeds per row)."""
    pace = float(measurement["uplink"]["pace_Bps"])
    out: dict[str, Any] = {"profile": profile.name, "distance_m": distance, "seeds": seeds,
                           "latency": None, "uplink": {"pace_Bps": pace, "rows": []},
                           "downlink": {"size": DOWN_SIZE, "rows": []}}
    lat = measurement.get("latency")
    if lat:
        rtts = [r for s in range(seeds) for r in echoes_once(profile, distance, int(lat["echoes"]), 1000 + s)]
        if rtts:
            out["latency"] = {"echoes": len(rtts) // seeds, "rtt_p50_ms": round(_pct(rtts, 0.5) * 1e3, 2),
                              "rtt_p95_ms": round(_pct(rtts, 0.95) * 1e3, 2),
                              "rtt_min_ms": round(min(rtts) * 1e3, 2)}
    for k, row in enumerate(measurement["uplink"]["rows"]):
        n = int(row["sent"])
        runs = [uplink_once(profile, distance, int(row["size"]), n, pace, 10_000 * (k + 1) + s) for s in range(seeds)]
        out["uplink"]["rows"].append(_median_row(runs))
    for k, row in enumerate(measurement["downlink"]["rows"]):
        n = int(row["sent"])
        runs = [downlink_once(profile, distance, float(row["rate_hz"]), n, 20_000 * (k + 1) + s,
                              int(row.get("size", DOWN_SIZE))) for s in range(seeds)]
        out["downlink"]["rows"].append(_median_row(runs))
    return out


def saturated(row: dict[str, Any]) -> bool:
    """Whether the sender outpaced the link in this row (arrivals spaced wider than sends)."""
    cap, offered = row.get("capacity_Bps") or 0.0, row.get("throughput_Bps") or 0.0
    return bool(cap) and cap < 0.9 * offered


def offset_error(profile: Profile, distance: float) -> float:
    """What the NTP-style offset estimate gets wrong on this profile (seconds): half of how much
    longer an echo takes up than down. Measured uplink delays read that much low, downlink ones
    that much high."""
    up, down = profile.up, profile.down
    return ((up.service_time(ECHO_SIZE, distance) + up.latency_s)
            - (down.service_time(ECHO_SIZE, distance) + down.latency_s)) / 2


def true_delay_ms(row: dict[str, Any], error_s: float) -> float | None:
    """A measured row's one-way delay p50 corrected for the clock offset's error."""
    if row.get("owd_p50_ms") is None:
        return None
    sign = 1.0 if row["direction"] == "up" else -1.0
    return float(row["owd_p50_ms"]) + sign * error_s * 1e3


def _within(a: float, b: float, rel: float, absolute: float) -> bool:
    return abs(a - b) <= max(rel * max(abs(a), abs(b)), absolute)


def _check(name: str, what: str, measured: Any, model: Any, ok: bool) -> dict[str, Any]:
    return {"row": name, "figure": what, "measured": measured, "model": model, "ok": bool(ok)}


def compare(measured: dict[str, Any], model: dict[str, Any], profile: Profile, distance: float,
            seeds: int = SEEDS) -> list[dict[str, Any]]:
    """Figure by figure, measured against replayed on `profile`, each with its tolerance's verdict."""
    out = []
    error = offset_error(profile, distance)
    ml, rl = measured.get("latency"), model.get("latency")
    if ml and rl:
        out.append(_check("echo", "rtt_p50_ms", ml["rtt_p50_ms"], rl["rtt_p50_ms"],
                          _within(ml["rtt_p50_ms"], rl["rtt_p50_ms"], 0.10, 5.0)))
    pairs = [(f"up {m['size']} B", m, r) for m, r in zip(measured["uplink"]["rows"], model["uplink"]["rows"],
                                                         strict=True)]
    pairs += [(f"down {m['rate_hz']:g} Hz", m, r) for m, r in zip(measured["downlink"]["rows"],
                                                                 model["downlink"]["rows"], strict=True)]
    for name, m, r in pairs:
        if saturated(m) or saturated(r):
            out.append(_check(name, "capacity_Bps", m["capacity_Bps"], r["capacity_Bps"],
                              _within(m["capacity_Bps"], r["capacity_Bps"], 0.10, 0.0)))
        n = int(m["sent"])
        p = (float(m["loss"]) + float(r["loss"])) / 2
        # bursts of mean length B multiply the variance of a loss count by about 2B - 1; the smaller
        # of the two sides' B, so that a model that drops whole runs cannot widen its own tolerance
        run_mean = min(10.0, max(1.0, min(float(m.get("loss_run_mean") or 1.0), float(r.get("loss_run_mean") or 1.0))))
        inflate = 2 * run_mean - 1
        sigma = math.sqrt(p * (1 - p) / n * (1 + 1 / seeds) * inflate)
        out.append(_check(name, "loss", m["loss"], r["loss"], abs(m["loss"] - r["loss"]) <= max(3 * sigma, 0.02)))
        dm, dr = true_delay_ms(m, error), r.get("owd_p50_ms")
        if dm is not None and dr is not None:
            out.append(_check(name, "owd_p50_ms", round(dm, 2), dr, _within(dm, dr, 0.20, 15.0)))
        runs_m, runs_r = int(m.get("loss_runs") or 0), int(r.get("loss_runs") or 0)
        if min(runs_m, runs_r) >= 5:
            a, b = float(m["loss_run_mean"]), float(r["loss_run_mean"])
            # a geometric run length of mean B has variance B (B - 1)
            se = math.sqrt(a * (a - 1) / runs_m + b * (b - 1) / (runs_r * seeds))
            out.append(_check(name, "loss_run_mean", a, b, abs(a - b) <= max(3 * se, 0.4)))
    return out
