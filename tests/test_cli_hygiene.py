"""Bad input and interrupts on every command: one line that starts `ttctl: error:`, a non-zero
exit, nothing left behind, never a traceback (real processes)."""

from __future__ import annotations

import os
import re
import signal
import statistics
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import ROOT, TTAPI, assert_no_traceback, run_ttctl, ttctl_cmd

BROKEN = ROOT / "tests" / "dialects" / "broken" / "keywords.xml"


def test_gen_that_fails_leaves_no_directory(tmp_path: Path) -> None:
    cases = [
        ([str(BROKEN), "-o", str(tmp_path / "x1")], 1, "error(s); nothing generated"),
        ([str(tmp_path / "missing.xml"), "-o", str(tmp_path / "x2")], 2, "missing.xml"),
        ([str(TTAPI), "-o", str(tmp_path / "x3"), "--lang", "cobol"], 2, "unknown language cobol"),
        ([str(TTAPI), "-o", str(tmp_path / "x4"), "--templates", str(tmp_path / "nope")], 2, "not a directory"),
        ([str(TTAPI), "-o", str(tmp_path / "x5"), "-I", str(tmp_path / "nope")], 2, "no such directory"),
    ]
    for args, code, text in cases:
        proc = run_ttctl("gen", *args)
        assert_no_traceback(proc)
        assert proc.returncode == code and text in proc.stderr + proc.stdout, (args, proc.stderr)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("cmd", ["validate", "gen"])
def test_include_dirs_must_exist(tmp_path: Path, cmd: str) -> None:
    a_file = tmp_path / "f.txt"
    a_file.write_text("x")
    for bad, why in ((tmp_path / "nope", "no such directory"), (a_file, "not a directory")):
        proc = run_ttctl(cmd, str(TTAPI), "-I", str(bad), *(["-o", str(tmp_path / "o")] if cmd == "gen" else []))
        assert proc.returncode == 2
        assert proc.stderr.strip() == f"ttctl: error: -I {bad}: {why}"
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("args", [["validate"], ["gen", "--lang"], ["send-file", "x", "--bogus"],
                                  ["bench", "transfer", "--size", "0"], ["link", "relay"], ["nosuch"]])
def test_usage_errors_are_one_line_starting_ttctl_error(args: list[str]) -> None:
    proc = run_ttctl(*args)
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("ttctl: error: "), proc.stderr


@pytest.mark.parametrize("bench", ["transfer", "link"])
def test_bench_plot_path_is_checked_before_any_work(tmp_path: Path, bench: str) -> None:
    for path, why in ((tmp_path / "no" / "x.png", f"no folder {tmp_path / 'no'}"), (tmp_path, "is a directory")):
        t0 = time.monotonic()
        proc = run_ttctl("bench", bench, "--plot", str(path))
        assert_no_traceback(proc)
        assert proc.returncode == 2 and proc.stderr.startswith("ttctl: error: ") and why in proc.stderr
        assert time.monotonic() - t0 < 10  # refused up front, not after the benchmark
    assert list(tmp_path.iterdir()) == []


def _startup() -> float:
    """How long this machine takes to start an interpreter as the console script does, site and
    the script's own `import re, sys` included, before any ttctl code (median of 5)."""
    times = []
    for _ in range(5):
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", "import re, sys"], check=True)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def _before_ttctl(err: str) -> bool:
    """Did the interrupt land before any code of ttctl ran: in the console script pip writes
    (`import re`, `import sys`, then `from ttctl.entry import main`), ahead of that last line,
    with no frame of the package itself?"""
    frames = re.findall(r'File "([^"]+)", line (\d+)', err)
    if not frames or "KeyboardInterrupt" not in err:
        return False
    script = [int(n) for f, n in frames if os.path.basename(f) == "ttctl"]
    ours = [f for f, _ in frames if f"{os.sep}ttctl{os.sep}" in f]
    if not script or ours:
        return False
    head = Path(frames[0][0]).read_text().splitlines()
    first_ours = next((i + 1 for i, line in enumerate(head) if "ttctl" in line and "import" in line), 0)
    return 0 < script[0] < first_ours


@pytest.mark.parametrize("args", [["validate", str(TTAPI)], ["gen", str(TTAPI), "-o", "{tmp}/out"],
                                  ["bench", "transfer", "--quick", "--seeds", "1"],
                                  ["send-file", str(TTAPI), "--to", "udpout:127.0.0.1:9", "--timeout", "5"],
                                  ["recv-file", "--listen", "udpin:127.0.0.1:0", "--dir", "{tmp}/in"]])
def test_ctrl_c_at_any_moment_is_one_quiet_line(tmp_path: Path, args: list[str]) -> None:
    """From a few interpreter start-up times on (before that, the interpreter itself is still
    starting and no program of its own has run), an interrupt while modules load, while
    options are parsed or while the command works is `ttctl: interrupted`, or the command's own
    clean stop; and an interrupted gen leaves no half-made tree."""
    base = max(0.03, 3 * _startup())
    for n, delay in enumerate((base, base * 1.5, base * 2, base * 3, base * 5, base * 8, 0.6, 1.0)):
        run_dir = tmp_path / f"run{n}"  # each run its own: a finished gen's tree is not another's leftover
        argv = [a.replace("{tmp}", str(run_dir)) for a in args]
        p = subprocess.Popen(ttctl_cmd() + argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(delay)
        p.send_signal(signal.SIGINT)
        _, err = p.communicate(timeout=60)
        if _before_ttctl(err):
            continue  # the interpreter, or the console script's own first imports, still starting (busy machine)
        assert "Traceback" not in err and "KeyboardInterrupt" not in err, (delay, err)
        assert p.returncode in (0, 1, 130), (delay, p.returncode, err)
        if p.returncode == 130:
            assert err.strip().splitlines()[-1] == "ttctl: interrupted", (delay, err)
        if args[0] == "gen" and p.returncode != 0:
            assert not run_dir.exists(), (delay, p.returncode, err)
        if args[0] == "recv-file" and p.returncode == 0:
            assert "stopped" in err, (delay, err)


def _command_paths(group: object, prefix: tuple[str, ...] = ()) -> list[tuple[str, ...]]:
    import click

    out = [prefix]
    if isinstance(group, click.Group):
        for name in group.list_commands(click.Context(group)):
            out += _command_paths(group.commands[name], (*prefix, name))
    return out


def test_lazy_command_tree_is_typers_tree() -> None:
    """The command line runs a tree built on demand (commands/lazy.py); every command's help,
    and the errors for a typo, are exactly what typer's whole tree gives."""
    import typer.main
    from click.testing import CliRunner

    from ttctl.app import app
    from ttctl.commands.lazy import lazy_command

    full, lazy = typer.main.get_command(app), lazy_command(app)
    paths = _command_paths(full)
    assert len(paths) > 20 and ("emulate", "onboard") in paths and ("bench", "validate") in paths
    assert _command_paths(lazy) == paths
    runner = CliRunner()
    for p in paths:
        a = runner.invoke(full, [*p, "--help"], prog_name="ttctl", terminal_width=100)
        b = runner.invoke(lazy, [*p, "--help"], prog_name="ttctl", terminal_width=100)
        assert (a.exit_code, a.output) == (b.exit_code, b.output), p
    for argv in (["valdate"], ["bench", "transfr"], ["emulate", "onboard", "--bogus"]):
        a = runner.invoke(full, argv, prog_name="ttctl")
        b = runner.invoke(lazy, argv, prog_name="ttctl")
        assert (a.exit_code, str(a.exception), a.output) == (b.exit_code, str(b.exception), b.output), argv


def test_lazy_command_tree_builds_only_what_runs() -> None:
    import click

    from ttctl.app import app
    from ttctl.commands.lazy import LazyCommands, lazy_command

    root = lazy_command(app)
    ctx = root.make_context("ttctl", ["bench", "validate", "--help"], resilient_parsing=True)
    root.resolve_command(ctx, ["bench"])
    assert isinstance(root.commands, LazyCommands)
    built = {k for k, v in dict.items(root.commands) if v is not None}
    assert built == {"bench"}
    bench = root.commands["bench"]
    assert isinstance(bench, click.Group) and isinstance(bench.commands, LazyCommands)
    assert {k for k, v in dict.items(bench.commands) if v is not None} == set()


def test_bench_times_tools_as_installed(monkeypatch: pytest.MonkeyPatch) -> None:
    """Whole-process benchmarks run ttctl and mavgen alike from byte-code: under
    PYTHONDONTWRITEBYTECODE ttctl's editable install would compile its modules on every run
    and pip-compiled mavgen would not."""
    from ttctl.bench.procs import bytecode_note, installed_env

    monkeypatch.setenv("PYTHONDONTWRITEBYTECODE", "1")
    monkeypatch.setenv("TTCTL_DIALECT", "x.xml")
    env = installed_env(drop=("TTCTL_DIALECT",))
    assert "PYTHONDONTWRITEBYTECODE" not in env and "TTCTL_DIALECT" not in env and env["PATH"]
    note = bytecode_note()
    assert note is None or "compiled on every run" in note


def test_a_ctrl_c_python_swallows_still_stops_the_command() -> None:
    """A KeyboardInterrupt raised while Python runs a finalizer is printed as 'Exception ignored'
    and lost (CI saw it in the import system's module-lock callback: recv-file then ran on for
    60 s after its only Ctrl-C). ttctl's handler remembers it: no traceback, and a command's loop
    stops as soon as it starts."""
    code = """
import asyncio, gc, os, signal, time
from ttctl import interrupts
from ttctl.commands.common import Signals
interrupts.install()
class Finalized:
    def __del__(self):
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(0.2)  # the handler runs here, inside the finalizer: Python swallows what it raises
Finalized()
gc.collect()
print("went on", interrupts.seen())
async def main():
    sigs = Signals(asyncio.get_running_loop(), asyncio.Event())
    print("loop stops", sigs.stop.is_set())
asyncio.run(main())
"""
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, p.stderr
    assert p.stdout.split("\n")[:2] == ["went on True", "loop stops True"], p.stdout
    assert "Traceback" not in p.stderr and "Exception ignored" not in p.stderr, p.stderr
