"""`ttctl link fit`: check the inputs, fit (ttctl.bench.fit), write the profile, print the fit."""

from __future__ import annotations

import json
import os
import re
from typing import Any

from ..errors import Fail

_NAME = re.compile(r"[A-Za-z0-9_-]{1,64}")


def fit_command(paths: list[str], output: str, name: str | None, base: str, as_json: bool,
                force: bool = False) -> int:
    from ..bench import fit as F
    from ..bench.plots import write_atomically
    from ..safeio import output_problem

    if not output.endswith(".toml"):
        raise Fail(f"-o {output}: the name must end in .toml (a link profile)")
    problem = output_problem(output)
    if problem:
        raise Fail(problem)
    if name is None:
        name = re.sub(r"[^A-Za-z0-9_-]", "_", os.path.basename(output)[:-len(".toml")])[:64] or "fitted"
    if not _NAME.fullmatch(name):
        raise Fail(f"--name {name!r}: a profile name is 1..64 letters, digits, '_' or '-'")
    if os.path.abspath(output) in {os.path.abspath(p) for p in paths}:
        raise Fail(f"-o {output} is one of the measurements: it would be overwritten")
    if not force and os.path.lexists(output):  # a hand-edited profile is not replaced by accident
        raise Fail(f"-o {output} exists: --force replaces it")
    base_prof = F.base_profile(base)
    ms = [F.load_measurement(p) for p in paths]
    result = F.fit(ms, base_prof, name)
    text = F.to_toml(result, [os.path.basename(p) for p in paths])
    try:
        write_atomically(output, lambda fh: fh.write(text.encode("utf-8")))
    except OSError as e:
        raise Fail(f"cannot write {output}: {e.strerror or e}") from None
    if as_json:
        import dataclasses

        print(json.dumps({"output": output, "profile": dataclasses.asdict(result.profile), "notes": result.notes,
                          "residuals": result.residuals}, indent=2))
    else:
        _print(result, output)
    return 0


def _print(result: Any, output: str) -> None:
    from rich.console import Console
    from rich.table import Table

    from ..bench.replay import SEEDS, TOLERANCES

    console = Console()
    p = result.profile
    t = Table(title=f"profile {p.name!r} (written to {output})")
    for col in ("", "rate B/s at m", "loss at m", "loss model", "buffer", "latency ms", "pacing"):
        t.add_column(col, overflow="fold")
    for d in ("up", "down"):
        dp = p.direction(d)
        model = f"burst, mean {dp.burst_mean:g}" if dp.loss_model == "burst" else "random"
        pacing = f"{dp.pacing_bytes} B / {dp.pacing_interval_s * 1e3:g} ms" if dp.pacing_bytes else "-"
        t.add_row(d, ", ".join(f"{v:g} @ {m:g}" for m, v in dp.rate_Bps),
                  ", ".join(f"{v:g} @ {m:g}" for m, v in dp.loss), model, str(dp.queue_packets),
                  f"{dp.latency_s * 1e3:g}", pacing)
    console.print(t)
    for n in result.notes:
        console.print(f"  {n}", highlight=False)
    r = Table(title=f"residuals: each measurement replayed on the fitted profile (median of {SEEDS} seeds)")
    for col in ("file", "row", "figure", "measured", "model", "ok"):
        r.add_column(col, overflow="fold")
    for row in result.residuals:
        r.add_row(os.path.basename(row["file"]), row["row"], row["figure"], f"{row['measured']:g}",
                  f"{row['model']:g}", "[green]yes[/]" if row["ok"] else "[red]no[/]")
    console.print(r)
    ok = sum(x["ok"] for x in result.residuals)
    console.print(f"{ok} of {len(result.residuals)} figures within tolerance; tolerances: "
                  + "; ".join(TOLERANCES.values()), highlight=False)
