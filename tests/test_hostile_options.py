"""Hostile input on every option of every command (issue 20, "Bad input everywhere").

- Every float option of every command (found by walking the real command tree, so a new option
  is covered without being listed here) refuses NaN and +-infinity: one line, exit 2. In
  process, through the real entry (`ttctl.app._run`): these are refused while parsing.
- Every option or argument naming a file ttctl reads gets: a missing file, a directory, a FIFO
  (nobody writing), /dev/zero, a sparse file of several GiB, a symlink loop and (not as root)
  an unreadable file: one line `ttctl: error: ...`, exit 2, within seconds, nothing left behind. Real
  processes, several at a time.
- Every number option of every command gets one of negative, zero, huge (a different one per
  option, rotating with the test's seed) and must never crash: a negative is refused (exit 2,
  one `ttctl: error:` line) unless it is a seed; an exit 2 is one error line; an accepted value
  runs (it is stopped after a moment) or ends with a documented status (0; 1 with a last
  `ttctl: error:` line saying why).
- `read_capped` stops at its cap while reading, not only by what stat says.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import resource
import signal
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import click
import pytest

from conftest import TTAPI, ttctl_cmd

NOWHERE = "udpout:127.0.0.1:9"


def _tree() -> list[tuple[list[str], click.Command]]:
    from ttctl.app import app
    from ttctl.commands.lazy import lazy_command

    out: list[tuple[list[str], click.Command]] = []

    def walk(cmd: click.Command, path: list[str]) -> None:
        if isinstance(cmd, click.Group):
            ctx = click.Context(cmd)
            for n in cmd.list_commands(ctx):
                sub = cmd.get_command(ctx, n)
                assert sub is not None
                walk(sub, [*path, n])
        else:
            out.append((path, cmd))

    walk(lazy_command(app), [])
    return out


TREE = _tree()

# arguments that make each command otherwise valid (and quick to refuse or to start)
BASE: dict[str, list[str]] = {
    "validate": [str(TTAPI)],
    "gen": [str(TTAPI), "-o", "{tmp}/g", "--check"],
    "recv-file": ["--listen", "udpin:127.0.0.1:0", "--dir", "{tmp}/in"],
    "send-file": ["x", "--to", NOWHERE, "--timeout", "1"],
    "bench validate": [str(TTAPI)],
    "bench gen": [str(TTAPI)],
    "bench dialect": [str(TTAPI)],
    "bench transfer": ["--quick"],
    "bench latency": [],
    "link relay": ["--listen", "udpin:127.0.0.1:0", "--to", NOWHERE],
    "link fit": ["{tmp}/m.json", "-o", "{tmp}/o.toml"],
    "emulate onboard": ["--no-gcs", "--listen", "udpin:127.0.0.1:0"],
    "emulate tablet": ["--to", NOWHERE],
    "hmd dump": ["--duration", "0.5"],
}


def _float_params() -> list[tuple[str, str]]:
    return [(" ".join(path), p.opts[0]) for path, cmd in TREE for p in cmd.params
            if isinstance(p, click.Option) and isinstance(p.type, click.types.FloatParamType)]


@pytest.mark.parametrize("value", ["nan", "inf", "-inf", "NaN", "+Infinity"])
def test_every_float_option_refuses_nan_and_infinity(value: str) -> None:
    from ttctl.app import _run

    params = _float_params()
    assert len(params) > 30  # the walk found the options (it is not testing nothing)
    bad = []
    for cmd, opt in params:
        argv = ["ttctl", *cmd.split(), *BASE.get(cmd, []), opt, value]
        err = io.StringIO()
        old = os.sys.argv  # type: ignore[attr-defined]
        os.sys.argv = argv  # type: ignore[attr-defined]
        try:
            with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
                code = _run()
        finally:
            os.sys.argv = old  # type: ignore[attr-defined]
        lines = err.getvalue().strip().splitlines()
        if not (code == 2 and len(lines) == 1 and lines[0].startswith("ttctl: error: ") and opt in lines[0]):
            bad.append((cmd, opt, code, err.getvalue()))
    assert not bad, bad


# -- files ------------------------------------------------------------------------------------

# (what, the command line with F where the file goes, kinds to skip)
FILE_INPUTS: list[tuple[str, list[str], set[str]]] = [
    ("validate DIALECT", ["validate", "F"], set()),
    ("gen DIALECT", ["gen", "F", "-o", "{tmp}/g"], set()),
    ("bench validate DIALECT", ["bench", "validate", "F"], set()),
    ("bench dialect DIALECT", ["bench", "dialect", "F"], set()),
    ("send-file FILE", ["send-file", "F", "--to", NOWHERE], {"huge"}),  # a big file is a fine thing to send
    ("send-file --key", ["send-file", "x", "--to", NOWHERE, "--key", "F"], set()),
    ("send-file --profile-file", ["send-file", "x", "--to", NOWHERE, "--profile-file", "F"], set()),
    ("send-file --dialect", ["send-file", "x", "--to", NOWHERE, "--dialect", "F"], set()),
    ("recv-file --key", ["recv-file", "--listen", "udpin:127.0.0.1:0", "--dir", "{tmp}/in", "--key", "F"], set()),
    ("recv-file --profile-file", ["recv-file", "--listen", "udpin:127.0.0.1:0", "--dir", "{tmp}/in",
                                  "--profile-file", "F"], set()),
    ("emulate onboard --key", ["emulate", "onboard", "--no-gcs", "--listen", "udpin:127.0.0.1:0", "--key", "F"],
     set()),
    ("emulate onboard --gcs-key", ["emulate", "onboard", "--listen", "udpin:127.0.0.1:0", "--gcs", NOWHERE,
                                   "--gcs-key", "F"], set()),
    ("emulate onboard --profile-file", ["emulate", "onboard", "--no-gcs", "--listen", "udpin:127.0.0.1:0",
                                        "--profile-file", "F"], set()),
    ("emulate tablet --script", ["emulate", "tablet", "--to", NOWHERE, "--script", "F"], set()),
    ("emulate tablet --key", ["emulate", "tablet", "--to", NOWHERE, "--key", "F"], set()),
    ("emulate tablet --profile-file", ["emulate", "tablet", "--to", NOWHERE, "--profile-file", "F"], set()),
    ("link relay --profile-file", ["link", "relay", "--listen", "udpin:127.0.0.1:0", "--to", NOWHERE,
                                   "--profile-file", "F"], set()),
    ("link fit MEASUREMENT", ["link", "fit", "F", "-o", "{tmp}/o.toml"], set()),
    ("bench link --like", ["bench", "link", "--like", "F"], set()),
    ("bench link --profile-file", ["bench", "link", "--profile-file", "F"], set()),
    ("bench transfer --profile-file", ["bench", "transfer", "--quick", "--profile-file", "F"], set()),
    ("bench latency --profile-file", ["bench", "latency", "--profile-file", "F"], set()),
    ("emulate onboard --plugin", ["emulate", "onboard", "--no-gcs", "--listen", "udpin:127.0.0.1:0", "--plugin", "F"],
     set()),
    ("emulate tablet --plugin", ["emulate", "tablet", "--to", NOWHERE, "--plugin", "F"], set()),
    ("hmd dump --profile-file", ["hmd", "dump", "--to", NOWHERE, "--duration", "0.1", "--profile-file", "F"],
     set()),
]
KINDS = ["missing", "directory", "fifo", "devzero", "huge", "unreadable", "symlink-loop"]


def _make(kind: str, folder: Path) -> str:
    folder.mkdir()
    path = folder / "f"
    if kind == "missing":
        return str(path)
    if kind == "directory":
        path.mkdir()
    elif kind == "fifo":
        os.mkfifo(path)
    elif kind == "devzero":
        return "/dev/zero"
    elif kind == "huge":
        with open(path, "wb") as fh:
            fh.truncate(5 << 30)  # sparse: 5 GiB that take no disk
    elif kind == "symlink-loop":  # unreadable even for root (ELOOP)
        path.symlink_to(path.name)
    elif kind == "unreadable":
        path.write_text("secret\n")
        path.chmod(0)
    return str(path)


def _bounded() -> None:
    """In the child: an unbounded read (the bug this file hunts) dies at 3 GiB, not the machine."""
    resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))


def _run_case(cmdline: list[str], tmp: Path, timeout: float = 10) -> tuple[int | None, str, str, float]:
    args = [str(tmp) + a[5:] if a.startswith("{tmp}") else a for a in cmdline]
    t0 = time.monotonic()
    p = subprocess.Popen(ttctl_cmd() + args, cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         stdin=subprocess.DEVNULL, preexec_fn=_bounded, start_new_session=True)
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:  # an accepted value runs: stop it and what it started (bench integrity's ends)
        with contextlib.suppress(ProcessLookupError):
            os.killpg(p.pid, signal.SIGKILL)
        out, err = p.communicate()
        return None, out, err, time.monotonic() - t0
    return p.returncode, out, err, time.monotonic() - t0


def test_every_file_input_refuses_missing_directories_fifos_devices_and_huge_files(tmp_path: Path) -> None:
    cases = []
    for i, (what, cmdline, skip) in enumerate(FILE_INPUTS):
        for kind in KINDS:
            if kind in skip or (kind == "unreadable" and os.geteuid() == 0):  # root reads anything
                continue
            work = tmp_path / f"{i}-{kind}"
            work.mkdir()
            f = _make(kind, work / "fixture")
            cases.append((what, kind, work, [f if a == "F" else a for a in cmdline]))

    def one(case: Any) -> tuple[Any, ...]:
        what, kind, work, cmdline = case
        code, out, err, secs = _run_case(cmdline, work)
        return what, kind, work, code, out, err, secs

    with ThreadPoolExecutor(4) as pool:
        results = list(pool.map(one, cases))
    bad = []
    for what, kind, work, code, out, err, secs in results:
        lines = (out + err).strip().splitlines()
        left = sorted(p.name for p in work.iterdir() if p.name != "fixture")
        # a dialect's problems are compiler-style, `PATH:LINE:COL: error: [CODE] ...` (README, validate)
        style = re.compile(r"ttctl: error: |\S+:1:1: error: \[[A-Z-]+\] " if "DIALECT" in what else "ttctl: error: ")
        if code != 2 or len(lines) != 1 or not style.match(lines[0]) or left:
            bad.append(f"{what} / {kind}: exit {code} in {secs:.1f} s, left {left}: {err.strip()[:300]!r}")
    assert not bad, "\n".join(bad)


def test_read_capped_counts_while_reading(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A file whose size stat understates (procfs, a file that grows) still stops at the cap."""
    from ttctl import safeio
    from ttctl.errors import Fail

    path = tmp_path / "grows"
    path.write_bytes(b"x" * 5000)
    real = os.fstat

    class Small:
        def __init__(self, st: os.stat_result) -> None:
            self.st_mode, self.st_size = st.st_mode, 0

    monkeypatch.setattr(safeio.os, "fstat", lambda fd: Small(real(fd)))
    with pytest.raises(Fail, match="more than 4 KiB"):
        safeio.read_capped(path, "--key grows", 4096)
    assert safeio.read_capped(path, "--key grows", 5000) == b"x" * 5000


def test_key_of_63_hex_digits_is_a_passphrase_and_says_so(tmp_path: Path) -> None:
    key = tmp_path / "key"
    key.write_text("a" * 63 + "\n")
    code, _out, err, _ = _run_case(["send-file", "x", "--to", NOWHERE, "--key", str(key)], tmp_path)
    assert code == 2 and "x: No such file" in err  # the key was taken ...
    assert "holds 63 characters of hex, not the 64 hex digits of a key" in err  # ... with a warning
    key.write_text("b" * 64 + "\n")
    code, _out, err, _ = _run_case(["send-file", "x", "--to", NOWHERE, "--key", str(key)], tmp_path)
    assert code == 2 and "warning" not in err


# -- numbers ----------------------------------------------------------------------------------

HUGE = {"integer": "1" + "0" * 30, "float": "1e300"}


def _number_cases(seed: int) -> list[tuple[str, str, list[str]]]:
    cases = []
    k = seed
    for path, cmd in TREE:
        name = " ".join(path)
        for p in cmd.params:
            if not isinstance(p, click.Option):
                continue
            kind = "float" if isinstance(p.type, click.types.FloatParamType) else (
                "integer" if isinstance(p.type, click.types.IntParamType) else None)
            if kind is None:
                continue
            value = ["-1", "0", HUGE[kind]][k % 3]
            k += 1
            cases.append((name, p.opts[0], [*path, *BASE.get(name, []), p.opts[0], value]))
    return cases


SIGNED = {"--seed"}  # the only number options a negative value means something for (a random seed)


def _one_error_line(err: str, at_end: bool = False) -> bool:
    """Exit 2: exactly one `ttctl: error: ...` line (warnings aside). Exit 1 (`at_end`): the run's
    last line (warnings aside) is ttctl's error saying why, not a stray library message."""
    lines = [ln for ln in err.strip().splitlines() if not ln.startswith("ttctl: warning: ")]
    if at_end:
        return bool(lines) and lines[-1].startswith("ttctl: error: ")
    return len(lines) == 1 and lines[0].startswith("ttctl: error: ")


def test_every_number_option_takes_negative_zero_or_huge_without_crashing(tmp_path: Path) -> None:
    seed = int(os.environ.get("TTCTL_HOSTILE_SEED", time.strftime("%j")))  # another third every day
    cases = _number_cases(seed)
    assert len(cases) > 60
    m = tmp_path / "m.json"
    m.write_text("{}")

    def one(i_case: tuple[int, tuple[str, str, list[str]]]) -> tuple[Any, ...]:
        i, (name, opt, argv) = i_case
        work = tmp_path / f"n{i}"
        work.mkdir()
        (work / "m.json").write_text("{}")
        code, out, err, _ = _run_case(argv, work, timeout=4)
        return name, opt, argv[-1], code, out, err

    with ThreadPoolExecutor(4) as pool:
        results = list(pool.map(one, enumerate(cases)))
    bad = []
    for name, opt, value, code, out, err in results:
        text = out + err
        if "Traceback" in text or "internal error" in text:
            bad.append(f"{name} {opt} {value}: crashed: {text.strip()[-300:]!r}")
        elif code not in (None, 0, 1, 2):  # the exit statuses the README documents (130 is Ctrl-C's)
            bad.append(f"{name} {opt} {value}: exit {code}, not a documented status: {text.strip()[-300:]!r}")
        elif code == 2 and not _one_error_line(err):
            bad.append(f"{name} {opt} {value}: exit 2 but not one line: {err.strip()[:300]!r}")
        elif value == "-1" and opt not in SIGNED and code != 2:  # no count, rate, time or size is negative
            bad.append(f"{name} {opt} -1: taken (exit {code}), not refused in one line with exit 2")
        elif code == 1 and not _one_error_line(err, at_end=True):  # ran and failed: it says why, last
            bad.append(f"{name} {opt} {value}: exit 1 without a final `ttctl: error:` line: {err.strip()[-300:]!r}")
    assert not bad, f"seed {seed}:\n" + "\n".join(bad)


@pytest.mark.parametrize(("argv", "words"), [
    (["recv-file", "--listen", "udpin:127.0.0.1:0", "--dir", "{tmp}/in", "--sysid", "0"],
     "--sysid must be in 1..255, not 0 (0 is MAVLink's broadcast address)"),
    (["emulate", "tablet", "--target-sysid", "-1", "--script", "{tmp}/s.yaml"], "--target-sysid must be in 1..255"),
    (["hmd", "dump", "--rate", "-1", "-o", "{tmp}/x.jsonl", "--duration", "0.1"],
     "--rate must be a positive number of bytes per second"),
    (["hmd", "dump", "--profile", "m100", "-o", "{tmp}/x.jsonl", "--duration", "0.1"], "they apply with --to"),
])
def test_ids_and_unused_link_options_are_refused(tmp_path: Path, argv: list[str], words: str) -> None:
    """An end's own id 0 (the broadcast address), a target id out of range, and link pacing
    given where there is no link: one line, exit 2, nothing made (these were accepted and
    silently meaningless)."""
    (tmp_path / "s.yaml").write_text("- status\n")
    p = subprocess.run(ttctl_cmd() + [a.replace("{tmp}", str(tmp_path)) for a in argv], capture_output=True,
                       text=True, timeout=60)
    lines = p.stderr.strip().splitlines()
    assert p.returncode == 2 and len(lines) == 1 and lines[0].startswith("ttctl: error: ") and words in lines[0], \
        p.stderr
    assert sorted(x.name for x in tmp_path.iterdir()) == ["s.yaml"]


def test_json_gets_json_for_usage_errors_too() -> None:
    """--json: a usage error (an unknown option, a number that is not one) is a JSON object on
    stdout as well as the one line on stderr."""
    import json

    p = subprocess.run(ttctl_cmd() + ["recv-file", "--listen", "udpin:127.0.0.1:0", "--json", "--max-file", "nan"],
                       capture_output=True, text=True, timeout=60)
    assert p.returncode == 2 and len(p.stderr.strip().splitlines()) == 1, p.stderr
    doc = json.loads(p.stdout)
    assert doc["ok"] is False and doc["exit"] == 2 and "--max-file" in doc["error"]
