"""`ttctl bench link`: the thesis's field measurement (ch. 3.9) repeated on the link model.

Uplink (tablet to drone): packets of 1, 10, 20, ..., 100 bytes, 100 per step, each handed to the
SDK as soon as the completion callback of the one before fired (one packet in flight), at 10,
50, 100, 150 and 200 m. Throughput is what the tablet can count, as in the thesis: bytes whose
callback fired per second from the first send to the last callback; goodput counts only the
bytes that arrived. Lost = packets that never arrived, out of 100.

Downlink (drone to tablet): the onboard send loop at 10, 20, ..., 100 Hz hands a 100-byte packet
to the SDK on every iteration, 100 iterations, with no feedback (what the SDK cannot queue it
drops), at 10 and 200 m. Lost = packets out of 100 that never arrived (queue overflow or the
radio); throughput = what the tablet receives, (received - 1) x size / (last arrival - first
arrival), the rate between the first and last packet it sees.

Each step is its own Channel with a fixed seed, so the tables are reproducible. `facts` holds the
statements the thesis and DJI's SDK documentation make about the link, evaluated on the numbers.

Sources: Matej Hrlec, "Wireless protocol and virtual reality support for controlling unmanned
aerial vehicles", master's thesis, University of Ljubljana, Faculty of Computer and Information
Science, chapters 3.9-3.10 (the measurements); DJI Mobile SDK and Onboard SDK documentation (Data
Transparent Transmission: 100-byte packets, about 1 KB/s up and 8 KB/s down).
"""

from __future__ import annotations

import json
import statistics
from typing import Any

from ..link.model import Channel, Impairments, Profile

UP_SIZES = (1, *range(10, 101, 10))
UP_DISTANCES = (10.0, 50.0, 100.0, 150.0, 200.0)
DOWN_RATES = tuple(range(10, 101, 10))
DOWN_DISTANCES = (10.0, 200.0)
DOWN_SIZE = 100
PACKETS = 100


def uplink_step(profile: Profile, distance: float, size: int, seed: int, packets: int = PACKETS) -> dict[str, Any]:
    ch = Channel(profile, "up", distance, Impairments(), seed=seed)
    payload = bytes([0x55]) * size
    t = 0.0
    arrived = 0
    for _ in range(packets):
        arrived += len(ch.submit(t, payload))
        t = max(t, ch.free_at())  # the completion callback: send the next one
    seconds = t
    return {"distance_m": distance, "size": size, "sent": packets, "lost": packets - arrived,
            "seconds": round(seconds, 3), "throughput_Bps": round(packets * size / seconds, 1),
            "goodput_Bps": round(arrived * size / seconds, 1)}


def downlink_step(profile: Profile, distance: float, rate_hz: float, seed: int, packets: int = PACKETS,
                  size: int = DOWN_SIZE) -> dict[str, Any]:
    ch = Channel(profile, "down", distance, Impairments(), seed=seed)
    payload = bytes([0x55]) * size
    arrivals: list[float] = []
    for i in range(packets):
        arrivals.extend(t for t, _ in ch.submit(i / rate_hz, payload))
    arrivals.sort()
    n = len(arrivals)
    span = arrivals[-1] - arrivals[0] if n > 1 else 0.0
    thr = (n - 1) * size / span if span > 0 else 0.0
    return {"distance_m": distance, "rate_hz": rate_hz, "size": size, "sent": packets, "lost": packets - n,
            "overflow": ch.stats.overflow, "radio_lost": ch.stats.lost, "throughput_Bps": round(thr, 1)}


def sizes_for(mtu: int) -> tuple[int, ...]:
    """The thesis's uplink sizes (1, 10, 20, ... bytes) up to the link's packet size."""
    return tuple(sorted({1, *range(10, mtu + 1, 10), mtu}))


def measure(profile: Profile, seed: int = 1) -> dict[str, Any]:
    """The report: both tables and the facts checked on them. Packet sizes follow the profile's
    (the thesis's 1..100 bytes on DTT; up to 128 on the Payload SDK channel)."""
    up_rows = []
    k = 0
    sizes = sizes_for(profile.mtu)
    for d in UP_DISTANCES:
        for s in sizes:
            k += 1
            up_rows.append(uplink_step(profile, d, s, seed * 10_000 + k))
    down_rows = []
    for d in DOWN_DISTANCES:
        for r in DOWN_RATES:
            k += 1
            down_rows.append(downlink_step(profile, d, r, seed * 10_000 + k, size=profile.mtu))
    report: dict[str, Any] = {
        "profile": profile.name,
        "seed": seed,
        "uplink": {"advertised_Bps": profile.up.advertised_Bps, "distances_m": list(UP_DISTANCES),
                   "sizes": list(sizes), "packets": PACKETS, "rows": up_rows},
        "downlink": {"advertised_Bps": profile.down.advertised_Bps, "distances_m": list(DOWN_DISTANCES),
                     "rates_hz": list(DOWN_RATES), "size": profile.mtu, "packets": PACKETS, "rows": down_rows},
    }
    report["facts"] = facts(report)
    return report


def _up(report: dict[str, Any], distance: float, size: int | None = None) -> list[dict[str, Any]]:
    return [r for r in report["uplink"]["rows"] if r["distance_m"] == distance and (size is None or r["size"] == size)]


def _down(report: dict[str, Any], distance: float, rate: float | None = None) -> list[dict[str, Any]]:
    return [r for r in report["downlink"]["rows"]
            if r["distance_m"] == distance and (rate is None or r["rate_hz"] == rate)]


def _fact(text: str, value: Any, expect: str, ok: bool) -> dict[str, Any]:
    return {"fact": text, "value": value, "expect": expect, "ok": bool(ok)}


def facts(report: dict[str, Any]) -> list[dict[str, Any]]:
    """What the thesis measured and DJI documents about the link, evaluated on a report."""
    out = []
    up = report["uplink"]
    dists, sizes = up["distances_m"], up["sizes"]
    near, far = min(dists), max(dists)
    big = max(sizes)
    adv = up["advertised_Bps"] or 0
    best = max(r["throughput_Bps"] for r in up["rows"])
    if adv:
        frac = best / adv
        out.append(_fact("uplink: at best about half the advertised rate", round(frac, 3),
                         "0.4..0.6 of advertised", 0.4 <= frac <= 0.6))
    ratio = _up(report, near, big)[0]["throughput_Bps"] / max(_up(report, far, big)[0]["throughput_Bps"], 1e-9)
    out.append(_fact(f"uplink: throughput falls about 4x from {near:g} m to {far:g} m ({big}-byte packets)",
                     round(ratio, 2), "3..5", 3.0 <= ratio <= 5.0))
    close = [r["lost"] for r in up["rows"] if r["distance_m"] < far]
    out.append(_fact(f"uplink: very few of 100 lost up to {max(d for d in dists if d < far):g} m",
                     {"mean": round(statistics.mean(close), 2), "max": max(close)}, "mean <= 3, max <= 8",
                     statistics.mean(close) <= 3 and max(close) <= 8))
    far_lost = [r["lost"] for r in _up(report, far)]
    out.append(_fact(f"uplink: reliability plummets at {far:g} m", round(statistics.mean(far_lost), 1),
                     "mean lost >= 25 of 100", statistics.mean(far_lost) >= 25))
    spread = []
    for d in dists:
        rows = _up(report, d)
        small = [r["lost"] for r in rows if r["size"] <= 40]
        large = [r["lost"] for r in rows if r["size"] >= 60]
        p = statistics.mean(r["lost"] for r in rows) / 100
        sigma = (p * (1 - p) * 100 * (1 / len(small) + 1 / len(large))) ** 0.5  # binomial noise of the difference
        diff = statistics.mean(small) - statistics.mean(large)
        spread.append((d, round(diff, 2), abs(diff) <= max(3 * sigma, 1.5)))
    out.append(_fact("uplink: packet size has little effect on loss",
                     {f"{d:g} m": diff for d, diff, _ in spread},
                     "mean lost (1..40 B) - mean lost (60..100 B) within 3 sigma of binomial noise",
                     all(ok for _, _, ok in spread)))
    down = report["downlink"]
    rates = down["rates_hz"]
    top = max(rates)
    for d in down["distances_m"]:
        lost_top = _down(report, d, top)[0]["lost"]
        out.append(_fact(f"downlink: about a third lost at {top:g} Hz with {down['size']}-byte packets ({d:g} m)",
                         lost_top, "25..42 of 100", 25 <= lost_top <= 42))
        rows = _down(report, d)
        low = [r for r in rows if r["rate_hz"] <= top / 2]
        more_loss = all(lost_top > r["lost"] for r in low)
        out.append(_fact(f"downlink: higher rate, more loss ({d:g} m)",
                         {f"{r['rate_hz']:g} Hz": r["lost"] for r in rows},
                         f"lost at {top:g} Hz > at <= {top / 2:g} Hz", more_loss))
        thr_top = _down(report, d, top)[0]["throughput_Bps"]
        best_thr = max(r["throughput_Bps"] for r in rows)
        ok = thr_top >= 0.95 * best_thr and all(thr_top > 1.1 * r["throughput_Bps"] for r in low)
        out.append(_fact(f"downlink: but still more throughput at {top:g} Hz ({d:g} m)", thr_top,
                         f">= 0.95 x best ({best_thr:g}) and > 1.1 x any rate <= {top / 2:g} Hz", ok))
    d0, d1 = min(down["distances_m"]), max(down["distances_m"])
    worst = 0.0
    worst_lost = 0
    for r in rates:
        a, b = _down(report, d0, r)[0], _down(report, d1, r)[0]
        worst = max(worst, abs(a["throughput_Bps"] - b["throughput_Bps"]) / max(a["throughput_Bps"], 1e-9))
        worst_lost = max(worst_lost, abs(a["lost"] - b["lost"]))
    out.append(_fact(f"downlink: distance hardly matters ({d0:g} m vs {d1:g} m)",
                     {"throughput_rel_diff_max": round(worst, 3), "lost_diff_max": worst_lost},
                     "throughput within 10%, lost within 10 packets", worst <= 0.10 and worst_lost <= 10))
    return out


def run(profile: Profile, as_json: bool, plot: str | None, seed: int = 1) -> dict[str, Any]:
    if plot:
        from .plots import require_matplotlib

        require_matplotlib(plot)
    report = measure(profile, seed)
    if plot:
        from .plots import plot_link

        plot_link(report, plot)
    if as_json:
        print(json.dumps(report, indent=2))
    else:
        _print_tables(report)
    return report


def _print_tables(report: dict[str, Any]) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console()
    up = report["uplink"]
    t = Table(title=f"uplink over {report['profile']}: {up['packets']} packets per step, one in flight "
                    f"(throughput B/s as the tablet counts it / lost of {up['packets']})")
    t.add_column("size B", justify="right")
    for d in up["distances_m"]:
        t.add_column(f"{d:g} m", justify="right")
    for s in up["sizes"]:
        cells = []
        for d in up["distances_m"]:
            r = _up(report, d, s)[0]
            cells.append(f"{r['throughput_Bps']:.0f} / {r['lost']}")
        t.add_row(str(s), *cells)
    console.print(t)
    down = report["downlink"]
    dt = Table(title=f"downlink over {report['profile']}: {down['size']}-byte packets, {down['packets']} per rate, "
                     f"no feedback (received B/s / lost of {down['packets']})")
    dt.add_column("loop Hz", justify="right")
    for d in down["distances_m"]:
        dt.add_column(f"{d:g} m", justify="right")
    for rate in down["rates_hz"]:
        cells = []
        for d in down["distances_m"]:
            r = _down(report, d, rate)[0]
            cells.append(f"{r['throughput_Bps']:.0f} / {r['lost']}")
        dt.add_row(f"{rate:g}", *cells)
    console.print(dt)
    ft = Table(title="facts of the thesis and DJI's docs on this model" + (
        "" if report["profile"] == "m100" else " (they describe the M100's DTT: another link may differ)"))
    for col in ("fact", "value", "expected", "ok"):
        ft.add_column(col, overflow="fold")  # wrapped, never cut with an ellipsis at 80 columns
    for f in report["facts"]:
        ft.add_row(f["fact"], _cell(f["value"]), f["expect"], "[green]yes[/]" if f["ok"] else "[red]no[/]")
    console.print(ft)


def _cell(value: Any) -> str:
    """A fact's value for the table: `key: value, ...` for several (in words, so it wraps)."""
    if isinstance(value, dict):
        return ", ".join(f"{str(k).replace('_', ' ')}: {v}" for k, v in value.items())
    return json.dumps(value)
