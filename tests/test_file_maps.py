"""TT_FILE_MAP: a receiver's gaps as a bit per frame, sent instead of TT_FILE_STATUS's ranges when
a report would need more than one status and the sender said (TT_FILE_FLAGS_MAP) that it reads
maps. At 30 % loss a signed status lists 5 gaps while 20 frames a second are lost down the m100
link; a map describes 336 frames in one packet. Checked here: a map says exactly which frames
arrived (never a missing byte as arrived), it fits one packet, a sender acknowledges from it
only what arrived, a receiver from before maps (which refuses the flag) still gets the file, and
the bench's signed downlink rows reach their floor."""

from __future__ import annotations

import random
from pathlib import Path
from typing import Any

import pytest

import ttapi
from conftest import shipped
from test_proto import ONBOARD, TABLET, World, data
from ttctl.bench import transfer as T
from ttctl.link.model import Channel, load_profile
from ttctl.proto.frame_loss import FrameLoss
from ttctl.proto.ranges import RangeSet
from ttctl.proto.receiver import MAP
from ttctl.proto.reports import map_gaps
from ttctl.proto.sender import FileSender
from ttctl.proto.storage import BytesSource, ReceiveDir
from ttctl.proto.transfer import MAP_MAX, MAP_MORE, Geometry, TransferConfig, map_bytes

M100 = load_profile("m100")


def bits_of(m: Any) -> list[bool]:
    """The map's bits as the test reads them, independently of map_gaps."""
    raw = bytes(m.map)
    return [bool(raw[i // 8] >> (i % 8) & 1) if i // 8 < len(raw) else False for i in range(8 * MAP_MAX)]


def test_map_gaps_reads_clear_bits_and_truncated_bytes_as_missing() -> None:
    # chunks of 66 from 1000: bits 0, 1, 3 set; 2 clear; 4.. clear (bytes truncated away)
    assert map_gaps(1000, 1000 + 5 * 66 - 10, 66, bytes([0b1011])) == [(1132, 1198), (1264, 1320)]
    assert map_gaps(0, 200, 100, b"\x03") == []
    assert map_gaps(0, 200, 100, b"") == [(0, 200)]
    assert map_gaps(0, 0, 66, b"\xff") == []


def test_a_map_fits_one_packet_signed_or_not() -> None:
    b = shipped()
    for mtu, signed in ((100, True), (100, False), (128, True), (128, False)):
        n = map_bytes(mtu, signed)
        m = b.TtFileMap(target_system=1, target_component=240, transfer_id=7, meta_check=9, received_contiguous=0,
                        region_start=0, received_end=n * 8 * 66, last_offset=0, hold_ms=0, chunk=66, rate_grant=0,
                        flags=0, map=[0xFF] * n + [0] * (MAP_MAX - n))
        frame = b.encoder(1, 240).encode(m)
        assert len(frame) + (13 if signed else 0) <= mtu, (mtu, signed, len(frame))
    assert map_bytes(100, True) == 42 and map_bytes(100, False) == 52  # 336 and 416 frames a map


def _receiver_with_gaps(tmp: Path, rng: random.Random, flags: int, frames: int = 600, loss: float = 0.3,
                        per_packet: int = 66) -> tuple[Any, Any, FileSender, list[int]]:
    """A FileReceiver that took an offer from a FileSender (flags forced) and got its first
    sends with `loss`; returns the receiver, the transfer, the sender and the lost offsets."""
    from ttctl.proto.receiver import FileReceiver

    b = shipped()
    body = data(frames * per_packet, rng.randrange(1 << 30))
    s = FileSender(b, lambda: 77, BytesSource(body, "m.bin"), "m.bin", ONBOARD, TransferConfig(), compress=False)
    s.flags = flags  # (what the offer carries)
    rx = FileReceiver(b, ReceiveDir(tmp), *ONBOARD)
    rx.ranges_per_status, rx.map_bytes = 5, map_bytes(100, True)
    enc, parser = b.encoder(*TABLET), b.parser()
    now = 0.0
    for m in s.offer_messages():
        for got in parser.feed(enc.encode(m)):
            rx.on_offer(now, got)
    statuses = [m for m, _ in rx.control(now)]
    [t] = rx.transfers.values()
    assert t.partial is not None and statuses[-1].result == ttapi.TtFileResult.TT_FILE_RESULT_IN_PROGRESS
    for m in statuses:
        s.on_status(now, m)
    s.mode = "narrow"
    lost = []
    while s.next_new < s.size:
        now += 0.015
        msg = s.next_data(now, 100)
        assert msg is not None
        if rng.random() < loss:
            lost.append(msg.offset)
            continue
        for got in parser.feed(enc.encode(msg)):
            rx.on_data(now, got, got.count if got.NAME == "TT_FILE_DATA_FIT" else 80)
    rx.now = now
    return rx, t, s, lost


@pytest.mark.parametrize("seed", range(8))
def test_a_map_says_exactly_which_frames_arrived_and_the_sender_acks_only_those(tmp_path: Path, seed: int) -> None:
    rng = random.Random(seed)
    rx, t, s, lost = _receiver_with_gaps(tmp_path, rng, MAP, frames=rng.choice([100, 600, 1200]),
                                         loss=rng.choice([0.2, 0.3, 0.6]))
    maps = rx.statuses(t)
    have: RangeSet = t.partial.ranges
    gaps = have.gaps(have.prefix(), max(b for _, b in have))
    if len(gaps) <= 5:  # one status holds them: ranges (as test_few_gaps_go_as_a_status...)
        assert [m.NAME for m in maps] == ["TT_FILE_STATUS"]
        return
    assert maps and all(m.NAME == "TT_FILE_MAP" for m in maps), [m.NAME for m in maps]
    seen_to = 0
    for k, m in enumerate(maps):
        assert m.received_contiguous == have.prefix() and m.chunk == 80  # the sender's frames (unsigned here)
        assert m.region_start <= max(m.received_contiguous, seen_to)  # successive regions, nothing skipped
        assert bool(m.flags & MAP_MORE) == (k < len(maps) - 1 or m.received_end < max(b for _, b in have))
        bits = bits_of(m)
        for i, a in enumerate(range(m.region_start, m.received_end, m.chunk)):
            e = min(a + m.chunk, m.received_end)
            assert bits[i] == have.covers(a, e), (k, a, e)  # set exactly when the chunk arrived whole
        seen_to = m.received_end
    # the sender takes from them only what arrived: nothing lost is acknowledged, every arrival is
    for m in maps:
        s.on_map(rx.now + 0.2, m)
    for off in lost:
        assert not s.acked.covers(off, off + 1), off
    for a, b in have:
        if b <= seen_to:
            assert s.acked.covers(a, b), (a, b)


def test_without_the_flag_the_receiver_lists_ranges(tmp_path: Path) -> None:
    rx, t, _, lost = _receiver_with_gaps(tmp_path, random.Random(3), 0)
    out = rx.statuses(t)
    assert len(lost) > 20 and out and all(m.NAME == "TT_FILE_STATUS" for m in out)


def test_few_gaps_go_as_a_status_even_to_a_sender_that_reads_maps(tmp_path: Path) -> None:
    rx, t, _, lost = _receiver_with_gaps(tmp_path, random.Random(4), MAP, frames=60, loss=0.05)
    assert 0 < len(lost) <= 5
    assert [m.NAME for m in rx.statuses(t)] == ["TT_FILE_STATUS"]


def test_a_receiver_from_before_maps_refuses_the_flag_and_still_gets_the_file(tmp_path: Path) -> None:
    """A receiver that does not know TT_FILE_FLAGS_MAP (as ttctl's before it) refuses the offer
    as REFUSED_UNSUPPORTED, naming the flag; the sender offers again without it, under a new id,
    and the file arrives over ranges alone."""
    w = World(tmp_path, loss=0.3, tablet_dir=tmp_path / "in")
    assert w.tablet.receiver is not None
    w.tablet.receiver.known_flags &= ~MAP
    body = data(20_000, 5)
    s = w.onboard.send_file("old.bin", TABLET, source=BytesSource(body, "old.bin"))
    maps = []
    submit = w.up.submit

    def spy(t: float, packet: bytes) -> list[tuple[float, bytes]]:
        maps.extend(m for m in shipped().parser().feed(packet) if m.NAME == "TT_FILE_MAP")
        return submit(t, packet)

    w.up.submit = spy  # type: ignore[method-assign]
    w.run(600, stop=lambda: s.done)
    assert s.result is not None and s.result.ok, s.result
    assert (tmp_path / "in" / "old.bin").read_bytes() == body
    assert not s.flags & MAP and not maps


def test_maps_carry_a_lossy_signed_download_whole(tmp_path: Path) -> None:
    w = World(tmp_path, loss=0.3, tablet_dir=tmp_path / "in", key=bytes(range(32)))
    body = data(40_000, 6)
    s = w.onboard.send_file("maps.bin", TABLET, source=BytesSource(body, "maps.bin"))
    names: list[str] = []
    submit = w.up.submit

    def spy(t: float, packet: bytes) -> list[tuple[float, bytes]]:
        assert len(packet) <= 100
        names.extend(m.NAME for m in shipped().parser().feed(packet))
        return submit(t, packet)

    w.up.submit = spy  # type: ignore[method-assign]
    w.run(600, stop=lambda: s.done)
    assert s.result is not None and s.result.ok, s.result
    assert (tmp_path / "in" / "maps.bin").read_bytes() == body
    assert names.count("TT_FILE_MAP") > 10, names.count("TT_FILE_MAP")


def test_signed_downlink_at_30_percent_loss_reaches_its_floor_with_maps() -> None:
    """The bench's own rows (virtual time, seeds 1..9, 64 KiB), random and burst: 0.935 and 0.965
    of the signed ceiling with ranges alone (random missed the 0.95 floor), 0.975 and 0.977 now."""
    seen: dict[str, int] = {"maps": 0}
    real = T.channels

    def spy(*args: Any, **kw: Any) -> tuple[Channel, Channel]:
        up, down = real(*args, **kw)
        submit = up.submit

        def record(t: float, packet: bytes) -> list[tuple[float, bytes]]:
            seen["maps"] += sum(m.NAME == "TT_FILE_MAP" for m in shipped().parser().feed(packet))
            return submit(t, packet)

        up.submit = record  # type: ignore[method-assign]
        return up, down

    T.channels = spy  # type: ignore[assignment]
    try:
        rows = [T.run_case("ttctl-signed", M100, 10.0, T.Case("down", 0.3, model), 65536, list(range(1, 10)))
                for model in ("random", "burst")]
    finally:
        T.channels = real  # type: ignore[assignment]
    for row in rows:
        assert row.ok and row.of_frame_ceiling is not None and row.of_frame_ceiling >= T.SIGNED_FLOOR, row
    assert seen["maps"] > 200


def test_wide_frames_need_the_longer_window_too() -> None:
    """Under bursts of loss a second without one is common: 192 narrow first sends at 30 % loss,
    then 64 with one lost. The latest 64 alone say 1.6 %, and wide frames would pay; the latest
    256 say 23 %, so the sender stays narrow. Once wide, the latest 64 bring it back."""
    g = Geometry(100)
    fl = FrameLoss()
    rng = random.Random(2)
    when = 0.0
    for k in range(256):
        when += 0.015
        fl._outcome("narrow", when, rng.random() < 0.3 if k < 192 else k == 200)
    fl.classify(0.0, 0, False, [], g)
    assert fl.loss["narrow"] is not None and fl.loss["narrow"] < 0.08 < (fl.long_loss or 0)
    assert fl.best("narrow", g) == "narrow"
    calm = FrameLoss()
    for k in range(256):
        calm._outcome("narrow", k * 0.015, k % 100 == 0)
    calm.classify(0.0, 0, False, [], g)
    assert calm.best("narrow", g) == "wide"  # a calm link: wide frames, as before
    assert fl.best("wide", g) == "wide"  # (the 64 latest alone judge the way back)


def test_a_map_longer_than_its_bits_costs_no_more_than_its_bits() -> None:
    """A stranger's map (chunk 1, a region of 4 GB): the bits it has are read, the rest is one
    missing range, in time bounded by the map's bytes, not by the region."""
    assert map_gaps(0, 4_000_000_000, 1, b"\xff" * 52) == [(416, 4_000_000_000)]
    assert map_gaps(0, 4_000_000_000, 1, b"\xff" * 51 + b"\x7f") == [(415, 4_000_000_000)]
    assert map_gaps(10, 30, 1, b"") == [(10, 30)]
