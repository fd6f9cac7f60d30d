"""`ttctl bench validate`: ttctl validate vs mavgen --lang Python3 on the same dialect."""

from __future__ import annotations

import json
import os
import tempfile

from .procs import Command, benchmark_dialect, bytecode_note, console_script, machine, median, time_interleaved

FLOOR = 0.75  # at most 0.75x mavgen's time on a real dialect (all.xml)
SYNTHETIC_FLOOR = 3.0  # at most 3x on a made-up dialect of tens of thousands of messages: time grows linearly
# what --synthetic makes (bench/synthetic.py): one file, no <include> (common.xml is not in it)
SYNTHETIC_KIND = "standalone (no common.xml)"


def run(dialect: str | None, runs: int, as_json: bool, synthetic: int | None = None) -> int:
    """Time both; 1 if the ratio misses the floor, else 0."""
    from ..errors import Fail

    if synthetic is not None and dialect is not None:
        raise Fail("give a DIALECT or --synthetic N, not both")
    floor = FLOOR if synthetic is None else SYNTHETIC_FLOOR
    warmup = 2 if synthetic is None or synthetic <= 10_000 else 1  # a run of 60,000 messages takes mavgen 12 s
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-") as tmp:
        if synthetic is not None:
            from pathlib import Path

            from .synthetic import synthetic_dialect

            dialect = str(synthetic_dialect(synthetic, Path(tmp) / f"synthetic{synthetic}.xml"))
        else:
            dialect = benchmark_dialect(dialect)
        cmds: dict[str, Command] = {
            "ttctl validate": console_script("ttctl", "ttctl") + ["validate", dialect],
            "mavgen Python3": console_script("mavgen.py", "pymavlink.tools.mavgen")
            + ["--lang", "Python3", "--wire-protocol", "2.0", "-o", os.path.join(tmp, "out"), dialect],
        }
        try:
            times = time_interleaved(cmds, runs, warmup=warmup)
        except RuntimeError as e:
            raise Fail(str(e)) from None
        note = bytecode_note()
    med = {k: median(v) for k, v in times.items()}
    ratio = med["ttctl validate"] / med["mavgen Python3"]
    result = {
        "dialect": f"synthetic, {synthetic} messages, {SYNTHETIC_KIND}" if synthetic is not None else dialect,
        "runs": runs,
        "median_s": {k: round(v, 4) for k, v in med.items()},
        "min_s": {k: round(min(v), 4) for k, v in times.items()},
        "ratio": round(ratio, 3),
        "floor": floor,
        "ok": ratio <= floor,
        "machine": machine(), "bytecode_note": note,
    }
    if as_json:
        print(json.dumps(result, indent=2))
        return 0 if result["ok"] else 1
    from rich.console import Console
    from rich.table import Table

    name = f"a synthetic {SYNTHETIC_KIND} dialect of {synthetic} messages" if synthetic is not None \
        else os.path.basename(dialect)
    table = Table(title=f"whole-process time on {name}, {runs} interleaved runs each")
    table.add_column("command")
    table.add_column("median s", justify="right")
    table.add_column("min s", justify="right")
    for k in cmds:
        table.add_row(k, f"{med[k]:.3f}", f"{min(times[k]):.3f}")
    console = Console()
    console.print(table)
    if note:
        console.print(f"[yellow]note:[/] {note}")
    verdict = "[green]meets[/]" if ratio <= floor else "[red]misses[/]"
    console.print(f"ratio ttctl/mavgen = [bold]{ratio:.2f}[/] ({verdict} the {floor}x floor)")
    return 0 if result["ok"] else 1
