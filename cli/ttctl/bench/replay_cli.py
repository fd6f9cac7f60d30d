"""`ttctl bench link --like MEASUREMENT`: a measurement replayed on a profile, printed and judged."""

from __future__ import annotations

import json
from typing import Any

from ..errors import Fail


def run_like(path: str, profile: str | None, profile_file: str | None, distance: float | None,
             as_json: bool) -> int:
    from ..link.model import ProfileError, load_profile
    from . import replay as R
    from .fit import load_measurement

    try:
        prof = load_profile(profile, profile_file)
    except ProfileError as e:
        raise Fail(str(e)) from None
    if distance is not None and not distance >= 0:
        raise Fail("--distance must be a number of metres >= 0")
    m = load_measurement(path)
    at = distance if distance is not None else (m.distance if m.distance is not None else 10.0)
    model = R.replay(prof, m.report, at)
    checks = R.compare(m.report, model, prof, at)
    bad = [c for c in checks if not c["ok"]]
    if as_json:
        print(json.dumps({"measurement": path, "profile": prof.name, "distance_m": at, "model": model,
                          "checks": checks, "tolerances": R.TOLERANCES, "ok": not bad}, indent=2))
    else:
        _print(path, prof.name, at, checks)
    return 1 if bad else 0


def _print(path: str, name: str, at: float, checks: list[dict[str, Any]]) -> None:
    from rich.console import Console
    from rich.table import Table

    from .replay import SEEDS, TOLERANCES

    console = Console()
    t = Table(title=f"{path} replayed on profile {name!r} at {at:g} m (median of {SEEDS} seeds)")
    for col in ("row", "figure", "measured", "model", "ok"):
        t.add_column(col, justify="right" if col in ("measured", "model") else "left")
    for c in checks:
        t.add_row(c["row"], c["figure"], f"{c['measured']:g}", f"{c['model']:g}",
                  "[green]yes[/]" if c["ok"] else "[red]no[/]")
    console.print(t)
    ok = sum(c["ok"] for c in checks)
    verdict = "reproduces the measurement" if ok == len(checks) else "does not reproduce the measurement"
    console.print(f"profile {name!r} {verdict}: {ok} of {len(checks)} figures within tolerance", highlight=False)
    console.print("tolerances: " + "; ".join(TOLERANCES.values()), highlight=False)
