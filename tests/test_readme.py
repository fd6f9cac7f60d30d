"""The README's quick start stays true: CI runs its test command verbatim."""

from __future__ import annotations

import re

from conftest import ROOT


def quick_start_commands() -> list[str]:
    text = (ROOT / "README.md").read_text()
    section = text.split("## Quick start", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```sh\n(.+?)\n```", section, re.S)


def test_quick_start_has_two_commands() -> None:
    cmds = quick_start_commands()
    assert len(cmds) == 2, cmds
    assert "pip install ." in cmds[0] and "ttctl" in cmds[0]
    assert "pytest" in cmds[1]


def test_ci_runs_the_readme_test_command() -> None:
    ci = (ROOT / ".ci" / "run").read_text()
    assert quick_start_commands()[1] in ci.splitlines()


def test_readme_tours_every_subcommand() -> None:
    from typer.main import get_command

    from ttctl.app import app

    text = (ROOT / "README.md").read_text()
    group = get_command(app)
    names: list[str] = []
    for name, cmd in group.commands.items():  # type: ignore[attr-defined]
        sub = getattr(cmd, "commands", None)
        names += [f"ttctl {name} {s}" for s in sub] if sub else [f"ttctl {name}"]
    for name in names:
        assert f"### `{name}" in text, f"README has no tour section for {name}"
