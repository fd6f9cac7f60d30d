"""The promise of a transfer, sans-IO: COMPLETE (exit 0 of send-file) only for the very transfer
that was offered, with many senders of equal MAVLink ids at once, stale state, collisions of
transfer ids, names the receiver cannot take, and strangers on the link.

Ends talk over `Bus`: lossless and instant, in virtual time, with each packet's source, so
that several senders (one per process, in real life) share one receiver."""

from __future__ import annotations

import hashlib
import os
import random
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

import ttapi
from conftest import shipped
from ttctl.proto.endpoint import Endpoint
from ttctl.proto.names import MAX_NAME_BYTES, Refused, check_name
from ttctl.proto.sender import FileSender
from ttctl.proto.storage import BytesSource, Quota, ReceiveDir
from ttctl.proto.transfer import META_PART, TransferConfig, meta_check

TABLET, ONBOARD = (255, 190), (1, 240)


def data(n: int, seed: int = 1) -> bytes:
    return random.Random(seed).randbytes(n)


class Bus:
    """One receiving end (`hub`) and any number of other ends around it. Every packet reaches
    its destination at once, tagged with where it came from; the hub's packets reach every
    other end (as a udpin end answers every peer)."""

    def __init__(self, hub: Endpoint, spokes: list[Endpoint]) -> None:
        self.hub = hub
        self.spokes = spokes
        self.now = 0.0
        self.tap: Callable[[int, bytes], bytes | None] | None = None  # may drop or change a spoke's packet

    def run(self, until: float, stop: Callable[[], bool] | None = None) -> float:
        while self.now <= until:
            busy = True
            while busy:
                busy = False
                for i, s in enumerate(self.spokes):
                    for _ in range(64):
                        pkt = s.poll(self.now)
                        if pkt is None:
                            break
                        busy = True
                        if self.tap is not None:
                            pkt = self.tap(i, pkt)
                        if pkt is not None:
                            self.hub.receive(self.now, pkt, source=i)
                for _ in range(64):
                    pkt = self.hub.poll(self.now)
                    if pkt is None:
                        break
                    busy = True
                    for s in self.spokes:
                        s.receive(self.now, pkt, source="hub")
                if stop is not None and stop():
                    return self.now
            times = [w for e in [self.hub, *self.spokes] if (w := e.wakeup()) is not None and w > self.now]
            if not times:
                break
            self.now = min(times)
            for e in [self.hub, *self.spokes]:
                e.now = self.now
        return self.now


def receiver(root: Path, events: list[tuple[str, Any, Any]] | None = None, quota: Quota | None = None,
             config: TransferConfig | None = None, **kw: Any) -> Endpoint:
    def log(what: str, obj: Any) -> None:
        if events is not None:
            events.append((what, obj, getattr(obj, "reason", None)))  # the reason as it was then

    return Endpoint(shipped(), *ONBOARD, receive_dir=ReceiveDir(root, quota), on_event=log, config=config,
                    rng=random.Random(99), **kw)


def tablet(seed: int | None = None, config: TransferConfig | None = None, **kw: Any) -> Endpoint:
    return Endpoint(shipped(), *TABLET, rng=random.Random(seed) if seed is not None else None, config=config, **kw)


def send(ep: Endpoint, name: str, payload: bytes, **kw: Any) -> FileSender:
    return ep.send_file(name, ONBOARD, name=name, source=BytesSource(payload, name), **kw)


def sha(b: bytes) -> str:
    return hashlib.sha256(b).hexdigest()


# -- the defect as reported: a new process's transfer taken for an earlier one -------------------

@pytest.mark.parametrize("same_seed", [False, True])
def test_a_new_sender_never_gets_an_earlier_transfers_complete(tmp_path: Path, same_seed: bool) -> None:
    """Two send-file processes, one after the other, same ids, same size, same name length, other
    bytes. With `same_seed` both draw the same transfer id (what every process numbering from 1
    did): the status's metadata check tells the second that the receiver's answer is not its own."""
    root = tmp_path / "in"
    hub = receiver(root)
    a = tablet(seed=7)
    alpha = send(a, "alpha1.bin", data(4502, 1))
    Bus(hub, [a]).run(60, lambda: alpha.done)
    assert alpha.result is not None and alpha.result.ok
    b = tablet(seed=7 if same_seed else 8)
    bravo = send(b, "bravo2.bin", data(4502, 2))
    assert (bravo.id == alpha.id) == same_seed
    Bus(hub, [b]).run(60, lambda: bravo.done)
    assert bravo.result is not None and bravo.result.ok, bravo.result
    assert bravo.result.stats.resumed_bytes == 0 and not bravo.result.nothing_sent
    assert (root / "bravo2.bin").read_bytes() == data(4502, 2)
    assert (root / "alpha1.bin").read_bytes() == data(4502, 1)


def test_an_edited_file_of_the_same_size_replaces_the_old_one(tmp_path: Path) -> None:
    root = tmp_path / "in"
    hub = receiver(root, quota=Quota(overwrite=True))
    old, new = b"speed: 2.0\nalt: 10\n", b"speed: 3.5\nalt: 10\n"
    for content, seed in ((old, 1), (new, 1)):  # the same seed: the same transfer id again
        t = tablet(seed=seed)
        s = send(t, "mission.yaml", content, overwrite=True)
        Bus(hub, [t]).run(60, lambda s=s: s.done)  # type: ignore[misc]
        assert s.result is not None and s.result.ok and s.result.message.endswith("delivered and verified")
        assert (root / "mission.yaml").read_bytes() == content


def test_an_identical_file_is_verified_there_without_sending(tmp_path: Path) -> None:
    root = tmp_path / "in"
    root.mkdir()
    (root / "same.bin").write_bytes(data(5000))
    events: list[tuple[str, Any, Any]] = []
    hub = receiver(root, events)
    t = tablet()
    s = send(t, "same.bin", data(5000))
    Bus(hub, [t]).run(60, lambda: s.done)
    assert s.result is not None and s.result.ok and s.result.nothing_sent and s.stats.bytes_sent == 0
    other = send(t, "same.bin", data(5000, 2))  # a different file of that name is still refused
    Bus(hub, [t]).run(120, lambda: other.done)
    assert other.result is not None and other.result.code == "REFUSED_EXISTS"
    assert [w for w, _, _ in events] == ["file-complete", "file-refused"]


# -- many senders at once --------------------------------------------------------------------------

def test_eight_senders_with_equal_ids_at_once_each_verified(tmp_path: Path) -> None:
    root = tmp_path / "in"
    hub = receiver(root)
    ends = [tablet() for _ in range(8)]
    files = {f"f{i}.bin": data(3000 + 997 * i, i) for i in range(8)}
    senders = [send(e, n, b) for e, (n, b) in zip(ends, files.items(), strict=True)]
    Bus(hub, ends).run(300, lambda: all(s.done for s in senders))
    assert all(s.result and s.result.ok for s in senders), [s.result for s in senders]
    for n, b in files.items():
        assert (root / n).read_bytes() == b
    assert len({s.id for s in senders}) == 8


def test_a_ninth_sender_waits_for_room_then_goes(tmp_path: Path) -> None:
    root = tmp_path / "in"
    events: list[tuple[str, Any, Any]] = []
    hub = receiver(root, events, config=TransferConfig(offer_interval_max=1.0))
    ends = [tablet(rate_Bps=20_000.0) for _ in range(9)]
    senders = [send(e, f"f{i}.bin", data(20_000, i)) for i, e in enumerate(ends)]
    Bus(hub, ends).run(600, lambda: all(s.done for s in senders))
    assert all(s.result and s.result.ok for s in senders), [s.result for s in senders]
    waited = [reason for w, _, reason in events if w == "file-busy"]
    assert waited == ["8 transfers are running here"]


def test_the_same_name_with_other_bytes_waits_and_is_then_refused(tmp_path: Path) -> None:
    root = tmp_path / "in"
    hub = receiver(root)
    a, b = tablet(rate_Bps=20_000.0), tablet(rate_Bps=20_000.0)
    first = send(a, "m.yaml", data(30_000, 1))
    second = send(b, "m.yaml", data(30_000, 2))
    Bus(hub, [a, b]).run(300, lambda: first.done and second.done)
    assert first.result is not None and first.result.ok
    assert second.result is not None and second.result.code == "REFUSED_EXISTS"
    assert second.result.message == "m.yaml exists and overwriting is not allowed here"
    assert (root / "m.yaml").read_bytes() == data(30_000, 1)


def test_the_same_file_from_two_senders_is_received_once_for_both(tmp_path: Path) -> None:
    root = tmp_path / "in"
    hub = receiver(root)
    a, b = tablet(rate_Bps=20_000.0), tablet(rate_Bps=20_000.0)
    payload = data(60_000)
    one = send(a, "m.bin", payload)
    bus = Bus(hub, [a, b])
    bus.run(1.5)  # about half of it is there
    two = send(b, "m.bin", payload)
    bus.run(300, lambda: one.done and two.done)
    assert one.result and one.result.ok and two.result and two.result.ok
    assert (root / "m.bin").read_bytes() == payload
    # one partial file takes both senders' bytes: the second started where the first had got to
    assert two.stats.resumed_bytes > 20_000 and two.stats.bytes_sent < 45_000


def test_a_restarted_sender_resumes_into_its_earlier_self_s_partial(tmp_path: Path) -> None:
    root = tmp_path / "in"
    hub = receiver(root)
    payload = data(50_000)
    first_end = tablet(rate_Bps=10_000.0)
    first = send(first_end, "big.bin", payload)
    Bus(hub, [first_end]).run(2.0)
    assert 5000 < first.acked_bytes < 40_000
    first_end.close()  # killed: the receiver still holds its transfer as live
    again_end = tablet(rate_Bps=10_000.0)
    again = send(again_end, "big.bin", payload)
    Bus(hub, [again_end]).run(120, lambda: again.done)
    assert again.result is not None and again.result.ok
    assert again.stats.resumed_bytes >= first.acked_bytes
    assert (root / "big.bin").read_bytes() == payload


# -- refusals: the receiver's reasons, before any data ---------------------------------------------

def test_a_name_under_a_file_is_refused_at_the_offer(tmp_path: Path) -> None:
    root = tmp_path / "in"
    root.mkdir()
    (root / "sub").write_text("a file, not a folder")
    hub = receiver(root, quota=Quota(overwrite=True))
    t = tablet()
    s = send(t, "sub/x.bin", data(5000), overwrite=True)
    Bus(hub, [t]).run(60, lambda: s.done)
    assert s.result is not None and s.result.code == "REFUSED_NAME"
    assert s.result.message == "sub exists here and is a file, not a directory"
    assert s.stats.bytes_sent == 0


@pytest.mark.parametrize("kind", ["directory", "fifo", "symlink-out"])
def test_what_is_not_a_regular_file_is_never_replaced(tmp_path: Path, kind: str) -> None:
    root = tmp_path / "in"
    root.mkdir()
    target = root / "x"
    if kind == "directory":
        target.mkdir()
    elif kind == "fifo":
        os.mkfifo(target)
    else:
        target.symlink_to(tmp_path / "elsewhere")
    hub = receiver(root, quota=Quota(overwrite=True))
    t = tablet()
    s = send(t, "x", data(100), overwrite=True)
    Bus(hub, [t]).run(60, lambda: s.done)
    assert s.result is not None and not s.result.ok and s.stats.bytes_sent == 0
    expected = {"directory": "x exists here and is a directory", "fifo": "x exists here and is a FIFO",
                "symlink-out": "the name leads outside the receive directory"}[kind]
    assert s.result.message == expected


NAMES = ["ok.bin", "a/b/c.yaml", "", "/abs", "../up", "a/../b", "a//b", "./a", "back\\slash", "ctl\x07",
         "nul\x00", "zw\u200bj", ".ttctl-partial/x", "x" * MAX_NAME_BYTES, "x" * (MAX_NAME_BYTES + 1),
         "é" * 111, "é" * 112, ("y" * 200 + "/") * 1 + "z"]


def raw_offer(name: bytes, payload: bytes, nonce: int) -> list[bytes]:
    enc = ttapi.Encoder(*TABLET)
    meta = hashlib.sha256(payload).digest() + name
    return [enc.encode(ttapi.TtFileOffer(target_system=1, target_component=240, transfer_id=nonce, size=len(payload),
                                         meta_length=len(meta), meta_offset=off, meta=meta[off:off + META_PART]))
            for off in range(0, len(meta), META_PART)]


@pytest.mark.parametrize("name", NAMES)
def test_the_sender_refuses_what_the_receiver_would_with_the_same_words(tmp_path: Path, name: str) -> None:
    root = tmp_path / "in"
    hub = receiver(root)
    try:
        check_name(name)
        sender_says = None
    except Refused as e:
        sender_says = e.reason
    if sender_says is not None:
        with pytest.raises(ValueError, match="^" + __import__("re").escape(sender_says) + "$"):
            send(tablet(), name, b"data")
    raw = name.encode("utf-8", "surrogateescape")
    if len(raw) + 32 > 255:  # cannot even be offered: the metadata length is one byte
        assert sender_says is not None
        return
    for frame in raw_offer(raw, b"data", 1234):
        hub.receive(0.0, frame)
    out = []
    while (pkt := hub.poll(0.0)) is not None:
        out.append(pkt)
    got = [m for p in out for m in ttapi.Parser().feed(p)]
    statuses = [m for m in got if isinstance(m, ttapi.TtFileStatus)]
    reasons = [m.text for m in got if isinstance(m, ttapi.TtFileReason)]
    assert statuses and statuses[0].transfer_id == 1234
    if sender_says is None:
        assert statuses[0].result == ttapi.TtFileResult.TT_FILE_RESULT_IN_PROGRESS
    else:
        assert statuses[0].result == ttapi.TtFileResult.TT_FILE_RESULT_REFUSED_NAME
        assert reasons == [sender_says[:80]]
    assert statuses[0].meta_check == meta_check(hashlib.sha256(b"data").digest() + raw)


def test_a_refusal_whose_words_are_lost_asks_again_then_falls_back(tmp_path: Path) -> None:
    root = tmp_path / "in"
    root.mkdir()
    (root / "m.yaml").write_text("old")
    hub = receiver(root)
    t = tablet()
    s = send(t, "m.yaml", b"new")
    dropped = []

    def drop_reasons(pkt: bytes) -> bytes | None:
        msgs = ttapi.Parser().feed(pkt)
        if any(isinstance(m, ttapi.TtFileReason) for m in msgs) and len(dropped) < 1:
            dropped.append(pkt)
            kept = [m.pack(m.get_seq(), 1, 240) for m in msgs if not isinstance(m, ttapi.TtFileReason)]
            return b"".join(kept) or None
        return pkt

    bus = Bus(hub, [t])
    real = hub.poll
    hub.poll = lambda now: (lambda p: p if p is None else drop_reasons(p))(real(now))  # type: ignore[method-assign]
    bus.run(60, lambda: s.done)
    assert dropped and s.result is not None and s.result.code == "REFUSED_EXISTS"
    assert s.result.message == "m.yaml exists and overwriting is not allowed here"  # asked again, got the words


def test_a_fetching_end_takes_only_the_file_it_asked_for(tmp_path: Path) -> None:
    events: list[tuple[str, Any, Any]] = []
    fetcher = receiver(tmp_path / "got", events, unsolicited=False)
    pusher = tablet()
    s = send(pusher, "surprise.sh", b"#!/bin/sh\n")
    Bus(fetcher, [pusher]).run(60, lambda: s.done)
    assert s.result is not None and s.result.code == "REFUSED_NAME"
    assert s.result.message == "this end takes only the files it asks for"
    assert not (tmp_path / "got").exists()


# -- time without progress -------------------------------------------------------------------------

def test_timeout_counts_time_without_progress_not_time_without_a_word(tmp_path: Path) -> None:
    root = tmp_path / "in"
    hub = receiver(root, config=TransferConfig(offer_interval_max=1.0))
    hub.receiver.max_transfers = 1  # type: ignore[union-attr]
    hog_end, waiting_end = tablet(rate_Bps=50.0), tablet(config=TransferConfig(give_up_after=10.0))
    hog = send(hog_end, "hog.bin", data(100_000))
    waiting = send(waiting_end, "w.bin", data(100))
    Bus(hub, [hog_end, waiting_end]).run(60, lambda: waiting.done)
    assert waiting.result is not None and waiting.result.code == "TIMEOUT"
    assert 10.0 <= waiting.result.seconds < 12.0  # it heard 'busy' every second, and still gave up
    assert waiting.result.message == "1/240 stayed busy for 10 s (1 transfers are running here)"
    assert not hog.done


# -- strangers -----------------------------------------------------------------------------------

def test_garbage_from_another_source_between_a_wide_frames_pieces_costs_nothing(tmp_path: Path) -> None:
    root = tmp_path / "in"
    hub = receiver(root)
    t = tablet(config=TransferConfig(frame_mode="wide"))
    payload = data(30_000)
    s = send(t, "w.bin", payload)
    rng = random.Random(5)
    bus = Bus(hub, [t])

    def interleave(i: int, pkt: bytes) -> bytes:
        hub.receive(bus.now, rng.randbytes(rng.randint(1, 100)), source=("10.0.0.9", 4242))  # a stranger
        return pkt

    bus.tap = interleave
    bus.run(60, lambda: s.done)
    assert s.result is not None and s.result.ok
    own = hub._rxs[0].stats  # the sender's packets: not one wide frame broken by the stranger's bytes
    assert own.bad_frames == 0 and own.carries_dropped == 0 and own.frames >= 30_000 // 247
    assert hub._rxs[("10.0.0.9", 4242)].stats.frames == 0
    assert (root / "w.bin").read_bytes() == payload


def test_a_flood_of_offers_is_bounded_and_does_not_stop_real_transfers(tmp_path: Path) -> None:
    """A peer offering thousands of files with fresh ids (a runaway script, or worse): the
    receiver remembers a bounded number of them, and a real transfer still goes through."""
    from ttctl.proto.receiver import MAX_KNOWN

    root = tmp_path / "in"
    root.mkdir()
    (root / "taken").write_text("x")
    hub = receiver(root)
    for nonce in range(1, 3 * MAX_KNOWN):
        for frame in raw_offer(b"taken", b"other bytes", nonce):  # refused: exists
            hub.receive(0.001 * nonce, frame)
        while hub.poll(0.001 * nonce) is not None:
            pass
    assert hub.receiver is not None and len(hub.receiver.transfers) <= MAX_KNOWN
    t = tablet()
    s = send(t, "real.bin", data(5000))
    Bus(hub, [t]).run(60, lambda: s.done)
    assert s.result is not None and s.result.ok
    assert (root / "real.bin").read_bytes() == data(5000)
