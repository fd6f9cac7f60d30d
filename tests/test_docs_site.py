"""The manual's site (mkdocs.yml, docs/) builds with warnings as errors, lists every page, and the
README's front door only shows what the manual shows (where the tests check it)."""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT, nav_pages
from test_readme import matches

DOCS = ROOT / "docs"


def mkdocs_build(config: Path, site: Path) -> subprocess.CompletedProcess[str]:
    if importlib.util.find_spec("mkdocs") is None or importlib.util.find_spec("material") is None:
        pytest.skip("mkdocs or mkdocs-material is not installed (pip install -e '.[test]' installs both)")
    return subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--config-file", str(config),
                           "--site-dir", str(site)], capture_output=True, text=True, timeout=180,
                          env={**os.environ, "NO_MKDOCS_2_WARNING": "1"})


def test_the_site_builds_strict(tmp_path: Path) -> None:
    proc = mkdocs_build(ROOT / "mkdocs.yml", tmp_path / "site")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert (tmp_path / "site" / "index.html").is_file()
    assert (tmp_path / "site" / "runtimes-cpp" / "index.html").is_file()


@pytest.mark.parametrize("link", ["[the dialect](../dialects/ttapi.xml)", "[gone](nowhere.md)",
                                  "[no such heading](files.md#no-such-heading)"])
def test_a_bad_link_fails_the_build(link: str, tmp_path: Path) -> None:
    """The build is strict about links: out of docs/, to a missing page, to a missing anchor."""
    shutil.copytree(DOCS, tmp_path / "docs")
    shutil.copy(ROOT / "mkdocs.yml", tmp_path / "mkdocs.yml")
    page = tmp_path / "docs" / "index.md"
    page.write_text(page.read_text() + f"\nSee {link}.\n")
    proc = mkdocs_build(tmp_path / "mkdocs.yml", tmp_path / "site")
    assert proc.returncode != 0, f"{link} passed the strict build"


def test_every_page_is_in_the_nav_and_every_entry_is_a_page() -> None:
    nav = nav_pages()
    assert len(nav) == len(set(nav)), "a page is in the nav twice"
    missing = [str(p.relative_to(DOCS)) for p in nav if not p.is_file()]
    assert not missing, f"mkdocs.yml's nav names pages that are not in docs/: {missing}"
    left_out = sorted(str(p.relative_to(DOCS)) for p in DOCS.rglob("*.md") if p not in nav)
    assert not left_out, f"pages in docs/ that mkdocs.yml's nav leaves out: {left_out}"


def _chunks(text: str) -> list[tuple[str, list[str]]]:
    """(command, output lines) of every `$ ` line of every console block; a trailing `&` (a job in
    the background) is not part of the command."""
    out = []
    for block in re.findall(r"```console\n(.+?)```", text, re.S):
        for chunk in re.split(r"^\$ ", block, flags=re.M)[1:]:
            cmd, _, rest = chunk.partition("\n")
            out.append((cmd.rstrip().removesuffix("&").rstrip(), [line for line in rest.rstrip("\n").split("\n")
                                                                   if line != ""]))
    return out


def test_the_readmes_examples_are_the_manuals() -> None:
    """Each command the README shows is one the docs show, and what it prints there is what the docs
    print (`...` for lines left out): the README's examples are checked where the docs' are."""
    shown = _chunks((ROOT / "README.md").read_text())
    assert len(shown) >= 10, shown
    docs = _chunks("\n".join(p.read_text() for p in nav_pages()))
    for cmd, expected in shown:
        there = [got for c, got in docs if c == cmd]
        assert there, f"the README runs `{cmd}`, which no page of docs/ shows"
        assert any(matches(expected, got) for got in there), \
            f"$ {cmd}\nREADME:\n" + "\n".join(expected) + "\ndocs/:\n" + "\n\n".join("\n".join(g) for g in there)


def test_the_readme_is_a_front_door() -> None:
    """Short, and every page of the site's nav a click away from it (directly, or from docs/index.md)."""
    text = (ROOT / "README.md").read_text()
    assert len(text.splitlines()) <= 250, "the README is the front door; the manual lives in docs/"
    linked = {(ROOT / t).resolve() for t in re.findall(r"\]\((docs/[^)#]+)", text)}
    index = (DOCS / "index.md").read_text()
    linked |= {(DOCS / t).resolve() for t in re.findall(r"\]\(((?!https?:)[^)#]+)", index)}
    unlinked = [str(p.relative_to(DOCS)) for p in nav_pages() if p.resolve() not in linked and p.name != "index.md"]
    assert not unlinked, f"pages neither the README nor docs/index.md links to: {unlinked}"
