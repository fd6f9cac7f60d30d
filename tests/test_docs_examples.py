"""Every ```console example of the manual (docs/) is run by a test and prints what it shows, or
says in the page why not (`<!-- not run: why -->` above it): a new example is one or the other.

Run elsewhere: the tours of validate, gen and bench link (tests/test_readme.py), and every
example of docs/troubleshooting.md (tests/test_troubleshooting.py). Run here: the quick,
self-contained rest (tests/docs_examples.py says how figures that vary by design are compared)."""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import nav_pages
from docs_examples import Block, blocks, run_block
from test_readme import console_examples

ROBOLAB = "dialects/examples/robolab.xml"

# (page, the block's first command) -> files of the repository the block's folder holds
RUN: dict[tuple[str, str], tuple[str, ...]] = {
    ("dialects.md", "ttctl validate robolab.xml"): (ROBOLAB,),
    ("ground-stations.md", "ttctl gen robolab.xml --lang xml -o gen"): (ROBOLAB,),
    ("benchmarks.md", "ttctl bench latency"): (),
}

# tours whose examples tests/test_readme.py runs (test_readme_examples_are_what_the_commands_print)
TOURS = ("ttctl validate", "ttctl gen", "ttctl bench link")
BY_OTHER_TESTS = {"troubleshooting.md": "tests/test_troubleshooting.py"}

ALL = [b for page in nav_pages() for b in blocks(page)]
HERE = [b for b in ALL if b.steps and (b.page, b.steps[0][0]) in RUN]


def _run_by_test_readme(block: Block) -> bool:
    ran = {cmd for heading in TOURS for cmd, _ in console_examples(heading)
           if "ttctl " in cmd and "conformance" not in cmd}
    cmds = [c for c, _ in block.steps]
    return bool(cmds) and all(c in ran for c in cmds)


@pytest.mark.parametrize("block", HERE, ids=[b.where for b in HERE])
def test_the_example_prints_what_the_manual_shows(block: Block, tmp_path: Path) -> None:
    assert block.not_run is None, f"{block.where} is marked not run, but is run here"
    run_block(block, tmp_path, RUN[(block.page, block.steps[0][0])])


def test_every_example_is_run_or_says_why_not() -> None:
    assert len(HERE) == len(RUN), "an entry of RUN names no block of the manual (its first command changed?)"
    unaccounted = [b.where for b in ALL if b.not_run is None and b not in HERE and b.page not in BY_OTHER_TESTS
                   and not _run_by_test_readme(b)]
    assert not unaccounted, ("console examples no test runs, without <!-- not run: why --> above them: "
                             f"{unaccounted}")
    run_anyway = [b.where for b in ALL if b.not_run is not None and (b in HERE or _run_by_test_readme(b))]
    assert not run_anyway, f"marked not run, but run by a test: {run_anyway}"
