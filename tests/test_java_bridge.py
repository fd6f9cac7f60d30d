"""The ground-station bridge of the generated Java runtime (runtime.GcsBridge, issue 22): its rules
without a vehicle (tests/java/gcs/GcsCheck.java: the sans-IO uplink queue and budget, the link
quality, a bridge on a recording link with a UDP socket as the ground station), the frames it
makes decoded by pymavlink as the oracle."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from conformance_lib import build_java
from conftest import ROOT

pytestmark = pytest.mark.skipif(not (shutil.which("javac") and shutil.which("java")),
                                reason="needs a JDK (javac, java)")


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    cls, _ = build_java(tmp_path_factory.mktemp("gcs_check"), [ROOT / "tests" / "java" / "gcs" / "GcsCheck.java"])
    return cls


def _mav() -> object:
    os.environ["MAVLINK20"] = "1"
    from pymavlink.dialects.v20 import common
    return common.MAVLink(None)


def test_bridge_rules_without_a_vehicle(classes: Path) -> None:
    """Retries of a waiting frame dropped, NEWEST slots replaced in place, PROTOCOL first, 64 + 64
    frames at most, the budget at 300 B/s over 10 virtual seconds; the table of ground stations
    (each 255/190 under its own free id, answers routed by target, forgotten after 30 s silent,
    at most 16 heard); the clashing 255/190 ground
    station carried as 254/190 and its answer given back to 255; a command for system 7 and
    garbage not carried; RADIO_STATUS within a second and a half; a port in use refused; on a
    signed link the scheduler signs the ground stations' frames; a send the socket refuses is told
    once, in words; bad settings are refused with words."""
    proc = subprocess.run(["java", "-cp", str(classes), "GcsCheck"], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    frames = {ln.split()[1]: bytes.fromhex(ln.split()[2]) for ln in proc.stdout.splitlines()
              if ln.startswith("FRAME ")}
    result = dict(kv.split("=") for kv in proc.stdout.splitlines()[-1].split()[1:])
    assert 3000 <= int(result["budget_bytes"]) <= 3200 and result["busy"] == "refused", result
    assert result["signed"] == "3", result
    [problem] = [ln for ln in proc.stdout.splitlines() if ln.startswith("PROBLEM ")]
    assert problem.startswith("PROBLEM sending to the ground station at 192.0.2.1:14550 failed: "), problem
    mav = _mav()
    moved = mav.parse_char(frames["resourced"])  # the CRC recomputed: pymavlink accepts it
    assert moved.get_type() == "COMMAND_LONG" and moved.get_srcSystem() == 254 and moved.get_srcComponent() == 190
    assert moved.target_system == 7 and moved.get_seq() == 9
    back = _mav().parse_char(frames["retargeted"])
    assert back.get_type() == "COMMAND_ACK" and back.target_system == 255 and back.target_component == 190
    radio = _mav().parse_char(frames["radio"])
    assert radio.get_type() == "RADIO_STATUS" and (radio.get_srcSystem(), radio.get_srcComponent()) == (1, 68)
    assert (radio.rssi, radio.remrssi, radio.txbuf, radio.rxerrors, radio.fixed) == (229, 229, 87, 70000 % 65536, 3)
    assert (radio.noise, radio.remnoise) == (0, 0)
    zero = _mav().parse_char(frames["radio_zero"])
    assert (zero.rssi, zero.txbuf, zero.rxerrors) == (0, 0, 0)
    live = _mav().parse_char(frames["radio_live"])
    assert live.get_type() == "RADIO_STATUS" and live.rssi == 254 and live.txbuf == 100
