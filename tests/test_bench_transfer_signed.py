"""`ttctl bench transfer`'s signed rows: ttctl with MAVLink 2 signing at both ends, judged against
what signed frames allow (under loss a signed TT_FILE_DATA_FIT fills one packet: 66 file bytes in
100 on DJI's DTT, 94 in the Payload SDK channel's 128)."""

from __future__ import annotations

import json
from typing import Any

import pytest

from conftest import assert_no_traceback, run_ttctl
from ttctl.bench import transfer as T
from ttctl.link.model import Channel, load_profile

M100 = load_profile("m100")


def test_signed_ceiling_is_one_packet_per_narrow_frame() -> None:
    assert T.signed_ceiling(0.0) == pytest.approx(247 / 280)
    assert T.signed_ceiling(0.1) == pytest.approx(66 / 100 * 0.9)
    assert T.signed_ceiling(0.3) == pytest.approx(66 / 100 * 0.7)
    assert T.signed_ceiling(0.1, 128) == pytest.approx(94 / 128 * 0.9)
    for p in (0.1, 0.3):  # above the two-packet TT_FILE_DATA's 80/113 (1 - p)^2, below the unsigned frames'
        assert 80 / 113 * (1 - p) ** 2 < T.signed_ceiling(p) < T.unsigned_ceiling(p) == pytest.approx(0.8 * (1 - p))
    assert T.unsigned_ceiling(0.1, 128) == pytest.approx(107 / 128 * 0.9)


def test_signed_rows_are_signed_and_near_their_ceiling(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every frame on the wire carries a signature (incompat flag 0x01), the narrow data frames
    fill one 100-byte packet each, and the row reaches 0.95 of the signed ceiling."""
    seen: list[bytes] = []
    real = T.channels

    def spy(*args: Any, **kw: Any) -> tuple[Channel, Channel]:
        chans = real(*args, **kw)
        for ch in chans:
            submit = ch.submit

            def record(t: float, packet: bytes, submit: Any = submit) -> list[tuple[float, bytes]]:
                seen.append(packet)
                return submit(t, packet)

            ch.submit = record  # type: ignore[method-assign]
        return chans

    monkeypatch.setattr(T, "channels", spy)
    row = T.run_case("ttctl-signed", M100, 10.0, T.Case("up", 0.1, "random"), 16384, [1, 2, 3])
    assert row.ok
    starts = [p for p in seen if p[0] == 0xFD]
    assert len(starts) > 200 and all(p[2] & 0x01 for p in starts)  # signed, every one
    fits = [p for p in starts if len(p) == 100 and int.from_bytes(p[7:10], "little") == 50014]
    assert len(fits) > 150 and not any(len(p) == 13 for p in seen)  # one packet each, nothing spills
    assert row.ceiling == pytest.approx(T.signed_ceiling(row.realised_loss), abs=1e-4)
    assert row.of_frame_ceiling is not None and row.of_frame_ceiling >= T.SIGNED_FLOOR, row
    unsigned = T.run_case("ttctl", M100, 10.0, T.Case("up", 0.1, "random"), 16384, [1, 2, 3])
    assert row.efficiency < unsigned.efficiency  # the signatures cost air


def test_a_signed_row_below_its_floor_fails_the_bench() -> None:
    row = T.Row("ttctl-signed", "down", 0.3, "random", 65536, 37.0, 1771.2, 6700.0, 0.2644, True, 9, 0.3,
                0.76, 0.3469)
    (check,) = [c for c in T.checks([row], []) if c["check"].startswith("signed")]
    assert check == {"check": "signed down 30% random of its ceiling", "value": 0.76, "floor": 0.95, "ok": False}


def test_bench_transfer_prints_and_judges_signed_rows() -> None:
    proc = run_ttctl("bench", "transfer", "--quick", "--seeds", "1", "--protocols", "ttctl,ttctl-signed", "--size",
                     "8192", "--json", timeout=300)
    assert_no_traceback(proc)
    report = json.loads(proc.stdout)
    signed = [r for r in report["rows"] if r["protocol"] == "ttctl-signed"]
    assert [(r["direction"], r["loss"]) for r in signed] == [("up", 0.0), ("up", 0.1)]
    assert all(r["ok"] and r["ceiling"] and r["of_frame_ceiling"] for r in signed)
    assert report["frame_efficiency"]["narrow_signed"] == round(66 / 100, 4)
    checks = [c for c in report["checks"] if c["check"].startswith("signed")]
    assert len(checks) == 2 and all(c["floor"] == 0.95 for c in checks)
    assert proc.returncode == (0 if all(c["ok"] for c in report["checks"]) else 1)


def test_signed_statuses_fit_one_packet_and_say_more_follows(tmp_path: Any) -> None:
    """A signed status listing 7 gaps is 115 bytes: over two 100-byte packets, lost when either
    is. The receiver lists as many gaps as fit one packet (5 signed, 6 unsigned on DJI's DTT; 7 in
    the Payload SDK channel's 128) and sets range_count's top bit on every status of a burst but the
    last, so a sender takes the bytes past received_end as unknown, not missing."""
    from ttctl.bench import shipped
    from ttctl.proto.endpoint import Endpoint
    from ttctl.proto.storage import ReceiveDir
    from ttctl.proto.transfer import MAX_RANGES, RANGES_MORE, ranges_per_status

    assert (ranges_per_status(100, True), ranges_per_status(100, False), ranges_per_status(128, True)) == (5, 6, 7)
    b = shipped.bindings()
    for signed, per in ((True, 5), (False, 6)):
        ep = Endpoint(b, 255, 190, mtu=100, rate_Bps=500, receive_dir=ReceiveDir(tmp_path / str(signed)),
                      signing=b.signing(T.BENCH_KEY) if signed else None)
        assert ep.receiver is not None and ep.receiver.ranges_per_status == per
        # as many gaps a report as three 7-gap statuses held, in one-packet statuses
        assert ep.receiver.cfg.status_batches == -(-3 * MAX_RANGES // per)
        ep.close()
    # what a status of a burst looks like on the wire, and how each sender reads it
    status = b.TtFileStatus(target_system=1, target_component=240, transfer_id=7, result=0, received_contiguous=0,
                            region_start=0, received_end=1000, last_offset=0, hold_ms=0,
                            range_count=5 | RANGES_MORE, meta_check=0,
                            ranges=[100, 166, 200, 266, 300, 366, 400, 466, 934, 1000] + [0] * 4)
    assert status.range_count & ~RANGES_MORE == 5
    signed = b.encoder(255, 190).encode(status)
    assert len(signed) + 13 <= 100  # (its signature is 13 bytes more): one packet


def test_a_sender_resends_only_the_gaps_of_a_status_that_says_more_follow() -> None:
    """Python's sender (and the C++ and Java ones, whose tests run the same link) keeps the bytes
    past received_end of a flagged status as unknown: it resends the five gaps, not the rest of the
    file; without the flag, five gaps would mean "nothing else is missing up to what I was sent"."""
    from ttctl.bench import shipped
    from ttctl.proto.sender import FileSender
    from ttctl.proto.storage import BytesSource
    from ttctl.proto.transfer import RANGES_MORE, TransferConfig

    b = shipped.bindings()

    def resent(flag: int) -> int:
        s = FileSender(b, lambda: 7, BytesSource(bytes(4000), "x.bin"), "x.bin", (1, 240), TransferConfig(),
                       compress=False)
        s.state = "sending"
        for _ in range(50):  # the whole file leaves once
            s.next_data(0.0, 100)
            if s.next_new >= s.size:
                break
        gaps = [80, 160, 240, 320, 400, 480, 560, 640, 720, 800]
        msg = b.TtFileStatus(target_system=255, target_component=190, transfer_id=s.id, result=0,
                             received_contiguous=80, region_start=80, received_end=800, last_offset=720,
                             hold_ms=65535, range_count=5 | flag, meta_check=0, ranges=gaps + [0] * 4)
        s._apply_status(10.0, msg)
        return s.retx.total()

    assert resent(RANGES_MORE) == 5 * 80  # the five gaps
    assert resent(0) == 5 * 80 + (4000 - 800)  # and everything past received_end, as missing


def test_tail_repeats_do_not_count_as_first_sends() -> None:
    """Once every byte has left, the sender repeats the unacknowledged ones while it waits for
    statuses; those repeats often arrive twice, so counted as first sends they made the measured
    loss near 0 and the sender chose three-packet frames at 30 % loss (0.78 of the ceiling)."""
    from ttctl.bench import shipped
    from ttctl.proto.sender import FileSender
    from ttctl.proto.storage import BytesSource
    from ttctl.proto.transfer import TransferConfig

    s = FileSender(shipped.bindings(), lambda: 7, BytesSource(bytes(800), "x.bin"), "x.bin", (1, 240),
                   TransferConfig(), compress=False)
    s.state = "sending"
    t = 0.0
    while s.next_new < s.size:
        assert s.next_data(t, 100) is not None
        t += 0.02
    first = len(s.frame_loss._unclassified)
    repeats = 0
    for _ in range(30):
        t += 0.5
        repeats += s.next_data(t, 100) is not None
    assert repeats > 5 and len(s.frame_loss._unclassified) == first == 10
