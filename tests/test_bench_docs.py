"""docs/benchmarks.md quotes `ttctl bench transfer`, which runs in virtual time on fixed seeds and
prints the same every run: tools/bench_docs.py --check runs it once and compares every quoted row
and the efficiency table with the run, so the page cannot drift from the code (issue 30 found 4 of
16 console rows and 7 of 20 table cells stale). About a minute of one core."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_the_bench_transfer_page_says_what_the_bench_prints() -> None:
    proc = subprocess.run([sys.executable, str(ROOT / "tools" / "bench_docs.py"), "--check"], capture_output=True,
                          text=True, timeout=1800)
    assert proc.returncode == 0, proc.stdout[-6000:] + proc.stderr[-3000:]


def test_rows_are_matched_by_their_case_not_their_figures() -> None:
    sys.path.insert(0, str(ROOT / "tools"))
    try:
        import bench_docs
    finally:
        sys.path.pop(0)
    a = bench_docs.shape("│ ttctl    │ down │  30% │ random │    18.5 │    3548 │     6700 │      0.530 │")
    b = bench_docs.shape("│ ttctl    │ down │  30% │ random │    18.2 │    3606 │     6700 │      0.538 │")
    c = bench_docs.shape("│ ttctl    │ down │  10% │ random │    14.0 │    4669 │     6700 │      0.697 │")
    assert a == b != c
    assert bench_docs.shape("│ signed down 30% burst of its ceiling  │ 0.9335  │ ≥ 0.95   │ no  │") == \
        bench_docs.shape("│ signed down 30% burst of its ceiling   │ 0.9651  │ ≥ 0.95   │ yes │")
