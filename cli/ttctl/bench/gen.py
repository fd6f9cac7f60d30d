"""`ttctl bench gen`: ttctl gen (Python, C++, Java in one run) against the sum of mavgen's
Python3, C++11 and Java runs on the same dialect, whole process against whole process."""

from __future__ import annotations

import json
import os
import tempfile

from .procs import benchmark_dialect, bytecode_note, console_script, machine, median, time_interleaved

FLOOR = 0.5  # issue: at most half the summed mavgen time


def run(dialect: str | None, runs: int, as_json: bool) -> int:
    """Time both; 1 if the ratio misses the floor, else 0. A dialect `ttctl gen` refuses is
    refused here (exit 2): timing a run that fails says nothing."""
    from ..errors import Fail

    dialect = benchmark_dialect(dialect)
    ttctl = console_script("ttctl", "ttctl")
    _check_dialect(ttctl, dialect)
    mavgen = console_script("mavgen.py", "pymavlink.tools.mavgen")
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-gen-") as tmp:
        def out(kind: str) -> str:
            return os.path.join(tmp, kind)

        cmds = {
            "ttctl gen (python,cpp,java)": lambda i: ttctl + ["gen", dialect, "-o", out(f"ttctl{i}")],
            "mavgen Python3": lambda i: mavgen + ["--lang", "Python3", "--wire-protocol", "2.0", "-o",
                                                  out(f"py{i}/x.py"), dialect],
            "mavgen C++11": lambda i: mavgen + ["--lang", "C++11", "--wire-protocol", "2.0", "-o", out(f"cpp{i}"),
                                                dialect],
            "mavgen Java": lambda i: mavgen + ["--lang", "Java", "--wire-protocol", "2.0", "-o", out(f"java{i}"),
                                               dialect],
        }
        try:
            times = time_interleaved(cmds, runs, warmup=1)  # type: ignore[arg-type]
        except RuntimeError as e:
            raise Fail(str(e)) from None
        note = bytecode_note()
    med = {k: median(v) for k, v in times.items()}
    ours = med["ttctl gen (python,cpp,java)"]
    peers = sum(v for k, v in med.items() if k.startswith("mavgen"))
    ratio = ours / peers
    result = {"dialect": dialect, "runs": runs, "median_s": {k: round(v, 3) for k, v in med.items()},
              "mavgen_sum_s": round(peers, 3), "ratio": round(ratio, 3), "floor": FLOOR, "ok": ratio <= FLOOR,
              "machine": machine(), "bytecode_note": note}
    if as_json:
        print(json.dumps(result, indent=2))
        return 0 if result["ok"] else 1
    from rich.console import Console
    from rich.table import Table

    table = Table(title=f"whole-process time on {os.path.basename(dialect)}, {runs} interleaved runs each")
    table.add_column("command")
    table.add_column("median s", justify="right")
    for k, v in med.items():
        table.add_row(k, f"{v:.3f}")
    table.add_row("mavgen, sum of the three", f"{peers:.3f}")
    console = Console()
    console.print(table)
    if note:
        console.print(f"[yellow]note:[/] {note}")
    verdict = "[green]meets[/]" if ratio <= FLOOR else "[red]misses[/]"
    console.print(f"ratio ttctl/mavgen-sum = [bold]{ratio:.2f}[/] ({verdict} the {FLOOR}x floor)")
    return 0 if result["ok"] else 1


def _check_dialect(ttctl: list[str], dialect: str) -> None:
    """Fail (exit 2) unless `ttctl validate` finds no errors in the dialect: gen would refuse it."""
    import subprocess

    from ..errors import Fail

    proc = subprocess.run(ttctl + ["validate", dialect], capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        text = proc.stdout + proc.stderr
        errors = [ln for ln in text.splitlines() if ": error: " in ln]
        first = errors[0] if errors else (text.strip().splitlines() or ["?"])[-1]
        raise Fail(f"{dialect}: ttctl gen refuses this dialect ({len(errors)} error(s); the first: {first}); "
                   f"nothing to time")
