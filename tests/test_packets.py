"""Property tests of the packet layer: packing by the rule, and no collateral loss — a lost,
corrupted, duplicated or displaced packet costs only the frames that overlapped it."""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import ttapi
from conftest import shipped
from ttctl.wire.packets import PacketReceiver, packetize

SETTINGS = settings(max_examples=300, deadline=None, suppress_health_check=list(HealthCheck))


@st.composite
def frame_lists(draw: st.DrawFn) -> list[bytes]:
    enc = ttapi.Encoder(sysid=1, compid=240)
    kinds = st.sampled_from(["heartbeat", "ack", "command", "narrow", "wide"])
    frames = []
    for kind in draw(st.lists(kinds, min_size=1, max_size=40)):
        blob = draw(st.binary(min_size=247, max_size=247))
        if kind == "heartbeat":
            msg: ttapi.Message = ttapi.Heartbeat(type=2, custom_mode=draw(st.integers(0, 2**32 - 1)))
        elif kind == "ack":
            msg = ttapi.TtCommandAck(command_id=draw(st.integers(0, 65535)), result=2, progress=100)
        elif kind == "command":
            msg = ttapi.TtActionCommand(command_id=draw(st.integers(0, 65535)), action=1, argument="x" * 40)
        elif kind == "narrow":
            msg = ttapi.TtFileData(transfer_id=1, offset=draw(st.integers(0, 2**32 - 1)), data=blob[:80])
        else:
            msg = ttapi.TtFileDataWide(transfer_id=1, offset=draw(st.integers(0, 2**32 - 1)), data=blob)
        frames.append(enc.encode(msg))
    return frames


def layout(frames: list[bytes], mtu: int = 100) -> tuple[list[bytes], list[set[int]]]:
    """Packets, and for each frame the packets its bytes are in. Packets are contiguous
    slices of the frame stream, so overlap follows from byte offsets."""
    packets = packetize(frames, mtu)
    starts, pos = [], 0
    for p in packets:
        starts.append((pos, pos + len(p)))
        pos += len(p)
    spans, pos = [], 0
    for f in frames:
        a, b = pos, pos + len(f)
        spans.append({i for i, (s, e) in enumerate(starts) if s < b and a < e})
        pos = b
    return packets, spans


def receive(packets: list[bytes]) -> list[bytes]:
    rx = PacketReceiver(shipped())
    got = [m for p in packets for m in rx.feed(p)] + rx.flush()
    return [m.pack(m.get_seq(), m.get_srcSystem(), m.get_srcComponent()) for m in got]


def check(frames: list[bytes], spans: list[set[int]], faulty: set[int], got: list[bytes]) -> None:
    assert set(got) <= set(frames), "a frame that was never sent came out"
    for f, s in zip(frames, spans, strict=True):
        if not s & faulty:
            assert f in got, "a frame that did not touch a faulty packet was lost"


@SETTINGS
@given(frame_lists(), st.sampled_from([40, 64, 100, 255]))
def test_packing_rule(frames: list[bytes], mtu: int) -> None:
    packets = packetize(frames, mtu)
    assert all(0 < len(p) <= mtu for p in packets)
    assert b"".join(packets) == b"".join(frames)
    # a frame that fits a packet never straddles two
    _, spans = layout(frames, mtu)
    for f, s in zip(frames, spans, strict=True):
        if len(f) <= mtu:
            assert len(s) == 1


@SETTINGS
@given(frame_lists())
def test_clean_link_delivers_everything_in_order(frames: list[bytes]) -> None:
    packets, _ = layout(frames)
    assert receive(packets) == frames


@SETTINGS
@given(frame_lists(), st.sets(st.integers(0, 200)))
def test_lost_packets(frames: list[bytes], lost: set[int]) -> None:
    packets, spans = layout(frames)
    lost = {i % len(packets) for i in lost}
    check(frames, spans, lost, receive([p for i, p in enumerate(packets) if i not in lost]))


def test_flush_gives_up_every_carry_its_replay_begins() -> None:
    """Found by hypothesis: a long frame whose tail is lost takes in the head and the tail of
    the next long frame; when it is given up, replaying those begins another carry, which must
    be given up too, or the small frame after the second tail never comes out."""
    enc = ttapi.Encoder(sysid=1, compid=240)
    frames = [enc.encode(m) for m in (
        ttapi.Heartbeat(type=2),
        ttapi.TtFileDataWide(transfer_id=1, offset=1, data=bytes(range(247))),
        ttapi.TtFileData(transfer_id=1, offset=2, data=b"\x01" * 80),
        ttapi.TtFileDataWide(transfer_id=1, offset=3, data=bytes(range(247))),
        ttapi.TtCommandAck(command_id=7, result=2, progress=100),
        ttapi.TtFileData(transfer_id=1, offset=4, data=b"\x02" * 80),
        ttapi.Heartbeat(type=3),
    )]
    packets, spans = layout(frames)
    lost = (spans[1] - {min(spans[1])}) | spans[2] | (spans[3] - {min(spans[3]), max(spans[3])})
    assert max(spans[3]) in spans[4] and not spans[4] & lost  # the ack shares the second tail's packet
    check(frames, spans, lost, receive([p for i, p in enumerate(packets) if i not in lost]))


def test_a_new_long_frame_gives_up_the_carry_its_replay_begins() -> None:
    """Found by hypothesis: when a packet begins a new long frame, the old carry is dropped and
    its packets replayed; that replay can begin a carry of its own (a long frame with a lost
    middle), whose packets must be replayed too before the new frame takes over, or the
    heartbeat after that frame's tail is lost with it."""
    enc = ttapi.Encoder(sysid=1, compid=240)

    def wide() -> ttapi.Message:
        return ttapi.TtFileDataWide(transfer_id=1, offset=0, data=b"\x01" * 247)

    def cmd() -> ttapi.Message:
        return ttapi.TtActionCommand(command_id=0, action=1, argument="x" * 40)

    def hb() -> ttapi.Message:
        return ttapi.Heartbeat(type=2)

    frames = [enc.encode(m) for m in (cmd(), wide(), hb(), wide(), hb(), wide(), hb(), cmd(), wide(),
                                      ttapi.TtFileData(transfer_id=1, offset=0, data=b"\x01" * 80), hb(), cmd())]
    packets, spans = layout(frames)
    lost = {0, 1, 4, 5, 7, 8, 11}
    assert spans[6] == {9} and not spans[6] & lost  # the heartbeat after the third wide frame's tail
    check(frames, spans, lost, receive([p for i, p in enumerate(packets) if i not in lost]))


def test_a_packet_of_whole_frames_is_not_a_continuation_even_if_the_crc_agrees() -> None:
    """Found by hypothesis: the middle packet of a long frame is lost and the next packet (a
    frame of its own) fills exactly what is missing. The offset below is one of the 1 in 65536
    for which that false assembly passes the CRC; the packet's own frame must still win."""
    wide = ttapi.TtFileDataWide(transfer_id=1, offset=15619, data=bytes(range(1, 248))).pack(0, 1, 240)
    narrow = ttapi.TtFileData(transfer_id=1, offset=5, data=b"\x07" * 80).pack(1, 1, 240)
    packets, spans = layout([wide, narrow])
    assert [len(p) for p in packets] == [100, 100, 67, 100]
    assert ttapi.decode(packets[0] + packets[2] + packets[3]).get_seq() == 0  # the chance match
    check([wide, narrow], spans, {1}, receive([packets[0], packets[2], packets[3]]))


@SETTINGS
@given(frame_lists(), st.integers(0, 10_000), st.integers(0, 200), st.integers(1, 255))
def test_corrupted_packet(frames: list[bytes], which: int, pos: int, flip: int) -> None:
    packets, spans = layout(frames)
    which %= len(packets)
    bad = bytearray(packets[which])
    bad[pos % len(bad)] ^= flip
    packets[which] = bytes(bad)
    check(frames, spans, {which}, receive(packets))


@SETTINGS
@given(frame_lists(), st.integers(0, 10_000))
def test_duplicated_packet(frames: list[bytes], which: int) -> None:
    packets, spans = layout(frames)
    which %= len(packets)
    got = receive(packets[: which + 1] + packets[which:])
    check(frames, spans, {which}, got)


@SETTINGS
@given(frame_lists(), st.integers(0, 10_000))
def test_adjacent_packets_swapped(frames: list[bytes], which: int) -> None:
    packets, spans = layout(frames)
    if len(packets) < 2:
        return
    i = which % (len(packets) - 1)
    packets[i], packets[i + 1] = packets[i + 1], packets[i]
    check(frames, spans, {i, i + 1}, receive(packets))


@SETTINGS
@given(frame_lists(), st.integers(0, 10_000))
def test_urgent_packet_between_pieces_of_a_long_frame(frames: list[bytes], where: int) -> None:
    """The sender may slip a self-contained packet of urgent frames into a long frame."""
    packets, _ = layout(frames)
    urgent = ttapi.Encoder(sysid=9, compid=9).encode(ttapi.TtCommandAck(command_id=4242, result=0))
    i = where % (len(packets) + 1)
    got = receive(packets[:i] + [urgent] + packets[i:])
    assert sorted(got) == sorted(frames + [urgent])


def test_zero_byte_packets_are_ignored() -> None:
    rx = PacketReceiver(shipped())
    assert rx.feed(b"") == [] and rx.stats.packets == 1


def test_probing_a_packet_for_its_own_frame_does_not_use_up_its_signature() -> None:
    """An urgent signed packet slipped between the pieces of a signed long frame: the receiver
    checks whether the packet starts with a whole frame before taking it for the continuation;
    that check must not record the frame's timestamp, or the frame is refused as a replay when
    delivered a moment later."""
    key = bytes(range(32))
    bulk = ttapi.Signing(key, link_id=0)
    urgent = ttapi.Signing(key, link_id=1)  # another stream (the same one would be a replay: it is newer)
    data = ttapi.TtFileDataWide(transfer_id=9, offset=0, data=bytes(range(1, 248)))
    wide = ttapi.Encoder(255, 190, bulk).encode(data)
    ack = ttapi.Encoder(255, 190, urgent).encode(ttapi.TtCommandAck(command_id=1, result=0))
    assert len(wide) == 280
    pieces = [wide[:100], wide[100:200], wide[200:]]
    rx = PacketReceiver(shipped(), signing=ttapi.Signing(key))
    got = [m for pkt in (pieces[0], ack, pieces[1], pieces[2]) for m in rx.feed(pkt)]
    assert sorted(type(m).__name__ for m in got) == ["TtCommandAck", "TtFileDataWide"]
    assert rx.stats.bad_frames == 0
