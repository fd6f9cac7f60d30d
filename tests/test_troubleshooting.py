"""docs/troubleshooting.md quotes the errors users meet most exactly as ttctl prints them: each
example is run and compared (tests/docs_examples.py), and the lines of the few that cannot run
in a test are found among the messages of cli/ttctl."""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import ROOT
from docs_examples import Block, blocks, quoted_by_code, run_block

PAGE = ROOT / "docs" / "troubleshooting.md"
BLOCKS = blocks(PAGE)
RUN = [b for b in BLOCKS if b.not_run is None]
NOT_RUN = [b for b in BLOCKS if b.not_run is not None]


def test_the_page_quotes_the_errors_users_meet() -> None:
    text = PAGE.read_text()
    for words in ("lacks the runtime's messages", "address already in use", "the same --key at both ends",
                  "link lost", "is extrapolated at", "waiting for a reader of this FIFO", "No such option",
                  "is in use by another ttctl receiver", "exists and overwriting is not allowed"):
        assert words in text, words
    assert len(RUN) >= 12 and len(NOT_RUN) <= 6, (len(RUN), len(NOT_RUN))


@pytest.mark.parametrize("block", RUN, ids=[b.where for b in RUN])
def test_each_example_prints_what_the_page_shows(block: Block, tmp_path: Path) -> None:
    run_block(block, tmp_path)


@pytest.mark.parametrize("block", NOT_RUN, ids=[b.where for b in NOT_RUN])
def test_each_line_of_the_examples_not_run_is_a_message_of_the_code(block: Block) -> None:
    quoted = [line for _, out in block.steps for line in out if "ttctl:" in line]
    assert quoted, block.where
    unknown = [line for line in quoted if not quoted_by_code(line)]
    assert not unknown, f"{block.where} ({block.not_run}): no message of cli/ttctl prints {unknown}"


@pytest.mark.parametrize("line", ["ttctl: error: --dialect mine.xml lacks the runtime's messages, sorry",
                                  "ttctl: tablet: link lost: the vehicle went home",
                                  "ttctl: error: refused by 1/240: the receiver does not like you"])
def test_a_line_the_code_does_not_print_is_not_taken_for_one(line: str) -> None:
    assert not quoted_by_code(line)
