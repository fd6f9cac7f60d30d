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


@pytest.fixture(scope="module")
def burst_classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    driver = ROOT / "tests" / "java" / "receiver" / "BurstCheck.java"
    cls, _ = build_java(tmp_path_factory.mktemp("java_burst"), [driver])
    return cls


@pytest.mark.parametrize(("mtu", "signed", "per"), [(100, True, 5), (100, False, 6), (128, True, 7), (128, False, 7)])
@pytest.mark.parametrize("gaps", [12, 29])
def test_statuses_fit_one_packet(burst_classes: Path, tmp_path: Path, mtu: int, signed: bool, per: int,
                                 gaps: int) -> None:
    """As the Python receiver (proto/receiver.py, endpoint.py's ranges_per_status): a status lists
    only the gaps that fit one packet of the tablet's link (its FileTransfers' scheduler: packet
    size, signer), so every status, packed and signed, fits one packet (a 7-gap status is 102
    bytes, 115 signed: two DTT packets, lost when either is); a report holds as many gaps as three
    7-gap statuses, in ceil(21 / per) statuses; range_count's top bit (RANGES_MORE) says more gaps
    follow past received_end, on every status of a burst but one that ends the gaps."""
    from ttctl.proto.transfer import MAX_RANGES, RANGES_MORE, ranges_per_status

    assert ranges_per_status(mtu, signed) == per
    (tmp_path / "inbox").mkdir()
    proc = subprocess.run(["java", "-cp", str(burst_classes), "ttctl.ttapi.transfer.BurstCheck",
                           str(tmp_path / "inbox"), str(mtu), "signed" if signed else "unsigned", str(gaps)],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    calls = [json.loads(line) for line in proc.stdout.splitlines()][1:]
    bursts = [c["statuses"] for c in calls if any(s["range_count"] for s in c["statuses"])]
    assert bursts, proc.stdout
    for burst in bursts:
        for s in burst:
            assert s["len"] <= mtu, s
            assert 0 < s["range_count"] & ~RANGES_MORE <= per, s
        listed = sum(s["range_count"] & ~RANGES_MORE for s in burst)
        assert len(burst) == min(-(-gaps // per), -(-3 * MAX_RANGES // per)), burst
        assert listed == min(gaps, len(burst) * per), burst
        more = [bool(s["range_count"] & RANGES_MORE) for s in burst]
        # the last says whether gaps remain past what the burst could list
        assert more == [True] * (len(burst) - 1) + [listed < gaps], burst
        for a, b in itertools.pairwise(burst):
            assert b["region_start"] == a["received_end"], burst
        gap_list = [(s["ranges"][2 * i], s["ranges"][2 * i + 1]) for s in burst
                    for i in range(s["range_count"] & ~RANGES_MORE)]
        base = 1 << 24  # (BurstCheck's: the data arrives past 16 MiB, every other frame)
        assert gap_list == [(0, base), *((base + 80 * k, base + 80 * (k + 1)) for k in range(1, 2 * listed - 2, 2))], \
            burst


@pytest.mark.parametrize("signed", [True, False])
@pytest.mark.parametrize("rate", [500, 6700])
def test_statuses_as_often_as_pythons(burst_classes: Path, tmp_path: Path, signed: bool, rate: int) -> None:
    """As ttctl's Python endpoint (since the one-packet statuses): on a slow link (the M100's
    500 B/s uplink) statuses may go 1.5 statuses' bytes at the rate apart, 0.8 near the end, a
    signature counted; the Java receiver takes the same intervals from its link's rate."""
    from conftest import shipped
    from ttctl.proto.endpoint import Endpoint
    from ttctl.proto.storage import ReceiveDir

    b = shipped()
    signing = b.mavlink.Signing(bytes(32), 1, False) if signed else None
    py = Endpoint(b, 1, 240, mtu=100, rate_Bps=float(rate), signing=signing, receive_dir=ReceiveDir(tmp_path / "py"))
    (tmp_path / "inbox").mkdir()
    proc = subprocess.run(["java", "-cp", str(burst_classes), "ttctl.ttapi.transfer.BurstCheck",
                           str(tmp_path / "inbox"), "100", "signed" if signed else "unsigned", "3", str(rate)],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    got = json.loads(proc.stdout.splitlines()[0])
    assert py.receiver is not None
    assert got == {"min": pytest.approx(py.receiver.cfg.status_min_interval, rel=1e-12),
                   "tail": pytest.approx(py.receiver.cfg.status_tail_interval, rel=1e-12)}


@pytest.mark.parametrize(("mtu", "signed"), [(100, True), (100, False), (128, True)])
def test_maps_to_a_sender_that_reads_them_are_pythons(burst_classes: Path, tmp_path: Path, mtu: int,
                                                      signed: bool) -> None:
    """To an offer with TT_FILE_FLAGS_MAP, the Java receiver reports 400 gaps as TT_FILE_MAPs: bit
    for bit what ttctl's Python receiver builds (proto/reports.py map_regions) from the same
    holdings, each map in one packet of the link, two a report, the first flagged as more follow."""
    from ttctl.proto.reports import map_regions
    from ttctl.proto.transfer import map_bytes

    gaps = 400
    (tmp_path / "inbox").mkdir()
    proc = subprocess.run(["java", "-cp", str(burst_classes), "ttctl.ttapi.transfer.BurstCheck",
                           str(tmp_path / "inbox"), str(mtu), "signed" if signed else "unsigned", str(gaps), "6700",
                           "map"], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    calls = [json.loads(line) for line in proc.stdout.splitlines()][1:]
    reports = [c["statuses"] for c in calls if any("map" in s for s in c["statuses"])]
    assert reports, proc.stdout
    frames = 2 * gaps - 1  # (BurstCheck's holdings with "map": every other 80-byte frame from 0)
    held = [(80 * k, 80 * (k + 1)) for k in range(0, frames, 2)]
    missing = [(a, b) for (_, a), (b, _) in itertools.pairwise(held)]
    want = map_regions(80, held[-1][1], held[-1][0], 80, missing, map_bytes(mtu, signed), 2)
    assert want[0][2][:2] == b"\xaa\xaa"  # a frame missing, one there, ...: the bits alternate
    for report in reports:
        assert all("map" in s for s in report), report
        got = [(s["region_start"], s["received_end"], bytes.fromhex(s["map"])[:map_bytes(mtu, signed)],
                bool(s["flags"] & 1)) for s in report]
        assert got == want, (got[0][:2], want[0][:2])
        assert all(s["len"] <= mtu and s["chunk"] == 80 and s["received_contiguous"] == 80 for s in report), report
