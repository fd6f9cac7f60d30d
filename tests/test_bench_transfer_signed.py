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
