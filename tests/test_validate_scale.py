"""Validation time grows linearly with the number of messages, valid or broken (a list test
per message, and libxml2 naming each XSD error's node by counting its siblings, made it
quadratic). Timed in-process in CPU time, min of three, as a ratio between two sizes of the same kind of
dialect: 4x the messages must cost well under 8x the time (quadratic costs about 16x)."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from ttctl.bench.synthetic import synthetic_dialect
from ttctl.validate import load_and_check


def _ratio(small: Path, large: Path, runs: int = 3) -> float:
    """CPU seconds of the large over the small, the least of `runs` each, interleaved: this
    process's own time, so other work on a busy machine does not count (wall time did)."""
    best = {small: float("inf"), large: float("inf")}
    for _ in range(runs):
        for path in (small, large):
            t0 = time.process_time()
            load_and_check(str(path), [])
            best[path] = min(best[path], time.process_time() - t0)
    return best[large] / best[small]


def _broken(path: Path) -> Path:
    """The same dialect with every message's description removed: one XSD error each."""
    path.write_text(path.read_text().replace("<description>m</description>", ""))
    return path


@pytest.mark.parametrize("broken", [False, True])
def test_validation_time_is_linear_in_messages(tmp_path: Path, broken: bool) -> None:
    small = synthetic_dialect(2000, tmp_path / "small.xml")
    large = synthetic_dialect(8000, tmp_path / "large.xml")
    if broken:
        small, large = _broken(small), _broken(large)
    _, rep, _ = load_and_check(str(large), [])
    assert rep.errors == (8000 if broken else 0)
    ratio = _ratio(small, large)
    assert ratio < 8.0, f"4x the messages took {ratio:.1f}x the time"


def test_the_largest_synthetic_dialect_fits_the_input_cap_and_validates(tmp_path: Path) -> None:
    from conftest import run_ttctl

    path = synthetic_dialect(60_000, tmp_path / "big.xml")
    assert path.stat().st_size < 8 << 20
    proc = run_ttctl("validate", str(path), timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert "(60000 messages, 60000 in this file; 1 enums; 1 file)" in proc.stdout
