"""`ttctl bench dialect`: what `--dialect` adds to a link command's start, whole process.

The command timed is `ttctl send-file` of a file that does not exist, which loads the dialect's
bindings and stops at the missing file (exit 2 with "No such file", checked on every run): all
start-up, no link. Three ways, interleaved: ttctl's shipped dialect (no --dialect), the user's
dialect with its bindings cached (warm), and the same with an empty cache each run (cold: the
dialect is validated and its Python generated). For scale, `ttctl gen DIALECT --lang python`
runs beside them. Python may write and read byte-code for all of them alike (the shipped
package's too), so that the comparison is of ttctl, not of the interpreter's settings.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile

from .procs import console_script, installed_env, machine, median, run_once

FLOOR_MS = 50.0  # issue: a warm start adds at most 50 ms


def example_dialect() -> str:
    from ..resources import data_dir

    return str(data_dir("dialects") / "examples" / "robolab.xml")


def run(dialect: str | None, runs: int, as_json: bool) -> None:
    from ..errors import Fail

    dialect = os.path.abspath(dialect or example_dialect())
    if not os.path.isfile(dialect):
        raise Fail(f"{dialect}: no such file")
    ttctl = console_script("ttctl", "ttctl")
    env = installed_env(drop=("TTCTL_DIALECT",))
    missing = "ttctl-bench-no-such-file.bin"
    send = [*ttctl, "send-file", missing, "--to", "udpout:127.0.0.1:9"]
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-dialect-") as tmp:
        warm_env = {**env, "TTCTL_CACHE_DIR": os.path.join(tmp, "warm")}

        def cold_env(i: int) -> dict[str, str]:
            folder = os.path.join(tmp, f"cold{i}")
            shutil.rmtree(folder, ignore_errors=True)
            return {**env, "TTCTL_CACHE_DIR": folder}

        cases = {
            "shipped ttapi (no --dialect)": lambda i: (send, env, (2, "No such file")),
            "--dialect, warm cache": lambda i: ([*send, "--dialect", dialect], warm_env, (2, "No such file")),
            "--dialect, cold cache": lambda i: ([*send, "--dialect", dialect], cold_env(i), (2, "No such file")),
            "ttctl gen --lang python": lambda i: ([*ttctl, "gen", dialect, "--lang", "python", "-o",
                                                   os.path.join(tmp, f"gen{i}")], env, None),
        }
        times: dict[str, list[float]] = {k: [] for k in cases}
        try:
            for i in range(-2, runs):  # two untimed rounds: byte-code written, the warm cache filled
                for key, case in cases.items():
                    cmd, e, expect = case(i)
                    t = run_once(cmd, cwd=tmp, env=e, expect=expect)
                    if i >= 0:
                        times[key].append(t)
        except RuntimeError as e:
            raise Fail(str(e)) from None
    med = {k: median(v) for k, v in times.items()}
    base = med["shipped ttapi (no --dialect)"]
    warm_ms = 1000 * (med["--dialect, warm cache"] - base)
    cold_ms = 1000 * (med["--dialect, cold cache"] - base)
    result = {"dialect": dialect, "runs": runs, "median_s": {k: round(v, 3) for k, v in med.items()},
              "warm_adds_ms": round(warm_ms, 1), "cold_adds_ms": round(cold_ms, 1), "floor_ms": FLOOR_MS,
              "ok": warm_ms <= FLOOR_MS, "machine": machine()}
    if as_json:
        print(json.dumps(result, indent=2))
        return
    from rich.console import Console
    from rich.table import Table

    table = Table(title=f"whole-process start of send-file with {os.path.basename(dialect)}, {runs} interleaved "
                        "runs each")
    table.add_column("command")
    table.add_column("median s", justify="right")
    for k, v in med.items():
        table.add_row(k, f"{v:.3f}")
    console = Console()
    console.print(table)
    verdict = "[green]meets[/]" if warm_ms <= FLOOR_MS else "[red]misses[/]"
    console.print(f"a warm --dialect adds [bold]{warm_ms:.0f} ms[/] ({verdict} the {FLOOR_MS:.0f} ms floor); "
                  f"a cold one {cold_ms:.0f} ms (gen of Python alone: {1000 * med['ttctl gen --lang python']:.0f} ms)")
