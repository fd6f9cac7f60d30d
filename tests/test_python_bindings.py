"""The generated Python package beyond the conformance protocol: signing (against pymavlink's
implementation), the stream parser under split, lost, corrupted and duplicated chunks, and
clear errors for values that do not fit."""

from __future__ import annotations

import hashlib
import itertools

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from pymavlink.dialects.v20 import common as pm

import ttapi

KEY = hashlib.sha256(b"correct horse battery staple").digest()


def sample_messages() -> list[ttapi.Message]:
    return [
        ttapi.Heartbeat(type=2, autopilot=3, custom_mode=7),
        ttapi.Attitude(10, 0.1, 0.2, 0.3, 0.0, 0.0, 0.0),
        ttapi.TtActionCommand(target_system=1, target_component=240, command_id=77,
                              action=ttapi.TtAction.TT_ACTION_FLY_TRAJECTORY, time_usec=2**60, param=(1.5, 0, 0, 0),
                              argument="mission.yaml"),
        ttapi.TtFileData(transfer_id=3, offset=1 << 20, data=bytes(range(80))),
        ttapi.TtFileDataWide(transfer_id=3, offset=5, data=bytes(range(247))),
        ttapi.Statustext(severity=4, text="hello"),
        ttapi.DjiPoseStamped(target_system=1, sec=5, nsec=6, topic_name=1, position=(1.0, 2.0, 3.0),
                             orientation=(0.0, 0.0, 0.0, 1.0)),
    ]


def test_signed_frames_verify_in_pymavlink() -> None:
    signing = ttapi.Signing(KEY, link_id=7)
    enc = ttapi.Encoder(sysid=42, compid=190, signing=signing)
    mav = pm.MAVLink(None)
    mav.signing.secret_key = KEY
    for msg in sample_messages()[:2] + [sample_messages()[5]]:
        frame = enc.encode(msg)
        assert frame[2] & 0x01 and len(frame) == 12 + frame[1] + 13
        got = mav.parse_buffer(frame)
        assert got and got[0].get_msgId() == msg.MSG_ID and got[0].get_signed()
    assert mav.signing.goodsig_count == 3 and mav.signing.badsig_count == 0


def test_pymavlink_signed_frames_verify_here_and_replays_and_tampering_fail() -> None:
    mav = pm.MAVLink(None, srcSystem=9, srcComponent=1)
    mav.signing.secret_key = KEY
    mav.signing.link_id = 3
    mav.signing.sign_outgoing = True
    mav.signing.timestamp = ttapi.Signing.now()
    frames = [bytes(pm.MAVLink_heartbeat_message(2, 3, 0, 0, 4, 3).pack(mav)) for _ in range(3)]
    parser = ttapi.Parser(signing=ttapi.Signing(KEY))
    got = parser.feed(b"".join(frames))
    assert [m.get_signed() for m in got] == [True, True, True]
    assert parser.feed(frames[1]) == [] and parser.stats.bad_signature == 1  # replay
    tampered = bytearray(frames[2])
    tampered[-1] ^= 0xFF
    assert parser.feed(bytes(tampered)) == [] and parser.stats.bad_signature == 2
    wrong_key = ttapi.Parser(signing=ttapi.Signing(hashlib.sha256(b"other").digest()))
    assert wrong_key.feed(frames[0]) == []


def test_a_new_stream_more_than_a_minute_old_is_refused_as_pymavlink_does() -> None:
    now = ttapi.Signing.now()
    frames = {}
    for name, ts in (("stale", now - 6_000_100), ("recent", now - 5_999_000), ("ahead", now + 10_000_000)):
        mav = pm.MAVLink(None, srcSystem=9, srcComponent=1)
        mav.signing.secret_key = KEY
        mav.signing.sign_outgoing = True
        mav.signing.timestamp = ts
        mav.signing.link_id = len(frames)  # each its own stream
        frames[name] = bytes(pm.MAVLink_heartbeat_message(2, 3, 0, 0, 4, 3).pack(mav))
    ours = ttapi.Signing(KEY, timestamp=now)
    assert ttapi.Parser(signing=ours).feed(frames["stale"]) == []
    oracle = pm.MAVLink(None)
    oracle.signing.secret_key = KEY
    oracle.signing.timestamp = now
    with pytest.raises(pm.MAVError):
        oracle.decode(bytearray(frames["stale"]))
    assert len(ttapi.Parser(signing=ours).feed(frames["recent"])) == 1
    assert len(ttapi.Parser(signing=ours).feed(frames["ahead"])) == 1
    assert ours.timestamp >= now + 10_000_000  # an accepted later clock moves ours forward
    assert ttapi.Parser(signing=ours).feed(frames["recent"]) == []  # now a minute behind ours


def test_unsigned_frames_are_refused_by_a_signing_parser_unless_allowed() -> None:
    frame = ttapi.Heartbeat().pack(0, 1, 1)
    assert ttapi.Parser(signing=ttapi.Signing(KEY)).feed(frame) == []
    assert len(ttapi.Parser(signing=ttapi.Signing(KEY, allow_unsigned=True)).feed(frame)) == 1
    with pytest.raises(ttapi.DecodeError, match="unsigned"):
        ttapi.decode(frame, signing=ttapi.Signing(KEY))


def test_signing_key_must_be_32_bytes() -> None:
    with pytest.raises(ValueError, match="32 bytes"):
        ttapi.Signing(b"short")


@st.composite
def streams(draw: st.DrawFn) -> tuple[list[bytes], bytes]:
    base = sample_messages()
    picks = draw(st.lists(st.sampled_from(range(len(base))), min_size=1, max_size=25))
    enc = ttapi.Encoder(sysid=1, compid=240)
    frames = [enc.encode(base[i]) for i in picks]
    return frames, b"".join(frames)


def chunks_of(data: bytes, cuts: list[int]) -> list[bytes]:
    points = sorted({c % (len(data) + 1) for c in cuts} | {0, len(data)})
    return [data[a:b] for a, b in itertools.pairwise(points) if b > a]


SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=list(HealthCheck))


@SETTINGS
@given(streams(), st.lists(st.integers(0, 10_000), max_size=30))
def test_split_chunks_lose_nothing(stream: tuple[list[bytes], bytes], cuts: list[int]) -> None:
    frames, data = stream
    parser = ttapi.Parser()
    got = [m for c in chunks_of(data, cuts) for m in parser.feed(c)]
    assert [m.pack(m.get_seq(), m.get_srcSystem(), m.get_srcComponent()) for m in got] == frames
    assert parser.pending == 0 and parser.stats.bad_crc == 0


def frame_spans(frames: list[bytes]) -> list[tuple[int, int]]:
    spans, pos = [], 0
    for f in frames:
        spans.append((pos, pos + len(f)))
        pos += len(f)
    return spans


@SETTINGS
@given(streams(), st.lists(st.integers(0, 10_000), min_size=2, max_size=30), st.integers(0, 1000))
def test_a_lost_chunk_costs_only_the_frames_it_overlapped(stream: tuple[list[bytes], bytes], cuts: list[int],
                                                          which: int) -> None:
    frames, data = stream
    chunks = chunks_of(data, cuts)
    lost = which % len(chunks)
    start = sum(len(c) for c in chunks[:lost])
    end = start + len(chunks[lost])
    parser = ttapi.Parser()
    got = [m for i, c in enumerate(chunks) if i != lost for m in parser.feed(c)] + parser.flush()
    untouched = [f for f, (a, b) in zip(frames, frame_spans(frames), strict=True) if b <= start or a >= end]
    delivered = [m.pack(m.get_seq(), m.get_srcSystem(), m.get_srcComponent()) for m in got]
    # every frame the loss did not touch arrives, in order; nothing but sent frames comes out (a
    # touched frame may still arrive: if the loss took only its magic byte, a surviving 0xFD
    # of an earlier frame completes it exactly)
    it = iter(delivered)
    assert all(any(d == f for d in it) for f in untouched)
    assert set(delivered) <= set(frames)


@SETTINGS
@given(streams(), st.integers(0, 100_000), st.integers(1, 255))
def test_a_corrupted_byte_costs_only_its_frame(stream: tuple[list[bytes], bytes], pos: int, flip: int) -> None:
    frames, data = stream
    pos %= len(data)
    bad = bytearray(data)
    bad[pos] ^= flip
    parser = ttapi.Parser()
    got = parser.feed(bytes(bad)) + parser.flush()
    expected = [f for f, (a, b) in zip(frames, frame_spans(frames), strict=True) if not a <= pos < b]
    assert [m.pack(m.get_seq(), m.get_srcSystem(), m.get_srcComponent()) for m in got] == expected


@SETTINGS
@given(streams(), st.lists(st.integers(0, 10_000), min_size=2, max_size=30), st.integers(0, 1000))
def test_a_duplicated_chunk_costs_only_frames_it_splits(stream: tuple[list[bytes], bytes], cuts: list[int],
                                                        which: int) -> None:
    """A repeated chunk interrupts the frames that began before it and end after it; every
    other frame arrives (those inside it possibly twice)."""
    frames, data = stream
    chunks = chunks_of(data, cuts)
    dup = which % len(chunks)
    start = sum(len(c) for c in chunks[:dup])
    end = start + len(chunks[dup])
    parser = ttapi.Parser()
    fed = chunks[: dup + 1] + chunks[dup:]
    got = [m.pack(m.get_seq(), m.get_srcSystem(), m.get_srcComponent())
           for m in [m for c in fed for m in parser.feed(c)] + parser.flush()]
    survivors = [f for f, (a, b) in zip(frames, frame_spans(frames), strict=True) if not (a < start and b > end)]
    it = iter(got)
    assert all(any(g == f for g in it) for f in survivors)  # in order, possibly repeated
    assert set(got) <= set(frames)


def test_garbage_never_raises_and_is_counted() -> None:
    import random

    rng = random.Random(5)
    parser = ttapi.Parser()
    for _ in range(300):
        blob = bytes(rng.getrandbits(8) for _ in range(rng.randint(0, 400)))
        parser.feed(blob.replace(b"\xfd", b"\xfd", 1))
    frame = ttapi.Heartbeat().pack()
    assert len(parser.feed(b"\xfd\x09" + frame)) >= 1
    assert parser.stats.skipped_bytes > 0


@pytest.mark.parametrize(("msg", "needle"), [
    (ttapi.Heartbeat(type=300), "HEARTBEAT"),
    (ttapi.Statustext(text="x" * 51), "STATUSTEXT.text: 51 bytes do not fit char[50]"),
    (ttapi.TtFileData(data=bytes(84)), "TT_FILE_DATA.data: 84 bytes do not fit"),
    (ttapi.DjiPoseStamped(position=(1.0, 2.0)), "DJI_POSE_STAMPED.position: expected 3 values, got 2"),
])
def test_values_that_do_not_fit_are_clear_errors(msg: ttapi.Message, needle: str) -> None:
    with pytest.raises(ValueError, match=needle.replace("[", r"\[").replace("]", r"\]")):
        msg.pack()


def test_truncation_and_extensions_match_pymavlink() -> None:
    mav = pm.MAVLink(None, srcSystem=1, srcComponent=1)
    ours = ttapi.Heartbeat(type=0, autopilot=0, base_mode=0, custom_mode=0, system_status=0, mavlink_version=0)
    ref = pm.MAVLink_heartbeat_message(0, 0, 0, 0, 0, 0).pack(mav)
    assert ours.pack(0, 1, 1) == bytes(ref)
    assert ours.pack()[1] == 1  # all-zero payload keeps one byte
    # SYS_STATUS has extension fields: set only the last one
    msg = ttapi.SysStatus(onboard_control_sensors_health_extended=5)
    frame = msg.pack(0, 1, 1)
    back = ttapi.decode(frame)
    # the extension is last on the wire: its three zero high bytes are truncated
    assert back == msg and frame[1] == ttapi.SysStatus.PAYLOAD_LENGTH - 3


def test_unpack_payload_refuses_oversized_payloads() -> None:
    with pytest.raises(ttapi.DecodeError, match="exceeds"):
        ttapi.Heartbeat.unpack_payload(bytes(10))
    assert ttapi.Heartbeat.unpack_payload(b"\x07").custom_mode == 7


def test_to_dict_from_dict_and_equality() -> None:
    msg = sample_messages()[2]
    again = type(msg).from_dict(msg.to_dict())
    assert again == msg and hash(again) == hash(msg)
    with pytest.raises(ValueError, match="no field"):
        ttapi.Heartbeat.from_dict({"nope": 1})
    nan = ttapi.Attitude(roll=float("nan"))
    assert ttapi.decode(nan.pack()) == nan
