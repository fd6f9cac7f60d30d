"""The generated C++ onboard end (onboard_node: tests/cpp_node_lib.py) against what else a link
may carry:

- garbage and strangers change nothing during an upload, and the node's memory stays where two
  floods put it (its tables are fixed); a signed link works, a wrong key is refused and counted;
- under ASan/UBSan: the shared name vectors (tests/data/names.json) offered raw, links left in
  the inbox, an offer beyond the quota, impossible metadata, floods of offers, data, commands
  and fetch requests, garbage between frames: refused or dropped, counted, never a crash,
  nothing written outside the inbox, tables bounded; then a real transfer still works.
"""

from __future__ import annotations

import hashlib
import json
import random
import time
from pathlib import Path
from typing import Any

import ttapi
from conftest import ROOT
from cpp_node_lib import Raw, needs_gxx, sha, write
from e2e_lib import LOCAL, Start, send

pytestmark = needs_gxx

NAMES = json.loads((ROOT / "tests" / "data" / "names.json").read_text(encoding="utf-8"))["names"]


def offer_frames(name: bytes, payload: bytes, nonce: int, size: int | None = None) -> list[Any]:
    meta = hashlib.sha256(payload).digest() + name
    return [ttapi.TtFileOffer(target_system=1, target_component=240, transfer_id=nonce,
                              size=len(payload) if size is None else size, meta_length=len(meta), meta_offset=off,
                              meta=meta[off:off + 71]) for off in range(0, len(meta), 71)]



# -- garbage, strangers, signing -----------------------------------------------------------------

def rss_kb(pid: int) -> int:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    return 0


def junk(rng: random.Random) -> bytes:
    kind = rng.randrange(4)
    if kind == 0:
        return rng.randbytes(rng.randint(1, 100))
    if kind == 1:
        return b"\xfd" + rng.randbytes(rng.randint(0, 99))  # a magic and nothing that follows
    if kind == 2:  # a valid frame cut short, then more junk
        frame = ttapi.encode(ttapi.TtFileOffer(target_system=1, transfer_id=rng.randrange(1, 2**32), meta_length=40),
                             0, 255, 190)
        return frame[:rng.randint(1, len(frame) - 1)] + rng.randbytes(rng.randint(0, 10))
    return rng.randbytes(rng.randint(101, 300))  # longer than a DTT packet


def flood(raw: Raw, rng: random.Random, count: int, first_id: int) -> None:
    """Offers whose metadata never completes, data for transfers nobody offered, commands for
    another vehicle, fetch requests whose name never completes, garbage: from a stranger."""
    for i in range(count):
        tid = first_id + i
        k = i % 5
        if k == 0:
            raw.frames(offer_frames(b"x" * 100, b"", tid, size=10)[0])  # 2 parts of 3: never whole
        elif k == 1:
            raw.frames(ttapi.TtFileData(transfer_id=tid, offset=rng.randrange(2**32), data=rng.randbytes(80)))
        elif k == 2:
            raw.frames(ttapi.TtActionCommand(target_system=9, target_component=240, command_id=tid & 0xFFFF, action=0))
        elif k == 3:
            raw.frames(ttapi.TtFileRequest(target_system=1, target_component=240, request_id=tid, name_length=200,
                                           name_offset=0, name=b"n" * 80))
        else:
            raw.raw(junk(rng))
        if i % 50 == 49:
            time.sleep(0.005)  # a socket buffer's worth at a time


def test_garbage_and_strangers_change_nothing_and_memory_stays_bounded(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                                       start: Start, cpp_nodes: Any) -> None:
    """During an upload: garbage datagrams from another port, and a stranger (77/1) sending data
    under the upload's own transfer id, an offer of the same name, commands for another
    vehicle, floods of offers, data and requests. The file arrives intact, nothing else is
    stored or run, the stranger's offer is told BUSY; the node's memory stays where two floods
    of thousands of frames put it (its tables are fixed)."""
    inbox = tmp_path / "inbox"
    src = write(tmp_path / "a.bin", 30_000, 7)
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox))
    stranger = Raw(node.port, sysid=77, compid=1)
    rng = random.Random(9)
    try:
        flood(stranger, rng, 3000, 10_000)
        rss1 = rss_kb(node.p.pid)
        sender = start("send", "send-file", str(src), "--to", f"udpout:{LOCAL}:{node.port}", "--rate", "8000",
                       "--json")
        acc = node.wait_event("accepted", 20, name="a.bin")
        assert acc["peer"] == "255/190"
        # the stranger: an offer of the same file name, and zeros under the upload's own id
        stranger.frames(*offer_frames(b"a.bin", b"other", 4242, size=5))
        for off in range(0, 30_000, 80):
            stranger.frames(ttapi.TtFileData(transfer_id=acc["transfer_id"], offset=off, data=b"\0" * 80))
        flood(stranger, rng, 3000, 50_000)
        rss2 = rss_kb(node.p.pid)
        assert sender.wait(60) == 0, sender.stderr
    finally:
        stranger.close()
    r = json.loads(sender.stdout)
    assert r["ok"] and r["restarts"] == 0 and sha(inbox / "a.bin") == sha(src)
    busy = node.wait_event("busy", 5)
    assert busy["peer"] == "77/1" and "being received from 255/190 right now" in busy["reason"], busy
    assert sorted(p.name for p in inbox.iterdir()) == [".ttctl-partial", "a.bin"]
    stats = node.stop()
    assert stats["executed"] == 0 and stats["files_received"] == 1, stats
    assert stats["requests_forgotten"] > 500 and stats["oversize"] > 0 and stats["ignored"] >= 1200, stats
    print("MEASURED", json.dumps({"rss_after_first_flood_kb": rss1, "rss_after_second_kb": rss2}))
    assert rss2 - rss1 < 2048, (rss1, rss2)  # bounded: the second flood found the tables at their size


def test_a_signed_link_works_and_a_wrong_key_is_refused(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                        cpp_nodes: Any) -> None:
    """The node with --key and `send-file --key` with the same passphrase: an upload and a fetch
    work, every frame signed both ways. Another key, or none: nothing is accepted, the node
    counts the refused frames and says once that it refuses that peer."""
    (tmp_path / "key").write_text("our secret\n")
    (tmp_path / "other").write_text("not our secret\n")
    inbox = tmp_path / "inbox"
    src = write(tmp_path / "s.bin", 12_000, 8)
    served = write(tmp_path / "serve" / "d.bin", 12_000, 9)
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox),
                     "--serve", str(served.parent), "--key", str(tmp_path / "key"), "--rate", "8000")
    to = f"udpout:{LOCAL}:{node.port}"
    proc, r = send(str(src), "--to", to, "--rate", "8000", "--key", str(tmp_path / "key"), timeout=60)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(inbox / "s.bin") == sha(src)
    # served signed: TT_FILE_DATA_FIT frames of 66 file bytes fill each 100-byte packet, signed (Geometry)
    (tmp_path / "got").mkdir()
    proc, f = send("d.bin", "--from", to, "--dir", str(tmp_path / "got"), "--rate", "8000", "--key",
                   str(tmp_path / "key"), timeout=60)
    assert proc.returncode == 0 and f["ok"], proc.stderr
    assert sha(tmp_path / "got" / "d.bin") == sha(served)
    for key in (["--key", str(tmp_path / "other")], []):
        proc, r = send(str(src), "--to", to, "--name", "t.bin", "--rate", "8000", "--timeout", "2", *key, timeout=60)
        assert proc.returncode == 1 and r["code"] == "TIMEOUT", proc.stderr
    assert not (inbox / "t.bin").exists()
    refused = node.events("link-refused")
    stats = node.stop()
    assert stats["refused_signature"] >= 4 and len(refused) >= 1, (stats, refused)


# -- hostile input under the sanitizers ----------------------------------------------------------

def reason_fit(text: str) -> str:
    raw = text.encode()
    return text if len(raw) <= 80 else raw[:77].decode("utf-8", "ignore") + "..."


def test_hostile_input_under_asan(cpp_node_bins: dict[str, Path], tmp_path: Path, start: Start, cpp_nodes: Any) -> None:
    """The ASan/UBSan build, listening. Every name of tests/data/names.json is offered raw: the
    refused ones get TT_FILE_REASON in the receiver's words (as Python's) and REFUSED_NAME, the
    others are stored inside the inbox. An offer beyond --max-file is refused for its quota;
    offers claiming impossible metadata are dropped; floods of offers, data, commands, requests
    and garbage are absorbed; then a real upload still works. No sanitizer report, no file
    outside the inbox."""
    jail = tmp_path / "jail"
    inbox = jail / "inbox"
    (jail / "outside").mkdir(parents=True)
    node = cpp_nodes(cpp_node_bins["asan"], tmp_path, "asan", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox),
                     "--max-file", "100000", "--heartbeat", "0")
    raw = Raw(node.port)
    rng = random.Random(11)
    try:
        def answer(tid: int) -> list[Any]:
            return raw.collect(3.0, until=lambda ms: any(isinstance(m, ttapi.TtFileStatus) and m.transfer_id == tid
                                                         for m in ms))

        stored = []
        for i, case in enumerate(NAMES):
            name = bytes.fromhex(case["hex"])
            if len(name) + 32 > 255:
                continue  # cannot even be offered: the metadata length is one byte
            tid = 5000 + i
            raw.frames(*offer_frames(name, b"data", tid))
            got = answer(tid)
            status = [m for m in got if isinstance(m, ttapi.TtFileStatus) and m.transfer_id == tid]
            reasons = [m for m in got if isinstance(m, ttapi.TtFileReason) and m.transfer_id == tid]
            assert status, (case, got)
            if case["refused"] is None:
                assert status[0].result == ttapi.TtFileResult.TT_FILE_RESULT_IN_PROGRESS, case
                raw.frames(ttapi.TtFileData(transfer_id=tid, offset=0, data=b"data"))
                done = raw.collect(3.0, until=lambda ms, t=tid: any(
                    isinstance(m, ttapi.TtFileStatus) and m.transfer_id == t and m.result == 1 for m in ms))
                assert any(isinstance(m, ttapi.TtFileStatus) and m.result == 1 for m in done), case
                stored.append(name.decode())
            else:
                assert status[0].result == ttapi.TtFileResult.TT_FILE_RESULT_REFUSED_NAME, case
                assert reasons and reasons[0].text == reason_fit(case["refused"]), (case, reasons)
        for name in stored:
            assert (inbox / name).read_bytes() == b"data", name
        # links someone left in the inbox: through a directory link, and a dangling file link
        (inbox / "esc").symlink_to(jail / "outside", target_is_directory=True)
        (inbox / "dangling.bin").symlink_to(jail / "outside" / "planted.bin")
        for tid, name, code in ((9101, b"esc/x.bin", ttapi.TtFileResult.TT_FILE_RESULT_REFUSED_NAME),
                                (9102, b"dangling.bin", ttapi.TtFileResult.TT_FILE_RESULT_REFUSED_EXISTS)):
            raw.frames(*offer_frames(name, b"data", tid))
            got = answer(tid)
            assert [m.result for m in got if isinstance(m, ttapi.TtFileStatus) and m.transfer_id == tid][:1] == [code]
        assert [m.text for m in got if isinstance(m, ttapi.TtFileReason)][:1] == [
            "dangling.bin exists here and is a symbolic link"]
        # beyond the quota
        raw.frames(*offer_frames(b"big.bin", b"", 9001, size=100_001))
        got = answer(9001)
        assert [m.result for m in got if isinstance(m, ttapi.TtFileStatus)][:1] == [
            ttapi.TtFileResult.TT_FILE_RESULT_REFUSED_QUOTA]
        assert [m.text for m in got if isinstance(m, ttapi.TtFileReason)][:1] == [
            "100001 bytes exceed the per-file quota of 100000 bytes"]
        # metadata that cannot be: offsets past the end, lengths that disagree, a zero id
        raw.frames(ttapi.TtFileOffer(target_system=1, transfer_id=9002, size=5, meta_length=255, meta_offset=250,
                                     meta=b"\xff" * 71),
                   ttapi.TtFileOffer(target_system=1, transfer_id=9002, size=6, meta_length=40, meta_offset=0),
                   ttapi.TtFileOffer(target_system=1, transfer_id=0, size=5, meta_length=33, meta_offset=0,
                                     meta=b"a" * 33))
        flood(raw, rng, 4000, 100_000)
        for _ in range(300):  # garbage between frames, in one packet
            frame = ttapi.encode(ttapi.Heartbeat(), 0, 255, 190)
            raw.raw((rng.randbytes(rng.randint(0, 20)) + frame + rng.randbytes(rng.randint(0, 20)))[:100])
        cmds = [ttapi.TtActionCommand(target_system=1, target_component=240, command_id=i, action=3, time_usec=i)
                for i in range(700)]
        for i in range(0, 700, 4):
            raw.frames(*cmds[i:i + 4])
            time.sleep(0.002)
    finally:
        raw.close()
    src = write(tmp_path / "after.bin", 8000, 12)
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{node.port}", "--rate", "8000", timeout=90)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(inbox / "after.bin") == sha(src)
    stats = node.stop()  # exit 0 and nothing on stderr: no sanitizer report
    assert stats["commands_forgotten"] > 0 and stats["executed"] <= 700, stats
    assert stats["requests_forgotten"] > 0 and stats["bad_frames"] + stats["oversize"] > 0, stats
    assert list((jail / "outside").iterdir()) == []
    escaped = [p for p in tmp_path.rglob("*") if p.is_file() and inbox not in p.parents
               and p.suffix not in (".out", ".err", ".bin")]
    assert escaped == [], escaped


# -- another dialect's frames --------------------------------------------------------------------

def test_frames_of_another_dialect_are_counted_as_pythons_end_counts_them(cpp_node_bins: dict[str, Path],
                                                                          tmp_path: Path, cpp_nodes: Any) -> None:
    """Whole frames of a msgid ttapi lacks (a peer speaking another dialect) are counted in the
    node's stats as `unknown`, where the packing rule puts a frame (a packet's start, right after a
    frame), as ttctl's PacketReceiver counts them; the frames around them still arrive."""
    from conftest import shipped
    from ttctl.wire.packets import PacketReceiver

    def stranger(payload_len: int, cut: int | None = None) -> bytes:  # msgid 0xBEEF, not in ttapi
        frame = bytes([0xFD, payload_len, 0, 0, 3, 9, 9, 0xEF, 0xBE, 0x00]) + bytes(range(payload_len)) + b"\x12\x34"
        return frame[:cut]

    beat = ttapi.Encoder(255, 190).encode(ttapi.Heartbeat(type=6, autopilot=8, base_mode=0, custom_mode=0,
                                                          system_status=4, mavlink_version=3))
    packets = [stranger(5), stranger(5) + beat, beat + stranger(7), stranger(80, cut=40),  # counted
               b"\x00\x01" + stranger(5), stranger(5) + b"\x00"]  # not where a frame begins, or ends: not
    rx = PacketReceiver(shipped())
    heard = [m for p in packets for m in rx.feed(p)]
    assert rx.stats.unknown == 4 and len(heard) == 2
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--heartbeat", "0")
    raw = Raw(node.port)
    try:
        for p in packets:
            raw.raw(p)
            time.sleep(0.05)
    finally:
        raw.close()
    time.sleep(0.3)
    stats = node.stop()
    assert stats["unknown"] == rx.stats.unknown, stats
    assert stats["frames_in"] == 2 and stats["bad_frames"] == 0, stats
