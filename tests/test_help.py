"""Every command's --help teaches: options in panels named in one list, an example that parses
(and, for the quick and harmless ones, runs to exit 0), and what each exit status means."""

from __future__ import annotations

import inspect
import re
import shlex
from collections import Counter
from pathlib import Path

import click
import pytest

from conftest import ROOT, assert_no_traceback, run_ttctl
from test_hostile_options import TREE as HOSTILE_TREE

# every command of the real command tree, as the command line builds it
TREE = [(" ".join(path), cmd) for path, cmd in HOSTILE_TREE]
NAMES = [name for name, _ in TREE]
WIDTH = 80  # the newcomer's terminal
CODES = {0, 1, 2, 3, 130}


def _text(cmd: click.Command) -> str:
    return inspect.cleandoc(cmd.help or "")


def _section(text: str, heading: str) -> tuple[str, list[str]]:
    """The heading line that starts with `heading`, and the indented lines under it."""
    lines = text.splitlines()
    at = [i for i, line in enumerate(lines) if re.match(heading, line)]
    assert len(at) == 1, f"{len(at)} lines start with {heading!r}"
    body = []
    for line in lines[at[0] + 1:]:
        if not line.startswith("  "):
            break
        body.append(line)
    return lines[at[0]], body


def _statuses(text: str) -> dict[int, str]:
    heading, body = _section(text, r"Exit status:")
    assert heading == "Exit status:"
    out: dict[int, str] = {}
    for line in body:
        m = re.match(r"  (\d+) +(\S.*)$", line)
        if m:
            out[int(m.group(1))] = m.group(2)
        else:  # the meaning of the status above, continued
            assert out and re.match(r" {7,}\S", line), f"not a status line: {line!r}"
    return out


def examples(text: str) -> list[str]:
    """The command lines under the help's Example(s) heading (a trailing backslash continues one)."""
    heading, body = _section(text, r"Examples?\b")
    assert heading.endswith(":"), heading
    out: list[str] = []
    joined = ""
    for line in body:
        joined += line.strip()
        if joined.endswith("\\"):
            joined = joined[:-1].rstrip() + " "
            continue
        out.append(joined)
        joined = ""
    assert not joined, "an example ends in a backslash"
    return out


def test_the_tree_is_every_command() -> None:
    assert len(TREE) >= 22 and {"validate", "gen", "emulate onboard", "bench transfer", "hmd dump"} <= set(NAMES)


@pytest.mark.parametrize("name", NAMES)
def test_help_states_every_exit_status(name: str) -> None:
    """0, 2 (bad options: click's own), 3 (internal error) and 130 (Ctrl-C) are every command's;
    1 where the command has a failure or a verdict of its own; nothing else."""
    statuses = _statuses(_text(dict(TREE)[name]))
    assert {0, 2, 3, 130} <= set(statuses) <= CODES, (name, sorted(statuses))
    assert list(statuses) == sorted(statuses), name
    assert "internal error" in statuses[3] and "Ctrl-C" in statuses[130], name


@pytest.mark.parametrize("name", NAMES)
def test_help_example_is_a_command_line_it_accepts(name: str) -> None:
    """Each example is a command line with options the command has and values they take,
    parsed by the command itself, so an example cannot name an option that was renamed or
    dropped. The first is of this command; the others may show its peers (three shells)."""
    found = examples(_text(dict(TREE)[name]))
    assert found, name
    assert shlex.split(found[0])[:1 + len(name.split())] == ["ttctl", *name.split()], found[0]
    for line in found:
        argv = shlex.split(line)
        assert argv[0] == "ttctl", line
        which = max((n for n in NAMES if argv[1:1 + len(n.split())] == n.split()), key=len)
        cmd = dict(TREE)[which]
        ctx = cmd.make_context(f"ttctl {which}", argv[1 + len(which.split()):])  # click's usage error if not
        assert not ctx.args, (line, ctx.args)


@pytest.mark.parametrize("name", NAMES)
def test_help_text_fits_80_columns(name: str) -> None:
    """Below its first line (which typer joins and wraps), the help keeps its own line breaks:
    a line over 78 columns (80 less the margins) would break in the middle of a newcomer's screen."""
    long = [line for line in _text(dict(TREE)[name]).split("\n\n", 1)[-1].splitlines() if len(line) > WIDTH - 2]
    assert not long, (name, long)


@pytest.mark.parametrize("name", NAMES)
def test_options_are_in_the_shared_panels(name: str) -> None:
    from ttctl.commands.panels import PANELS

    cmd = dict(TREE)[name]
    panels: Counter[str] = Counter()
    for p in cmd.params:
        if isinstance(p, click.Option) and p.name != "help":
            panel = getattr(p, "rich_help_panel", None)
            assert panel in PANELS, f"{name} {p.opts[0]}: panel {panel!r} is not in commands/panels.py"
            panels[panel] += 1
    crowded = {k: v for k, v in panels.items() if v > 8}
    assert not crowded, f"{name}: more than 8 options in {crowded}"


def test_panels_show_in_the_help_at_80_columns() -> None:
    proc = run_ttctl("emulate", "onboard", "--help", timeout=60, env={"COLUMNS": str(WIDTH), "TERM": "dumb"})
    assert proc.returncode == 0, proc.stderr
    for title in ("Link", "Ground stations", "Vehicle", "Signing", "Dialect", "Exit status:", "Example"):
        assert title in proc.stdout, title
    assert max(len(line) for line in proc.stdout.splitlines()) <= WIDTH


def test_panel_names_are_one_list() -> None:
    """Commands name panels through commands/panels.py, never as strings of their own."""
    from ttctl.commands import panels

    assert len(set(panels.PANELS)) == len(panels.PANELS)
    for path in (ROOT / "cli" / "ttctl").rglob("*.py"):
        for m in re.finditer(r"rich_help_panel=(\S+?)[,)\n]", path.read_text()):
            assert re.fullmatch(r"[A-Z_]+", m.group(1)), f"{path.name}: rich_help_panel={m.group(1)}"


# examples quick and harmless enough to run as they are shown (in a folder holding dialects/)
RUN = {"validate": 0, "gen": 0, "bench link": 0, "bench latency": 0, "hmd dump": 0}


@pytest.mark.parametrize("name", sorted(RUN))
def test_help_example_runs(name: str, tmp_path: Path) -> None:
    (tmp_path / "dialects").symlink_to(ROOT / "dialects")
    line = examples(_text(dict(TREE)[name]))[RUN[name]]
    proc = run_ttctl(*shlex.split(line)[1:], cwd=tmp_path, timeout=120)
    assert_no_traceback(proc)
    assert proc.returncode == 0, f"$ {line}\n{proc.stdout[-2000:]}{proc.stderr[-2000:]}"


def test_every_argument_shows_its_help() -> None:
    """An argument's declared help is in its command's --help (click 8.5's Argument once reset
    typer's to None, so DIALECT, FILE... showed without a word)."""
    from typer.core import TyperArgument

    seen = 0
    for name, cmd in TREE:
        args = [p for p in cmd.params if isinstance(p, TyperArgument)]
        if not args:
            continue
        proc = run_ttctl(*name.split(), "--help", env={"COLUMNS": "200"})
        assert proc.returncode == 0, proc.stderr
        for p in args:
            assert p.help, f"{name}: argument {p.name} has no help"
            assert " ".join(p.help.split()[:4]) in " ".join(proc.stdout.split()), (name, p.name, proc.stdout)
            seen += 1
    assert seen >= 5
