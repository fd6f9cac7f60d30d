"""The Java receiver's statuses without a network (tests/java/receiver/CompleteCheck.java, the
generated FileReceiver on a virtual clock), against what ttctl's Python receiver says."""

from __future__ import annotations

import itertools
import json
import shutil
import subprocess
from pathlib import Path

import pytest

from conformance_lib import build_java
from conftest import ROOT

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")


def test_complete_is_said_three_times_50_ms_apart(tmp_path: Path) -> None:
    """As the Python receiver (proto/receiver.py COMPLETE_REPEATS): the COMPLETE status goes
    three times, 50 ms apart, then no more, so that one lost packet does not leave the sender
    (a server whose fetcher exits at once) recording a delivered, verified file as failed."""
    from ttctl.proto.receiver import COMPLETE_REPEAT_GAP, COMPLETE_REPEATS

    cls, _ = build_java(tmp_path, [ROOT / "tests" / "java" / "receiver" / "CompleteCheck.java"])
    (tmp_path / "inbox").mkdir()
    proc = subprocess.run(["java", "-cp", str(cls), "ttctl.ttapi.transfer.CompleteCheck", str(tmp_path / "inbox")],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    got = json.loads(proc.stdout)
    assert got["file"]
    said = got["complete"]
    assert len(said) == 1 + COMPLETE_REPEATS, said
    assert said[0] == pytest.approx(1.0)
    for a, b in itertools.pairwise(said):
        assert b - a == pytest.approx(COMPLETE_REPEAT_GAP, abs=0.011), said
