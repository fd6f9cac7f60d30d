"""docs/reference/cli.md is what tools/gen_cli_reference.py writes from the real command tree
(issue 30: the command reference comes from the CLI itself, so it cannot drift)."""

from __future__ import annotations

import importlib.util
import re
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import click
import pytest

from conftest import ROOT
from test_help import TREE

SCRIPT = ROOT / "tools" / "gen_cli_reference.py"
PAGE = ROOT / "docs" / "reference" / "cli.md"


def _script() -> ModuleType:
    spec = importlib.util.spec_from_file_location("gen_cli_reference", SCRIPT)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_checked_in_reference_is_what_the_command_tree_writes() -> None:
    expected = _script().render()
    assert PAGE.read_text() == expected, "docs/reference/cli.md is stale: run python tools/gen_cli_reference.py"


def test_every_command_option_example_and_status_is_in_the_reference() -> None:
    """The page is not just equal to the script's output: it holds each command's usage, every
    visible option with its panel, the examples and the exit statuses --help shows."""
    text = PAGE.read_text()
    sections = dict(re.findall(r"^#{2,4} (ttctl[\w -]*)\n(.*?)(?=^#{2,4} ttctl|\Z)", text, re.S | re.M))
    for name, cmd in TREE:
        body = sections.get(f"ttctl {name}")
        assert body is not None, f"no section for ttctl {name}"
        assert f"Usage: ttctl {name} [OPTIONS]" in body, name
        for p in cmd.params:
            if isinstance(p, click.Option) and not p.hidden and p.name != "help":
                for opt in p.opts:  # in an option row's first cell
                    assert re.search(r"^\| `[^`]*(?<![\w-])" + re.escape(opt) + r"(?![\w-])", body, re.M), (name, opt)
                assert f"**{p.rich_help_panel}**" in body, (name, p.opts, p.rich_help_panel)  # type: ignore[attr-defined]
        doc = cmd.help or ""
        for example in re.findall(r"^ +(ttctl .*)$", doc.split("Example", 1)[1], re.M):
            assert example.strip() in body, (name, example)
        for code in re.findall(r"^ +(\d+) +\S", doc.split("Exit status:", 1)[1].split("Example", 1)[0], re.M):
            assert re.search(rf"^\| {code} \| \S", body, re.M), (name, code)


def test_check_fails_on_a_stale_page(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    script = _script()
    stale = tmp_path / "cli.md"
    stale.write_text(PAGE.read_text().replace("--mtu INTEGER RANGE", "--mtu N"))
    monkeypatch.setattr(script, "PAGE", stale)
    monkeypatch.setattr(script, "ROOT", tmp_path)
    assert script.main(["--check"]) == 1
    assert script.main([]) == 0 and script.main(["--check"]) == 0  # rewritten, it is current again
    assert stale.read_text() == PAGE.read_text()


def test_the_script_runs_as_a_program() -> None:
    proc = subprocess.run([sys.executable, str(SCRIPT), "--check"], cwd=ROOT, capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 0, proc.stderr
