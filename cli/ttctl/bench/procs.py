"""Whole-process timing: commands run interleaved, so machine noise hits all of them alike."""

from __future__ import annotations

import os
import shutil
import statistics
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path


def benchmark_dialect(dialect: str | None) -> str:
    """The dialect given, or pymavlink's all.xml (353 messages in 17 files); Fail if missing."""
    from ..dialect.source import pymavlink_dialects_dir
    from ..errors import Fail

    if dialect is None:
        base = pymavlink_dialects_dir()
        if base is None:
            raise Fail("pymavlink's dialects not found; pass a dialect file")
        dialect = os.path.join(base, "all.xml")
    if not os.path.isfile(dialect):
        raise Fail(f"{dialect}: no such file")
    return dialect


def console_script(name: str, module: str) -> list[str]:
    """The console script `name` next to this interpreter, else `python -m module`."""
    here = Path(sys.executable).with_name(name)
    if here.exists():
        return [str(here)]
    found = shutil.which(name)
    return [found] if found else [sys.executable, "-m", module]


def run_once(cmd: list[str], cwd: str | None = None, env: dict[str, str] | None = None,
             expect: tuple[int, str] | None = None) -> float:
    """Seconds the command took. Exit 0 or 1 (validate's errors) is success, anything else a
    RuntimeError; `expect` (status, words on stderr) names the one outcome accepted instead."""
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, check=False, env=env)
    elapsed = time.perf_counter() - t0
    if expect is not None:
        text = proc.stderr.decode(errors="replace")
        if proc.returncode != expect[0] or expect[1] not in text:
            last = text.strip().splitlines()
            raise RuntimeError(f"{' '.join(cmd[:3])} ... ended {proc.returncode} ({last[-1] if last else ''}), "
                               f"not {expect[0]} with {expect[1]!r}")
        return elapsed
    if proc.returncode not in (0, 1):  # validate exits 1 on errors; anything else is a failure
        err = proc.stderr.decode(errors="replace").strip().splitlines()
        raise RuntimeError(f"{' '.join(cmd[:3])} ... failed ({proc.returncode}): {err[-1] if err else ''}")
    return elapsed


Command = list[str] | Callable[[int], list[str]]


def time_interleaved(cmds: dict[str, Command], runs: int, warmup: int = 2,
                     cwd: str | None = None) -> dict[str, list[float]]:
    """Run each command `warmup` times untimed, then `runs` times, round-robin, in the
    environment of `installed_env`. A command may be a function of the run number (e.g. to
    write into a fresh directory each time)."""
    env = installed_env()

    def at(cmd: Command, i: int) -> list[str]:
        return cmd(i) if callable(cmd) else cmd

    for w in range(warmup):
        for cmd in cmds.values():
            run_once(at(cmd, -1 - w), cwd, env)
    times: dict[str, list[float]] = {k: [] for k in cmds}
    for i in range(runs):
        for key, cmd in cmds.items():
            times[key].append(run_once(at(cmd, i), cwd, env))
    return times


def installed_env(drop: tuple[str, ...] = ()) -> dict[str, str]:
    """The environment for timing Python tools as installed: without PYTHONDONTWRITEBYTECODE.
    pip byte-compiles what it installs (mavgen's pymavlink), while an editable install writes
    its byte-code on first use; under PYTHONDONTWRITEBYTECODE ttctl's own modules would be
    compiled from source on every run and mavgen's not, which times the compiler, not the tools.
    The warm-up runs write the byte-code; `bytecode_note` says if they could not."""
    skip = ("PYTHONDONTWRITEBYTECODE", *drop)
    return {k: v for k, v in os.environ.items() if k not in skip}


def bytecode_note() -> str | None:
    """None when ttctl's modules run from byte-code, else why the timing includes compiling them."""
    import importlib.util

    from .. import validate

    cached = importlib.util.cache_from_source(validate.__file__)
    if os.path.exists(cached):
        return None
    return (f"ttctl's byte-code could not be written ({os.path.dirname(cached)} missing or read-only): "
            "its modules are compiled on every run, mavgen's are not")


def median(xs: list[float]) -> float:
    return statistics.median(xs)


def machine() -> str:
    return f"{os.cpu_count()} cpus, Python {sys.version.split()[0]}"
