"""`ttctl bench ends`: what the onboard end costs, measured on the real node in this process.

Idle: default telemetry rates on both links, nobody talking to it: the share of one core it
uses. Loaded: telemetry at 50 Hz on the ground-station link and to the tablet, while a
`ttctl send-file --from` process fetches a large served file at the link's full rate (the LAN
profile's 1 MB/s: the M100 downlink's 6.7 KB/s could not carry 50 Hz telemetry and a file):
the event loop's lag (how late a 10 ms timer fires), p50/p99/max, and the core share. Floors: lag
p99 below 5 ms loaded, under 3 % of a core idle.
"""

from __future__ import annotations

import asyncio
import json
import os
import socket
import statistics
import subprocess
import tempfile
import time
from pathlib import Path
from typing import Any

from .procs import console_script

LAG_FLOOR_MS = 5.0
IDLE_FLOOR = 0.03


def _port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


async def _phase(seconds: float, loaded: bool, work: Path) -> dict[str, Any]:
    from ..ends.onboard.node import OnboardConfig, OnboardNode
    from ..link.transport import parse_spec

    sink = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)  # a ground station that only listens
    sink.bind(("127.0.0.1", 0))
    sink.setblocking(False)
    dtt = _port()
    serve = work / "served"
    serve.mkdir(exist_ok=True)
    (serve / "big.bin").write_bytes(os.urandom(64 << 20))  # more than the phase can move
    lan = 1_000_000.0
    gcs = parse_spec(f"udpout:127.0.0.1:{sink.getsockname()[1]}")
    cfg = OnboardConfig(dtt=parse_spec(f"udpin:127.0.0.1:{dtt}"), gcs=[gcs], serve=serve,
                        rate_Bps=lan if loaded else None, telemetry_hz=50.0 if loaded else 2.0)
    from .shipped import bindings

    node = OnboardNode(bindings(), cfg)
    await node.start()
    if loaded:
        node.gcs.rates.set_all(50.0)
    stop = asyncio.Event()
    runner = asyncio.get_running_loop().create_task(node.run(stop))
    fetch = None
    if loaded:
        fetch = subprocess.Popen(console_script("ttctl", "ttctl") + [
            "send-file", "big.bin", "--from", f"udpout:127.0.0.1:{dtt}", "--dir", str(work / "got"), "--profile",
            "lan", "--timeout", str(int(seconds) + 30)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    await asyncio.sleep(1.0)  # settle
    lags: list[float] = []
    loop = asyncio.get_running_loop()
    cpu0, wall0 = time.process_time(), time.monotonic()
    sent0 = node.endpoint.scheduler.bytes if node.endpoint is not None else 0
    end = wall0 + seconds
    # idle: nothing else runs in this process (a probe waking every 10 ms would cost more than
    # the node); loaded: how late a 10 ms timer fires is the lag every handler sees
    period = 0.01 if loaded else 1.0
    while time.monotonic() < end:
        t = loop.time()
        await asyncio.sleep(period)
        lags.append(max(0.0, loop.time() - t - period) * 1000)
        while True:
            try:
                sink.recv(4096)
            except (BlockingIOError, OSError):
                break
    cpu, wall = time.process_time() - cpu0, time.monotonic() - wall0
    dtt_bytes = (node.endpoint.scheduler.bytes if node.endpoint is not None else 0) - sent0
    stop.set()
    await runner
    await node.close()
    sink.close()
    if fetch is not None:
        fetch.kill()
        fetch.wait()
    lags.sort()
    return {"phase": "loaded" if loaded else "idle", "seconds": round(wall, 1), "core_share": round(cpu / wall, 4),
            "lag_p50_ms": round(statistics.median(lags), 2), "lag_p99_ms": round(lags[int(0.99 * (len(lags) - 1))], 2),
            "lag_max_ms": round(lags[-1], 2), "dtt_Bps": round(dtt_bytes / wall, 1)}


def run(seconds: float, as_json: bool) -> int:
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-ends-") as d:
        idle = asyncio.run(_phase(seconds, False, Path(d)))
        loaded = asyncio.run(_phase(seconds, True, Path(d)))
    checks = [{"check": "idle core share", "value": idle["core_share"], "ceiling": IDLE_FLOOR,
               "ok": idle["core_share"] < IDLE_FLOOR},
              {"check": "loaded lag p99 ms", "value": loaded["lag_p99_ms"], "ceiling": LAG_FLOOR_MS,
               "ok": loaded["lag_p99_ms"] < LAG_FLOOR_MS}]
    report = {"phases": [idle, loaded], "checks": checks}
    if as_json:
        print(json.dumps(report, indent=2))
    else:
        from rich.console import Console
        from rich.table import Table

        t = Table(title=f"the onboard end on one core, {seconds:g} s per phase")
        for col in ("phase", "core share", "lag p50 ms", "lag p99 ms", "lag max ms", "DTT out B/s"):
            t.add_column(col, justify="left" if col == "phase" else "right")
        for p in (idle, loaded):
            t.add_row(p["phase"], f"{p['core_share']:.1%}", f"{p['lag_p50_ms']:.2f}", f"{p['lag_p99_ms']:.2f}",
                      f"{p['lag_max_ms']:.2f}", f"{p['dtt_Bps']:.0f}")
        c = Console()
        c.print(t)
        for ch in checks:
            verdict = "[green]meets[/]" if ch["ok"] else "[red]misses[/]"
            c.print(f"{ch['check']}: {ch['value']} ({verdict} the ceiling {ch['ceiling']})")
    return 0 if all(ch["ok"] for ch in checks) else 1
