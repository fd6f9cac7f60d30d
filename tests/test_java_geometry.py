"""The Java runtime's file-data frames follow the link's packet size (issue 26, /work/notes/geometry.md
as the lead decided it): a LinkScheduler takes its packet size from the Link (Link.mtu()), and
FileTransfers size their data frames to it: TT_FILE_DATA 80/100 on an unsigned 100-byte link as
before, TT_FILE_DATA_FIT filling the packet otherwise (107 bytes at 128, 66 at 100 signed, 94 at
128 signed), TT_FILE_DATA_WIDE across packets. Java to Java over an in-memory link of those packets
with seeded loss (tests/java/geometry/GeometryCheck.java): every file arrives whole, no packet is
over the link's size, and the receiver sees the frames the geometry says.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from conformance_lib import build_java
from conftest import ROOT

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

# mtu:signed:mode:loss -> (narrow kind, its largest count: what a full frame carries)
CASES = {
    "100:0:narrow:0.05": ("data", 0),
    "128:0:narrow:0.05": ("fit", 107),
    "100:1:narrow:0.05": ("fit", 66),
    "128:1:narrow:0.05": ("fit", 94),
    "128:0:wide:0.05": ("wide", 0),
    # no loss: after its probe frames the sender goes wide (247/280 = 0.88 of the link against 94/128)
    "128:1:auto:0": ("auto", 94),
}


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    cls, _ = build_java(tmp_path_factory.mktemp("java_geometry"), [ROOT / "tests/java/geometry/GeometryCheck.java"])
    return cls


def test_frames_follow_the_link_packet(classes: Path, tmp_path: Path) -> None:
    proc = subprocess.run(["java", "-cp", str(classes), "GeometryCheck", str(tmp_path), *CASES],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    lines = [ln for ln in proc.stdout.splitlines() if ln.startswith("CASE ")]
    assert len(lines) == len(CASES), proc.stdout + proc.stderr
    for case, line in zip(CASES, lines):
        got = dict(re.findall(r"(\w+)=(\S+)", line))
        kind, cap = CASES[case]
        assert got["ok"] == "true" and got["sha"] == "1", (case, line)
        assert got["oversize"] == "0", (case, line)  # no packet over the link's size
        if kind == "auto":
            assert got["data"] == "0" and int(got["fit"]) > 0 and int(got["wide"]) > 0, (case, line)
            assert int(got["fitmax"]) == cap, (case, line)
            continue
        others = {"data", "fit", "wide"} - {kind}
        assert int(got[kind]) > 0 and all(got[o] == "0" for o in others), (case, line)
        if kind == "fit":
            assert int(got["fitmax"]) == cap, (case, line)
