"""`ttctl bench hmd`: what recording VR poses costs, measured on real `ttctl hmd dump` processes.

1. Recording: the synthetic source at 90 Hz (headset) + 2 x 250 Hz (controllers), in real time,
   to a ROS 2 MCAP file. The share of one core is the *marginal* one: CPU seconds of a long run
   minus those of a short run, over the difference in wall time, so that interpreter start-up
   (a fixed cost, reported apart) does not count as recording. Ceiling: 10 % of a core.
2. Replay: a 10-minute MCAP recording (made with --speed 0), replayed with --speed 0 into a
   JSONL file (reading, converting and writing every sample: what a script consuming a recording
   waits for). Ceiling: 10 s. Replaying it into a new MCAP file is reported beside it.
The median of `runs` of each is reported.
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import tempfile
import time
from pathlib import Path
from typing import Any

from ..errors import Fail
from .procs import console_script

CORE_CEILING = 0.10
REPLAY_CEILING_S = 10.0


def _run(args: list[str]) -> tuple[float, float]:
    """(wall s, CPU s) of a `ttctl` process, children included."""
    cmd = console_script("ttctl", "ttctl") + args
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    errtext = proc.stderr.read().decode(errors="replace").strip() if proc.stderr else ""
    if proc.returncode != 0:
        last = errtext.splitlines()[-1] if errtext else ""
        raise Fail(f"ttctl {' '.join(args[:3])} ... failed ({proc.returncode}): {last}", 1)
    return wall, usage.ru_utime + usage.ru_stime


def _record(out: Path, seconds: float) -> tuple[float, float]:
    return _run(["hmd", "dump", "--source", "synthetic", "--rate-hmd", "90", "--rate-controllers", "250",
                 "--duration", str(seconds), "-o", str(out), "--quiet"])


def run(seconds: float, runs: int, replay_minutes: float, as_json: bool) -> int:
    short = 2.0
    if seconds <= short + 1:
        raise Fail(f"--seconds must be above {short + 1:g}")
    shares: list[float] = []
    startup: list[float] = []
    replays: list[float] = []
    remcap: list[float] = []
    sizes: dict[str, float] = {}
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-hmd-") as d:
        work = Path(d)
        for _ in range(runs):
            w1, c1 = _record(work / "short.mcap", short)
            w2, c2 = _record(work / "long.mcap", seconds)
            shares.append(max(0.0, (c2 - c1) / (w2 - w1)))
            startup.append(c1 - short * shares[-1])
        sizes["recording_bytes_per_s"] = (work / "long.mcap").stat().st_size / seconds
        long_rec = work / "ten.mcap"
        _run(["hmd", "dump", "--source", "synthetic", "--duration", str(replay_minutes * 60), "--speed", "0",
              "-o", str(long_rec), "--quiet"])
        sizes["replayed_file_bytes"] = long_rec.stat().st_size
        for _ in range(runs):
            for into, times in (("again.jsonl", replays), ("again.mcap", remcap)):
                wall, _cpu = _run(["hmd", "dump", "--source", "replay", str(long_rec), "--speed", "0",
                                   "-o", str(work / into), "--quiet"])
                times.append(wall)
    share = statistics.median(shares)
    replay = statistics.median(replays)
    ceiling = REPLAY_CEILING_S * replay_minutes / 10.0
    checks: list[dict[str, Any]] = [
        {"check": "recording to MCAP, share of one core", "value": round(share, 4), "ceiling": CORE_CEILING,
         "ok": share < CORE_CEILING},
        {"check": f"replaying {replay_minutes:g} min of MCAP into JSONL (--speed 0), s", "value": round(replay, 2),
         "ceiling": ceiling, "ok": replay < ceiling},
    ]
    report: dict[str, Any] = {"runs": runs, "record_seconds": seconds, "core_shares": [round(s, 4) for s in shares],
                              "startup_cpu_s": round(statistics.median(startup), 3),
                              "replay_s": [round(r, 2) for r in replays],
                              "replay_into_mcap_s": [round(r, 2) for r in remcap], **sizes, "checks": checks}
    if as_json:
        print(json.dumps(report, indent=2))
    else:
        from rich.console import Console
        from rich.table import Table

        t = Table(title=f"ttctl hmd dump: synthetic 90 + 2 x 250 Hz, medians of {runs}")
        for col in ("measure", "median", "ceiling", "ok"):
            t.add_column(col, justify="left" if col == "measure" else "right")
        for ch in checks:
            ok = "[green]yes[/]" if ch["ok"] else "[red]no[/]"
            t.add_row(str(ch["check"]), f"{ch['value']:g}", f"{ch['ceiling']:g}", ok)
        c = Console()
        c.print(t)
        c.print(f"start-up (import, once per process): {report['startup_cpu_s']:.2f} CPU s; "
                f"MCAP written: {sizes['recording_bytes_per_s'] / 1024:.0f} KiB/s; the same replay into MCAP: "
                f"{statistics.median(remcap):.1f} s")
    return 0 if all(ch["ok"] for ch in checks) else 1
