#!/usr/bin/env python3
"""Refresh the figures docs/benchmarks.md quotes from `ttctl bench transfer`, which runs in
virtual time on fixed seeds and so prints the same every run.

    python tools/bench_docs.py           # run the bench once, rewrite its rows in the page
    python tools/bench_docs.py --check   # exit 1, naming each row, if the page differs from a run

What it refreshes: every line of the console blocks that show the bench's output (the block
run as `$ ttctl bench transfer ...`, and the blocks marked "rows of bench transfer's run
above"), each matched to the run's line of the same shape (its words, with the figures left
out); `...` lines stay. And the markdown table of ttctl's efficiency by loss. The prose around
them quotes some figures too: `--check` cannot see those, so read it after a refresh.
tests/test_bench_docs.py runs `--check`, so the page cannot drift from the bench.

This is a maintainer's tool, not a `ttctl` command.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAGE = ROOT / "docs" / "benchmarks.md"
COMMAND = "ttctl bench transfer --plot docs/bench-transfer.png"
ROWS_MARK = "rows of bench transfer's run above"
TABLE_HEAD = "| loss | up random | up burst | down random | down burst |"


def _run(plot: Path) -> str:
    env = {**os.environ, "COLUMNS": "200", "TERM": "dumb"}  # as tests/docs_examples.py runs the manual
    cmd = [sys.executable, "-m", "ttctl", "bench", "transfer", "--plot", str(plot)]
    proc = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=1800)
    if proc.returncode not in (0, 1) or not proc.stdout.strip():
        raise SystemExit(f"bench_docs: ttctl bench transfer failed ({proc.returncode}): {proc.stderr.strip()[-500:]}")
    return proc.stdout


def shape(line: str) -> str:
    """A line with its figures left out: what a row of the run is matched by."""
    s = re.sub(r"\d+\.\d+%?|\d+(?![\d%])", "#", line)  # "30%" names a case; "0.530", "99.8%", "459" are figures
    s = re.sub(r"\b(yes|no)\b", "?", s)
    s = re.sub(r"([━─═])\1+", r"\1", s)
    return re.sub(r"\s+", " ", s).strip()


def _blocks(lines: list[str]) -> list[tuple[int, int]]:
    """(first, end) line indexes of the bench's console blocks' contents."""
    out = []
    for i, ln in enumerate(lines):
        if ln.strip() != "```console":
            continue
        above = lines[i - 1] if i else ""
        j = i + 1
        while j < len(lines) and lines[j].strip() != "```":
            j += 1
        first = lines[i + 1].strip() if i + 1 < len(lines) else ""
        if first == f"$ {COMMAND}":
            out.append((i + 2, j))
        elif ROWS_MARK in above:
            out.append((i + 1, j))
    return out


def refresh_rows(lines: list[str], run: list[str]) -> list[str]:
    """The page's lines, each bench row replaced by the run's row of its shape. Raises
    SystemExit naming the rows the run no longer prints."""
    by_shape: dict[str, list[str]] = {}
    for ln in run:
        by_shape.setdefault(shape(ln), []).append(ln.rstrip())
    lines = list(lines)
    lost = []
    for first, end in _blocks(lines):
        used: dict[str, int] = {}
        for k in range(first, end):
            ln = lines[k]
            if ln.strip() in ("", "..."):
                continue
            key = shape(ln)
            cands = by_shape.get(key)
            if not cands:
                lost.append(ln)
                continue
            n = used.get(key, 0)  # lines of one shape (rules, headers) in the order the run prints them
            lines[k] = cands[min(n, len(cands) - 1)]
            used[key] = n + 1
    if lost:
        raise SystemExit("bench_docs: the run prints no row like these (edit the page):\n  " + "\n  ".join(lost))
    return lines


def efficiency_table(run: list[str]) -> list[str]:
    """The markdown table of ttctl's (and ttctl signed's) efficiency, median of the seeds, from
    the run's first table (its rows: protocol, dir, loss, model, ..., efficiency)."""
    eff = {}
    for ln in run:
        cells = [c.strip() for c in ln.strip().strip("│").split("│")]
        if len(cells) == 8 and cells[0] in ("ttctl", "signed"):
            eff[(cells[0], cells[1], cells[2], cells[3])] = cells[7]
    out = [TABLE_HEAD, "|---|---|---|---|---|"]
    for proto, label in (("ttctl", ""), ("signed", "signed, ")):
        for loss in ("0%", "10%", "30%"):
            cells = [eff.get((proto, d, loss, model), "") if not (loss == "0%" and model == "burst") else ""
                     for d in ("up", "down") for model in ("random", "burst")]
            out.append(re.sub(r"\|\s+\|", "| |", f"| {label}{loss[:-1]} % | " + " | ".join(cells) + " |"))
            out[-1] = re.sub(r"\|\s+\|", "| |", out[-1])  # (twice: the empty cells are neighbours)
    return out


def refresh_table(lines: list[str], table: list[str]) -> list[str]:
    i = next((k for k, ln in enumerate(lines) if ln.strip() == TABLE_HEAD), None)
    if i is None:
        raise SystemExit(f"bench_docs: {PAGE.name} has no table headed {TABLE_HEAD!r}")
    j = i
    while j < len(lines) and lines[j].startswith("|"):
        j += 1
    return lines[:i] + table + lines[j:]


def main(argv: list[str]) -> int:
    check = "--check" in argv
    with tempfile.TemporaryDirectory(prefix="ttctl-bench-docs-") as d:
        plot = Path(d) / "bench-transfer.png"
        run = _run(plot).splitlines()
        page = PAGE.read_text(encoding="utf-8").splitlines()
        new = refresh_table(refresh_rows(page, run), efficiency_table(run))
        if check:
            diff = [f"  page: {a}\n  run:  {b}" for a, b in zip(page, new, strict=True) if a != b]
            if diff:
                print(f"bench_docs: {PAGE.relative_to(ROOT)} differs from the bench in {len(diff)} line(s) "
                      f"(python tools/bench_docs.py rewrites them):\n" + "\n".join(diff))
                return 1
            return 0
        PAGE.write_text("\n".join(new) + "\n", encoding="utf-8")
        (ROOT / "docs" / "bench-transfer.png").write_bytes(plot.read_bytes())
        print(f"bench_docs: {sum(a != b for a, b in zip(page, new, strict=True))} line(s) rewritten in "
              f"{PAGE.relative_to(ROOT)}; docs/bench-transfer.png replaced")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
