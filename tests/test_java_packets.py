"""The generated Java Packetizer and PacketReceiver against ttctl's Python ones (the reference,
cli/ttctl/wire/packets.py): identical packets for identical frames, and identical frames (and
counters) out for identical packets in, on seeded random streams with lost, duplicated, reordered,
corrupted, truncated, merged, empty and garbage packets, long frames (TT_FILE_DATA_WIDE, 267
bytes, signed ones 280) spanning packets with urgent packets slipped between their pieces.

One JVM (tests/java/packets/PacketsDriver.java) and one Python process
(tests/java/packets/oracle.py, on the freshly generated Python bindings) each read all the cases
on stdin; their outputs must match line for line."""

from __future__ import annotations

import os
import random
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conformance_lib import build_java
from conftest import ROOT

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

DRIVERS = ROOT / "tests" / "java" / "packets"
SEED = 20261123
KEY = bytes(range(32))
MADE: list[bytes] = []  # every frame any case was made of


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """(classes, generated tree): Java sources and driver built with --release 11 -Xlint:all -Werror."""
    return build_java(tmp_path_factory.mktemp("java_packets"), sorted(DRIVERS.glob("*.java")), "python,java")


def run_both(built: tuple[Path, Path], cases: list[str]) -> tuple[list[str], list[str]]:
    cls, out = built
    data = "\n".join(cases) + "\n"
    java = subprocess.run(["java", "-cp", str(cls), "PacketsDriver"], input=data, capture_output=True, text=True,
                          timeout=300)
    assert java.returncode == 0, java.stderr[-4000:]
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(out / "python"), str(ROOT / "cli")])}
    py = subprocess.run([sys.executable, str(DRIVERS / "oracle.py")], input=data, capture_output=True, text=True,
                        timeout=300, env=env)
    assert py.returncode == 0, py.stderr[-4000:]
    j, p = java.stdout.splitlines(), py.stdout.splitlines()
    assert j[-1] == "DONE" and p[-1] == "DONE", (j[-1:], p[-1:])
    assert len(j) == len(p) == len(cases) + 1
    assert not [x for x in j if x.startswith("ERR")], [x for x in j if x.startswith("ERR")][:3]
    return j[:-1], p[:-1]


# --- streams ------------------------------------------------------------------------------

def make_frames(rng: random.Random, n: int) -> list[bytes]:
    import ttapi

    encs = [ttapi.Encoder(sysid=1, compid=240), ttapi.Encoder(sysid=7, compid=1),
            ttapi.Encoder(sysid=2, compid=2, signing=ttapi.Signing(KEY, link_id=3))]
    frames = []
    for _ in range(n):
        kind = rng.choice(["heartbeat", "ack", "command", "narrow", "wide", "wide", "wide"])
        if kind == "heartbeat":
            msg = ttapi.Heartbeat(type=2, custom_mode=rng.getrandbits(32))
        elif kind == "ack":
            msg = ttapi.TtCommandAck(command_id=rng.getrandbits(16), result=2, progress=100)
        elif kind == "command":
            msg = ttapi.TtActionCommand(command_id=rng.getrandbits(16), action=1, argument="x" * rng.randint(0, 48))
        elif kind == "narrow":
            msg = ttapi.TtFileData(transfer_id=1, offset=rng.getrandbits(32), data=rng.randbytes(rng.randint(1, 80)))
        else:  # a full 267-byte frame (280 signed): the last data byte is never zero
            msg = ttapi.TtFileDataWide(transfer_id=rng.getrandbits(16), offset=rng.getrandbits(32),
                                       data=rng.randbytes(246) + bytes([rng.randint(1, 255)]))
        frames.append(rng.choice(encs).encode(msg))
    MADE.extend(frames)
    return frames


def pack(frames: list[bytes], mtu: int) -> list[bytes]:
    from ttctl.wire.packets import packetize

    return packetize(frames, mtu)


def impair(rng: random.Random, packets: list[bytes], frames: list[bytes], mtu: int) -> list[bytes]:
    ps = list(packets)
    for _ in range(rng.randint(1, 6)):
        op = rng.choice(["lose", "dup", "swap", "corrupt", "truncate", "garbage", "urgent", "urgent", "merge",
                         "empty", "fakehead", "replay", "foreign"])
        i = rng.randrange(len(ps)) if ps else 0
        if op == "lose" and ps:
            del ps[i]
        elif op == "dup" and ps:
            ps.insert(rng.randint(i, len(ps)), ps[i])
        elif op == "swap" and len(ps) > 1:
            i = min(i, len(ps) - 2)
            ps[i], ps[i + 1] = ps[i + 1], ps[i]
        elif op == "corrupt" and ps and ps[i]:
            b = bytearray(ps[i])
            b[rng.randrange(len(b))] ^= 1 << rng.randrange(8)
            ps[i] = bytes(b)
        elif op == "truncate" and ps and ps[i]:
            ps[i] = ps[i][:rng.randrange(len(ps[i]))]
        elif op == "garbage":
            g = bytearray(rng.randbytes(rng.randint(1, 150)))
            for _ in range(rng.randint(0, 4)):  # magic bytes and real headers in the noise
                k = rng.randrange(len(g))
                f = rng.choice(frames)
                g[k:k + 10] = f[:10] if rng.random() < 0.5 else b"\xfd"
            ps.insert(i, bytes(g))
        elif op == "urgent":  # whole short frames on a packet of their own, maybe between pieces
            ps.insert(i, urgent_packet(rng, mtu))
        elif op == "merge" and len(ps) > 1:  # an oversized packet
            i = min(i, len(ps) - 2)
            ps[i:i + 2] = [ps[i] + ps[i + 1]]
        elif op == "empty":
            ps.insert(i, b"")
        elif op == "fakehead":  # a header promising a long frame at a packet's end
            f = rng.choice([f for f in frames if len(f) > 100] or frames)
            ps.insert(i, rng.randbytes(rng.randint(0, 40)) + f[:rng.randint(1, 40)])
        elif op == "replay" and ps:
            ps.append(rng.choice(ps))
        elif op == "foreign":  # a frame of a message the dialect lacks (another dialect's), then maybe frames
            body = rng.randbytes(rng.randint(0, 60))
            foreign = bytes([0xFD, len(body), 0, 0, 9, 1, 240, 0x21, 0xCB, 0]) + body + rng.randbytes(2)
            ps.insert(i, foreign + (urgent_packet(rng, mtu) if rng.random() < 0.5 else b""))
    return ps


def urgent_packet(rng: random.Random, mtu: int) -> bytes:
    """A packet of whole short frames, as many as fit."""
    out = b""
    for f in make_frames(rng, rng.randint(1, 4)):
        if len(f) <= 100 and len(out) + len(f) <= mtu:
            out += f
    return out


def receive_case(packets: list[bytes]) -> str:
    return " ".join(["R", *[p.hex() if p else "-" for p in packets]])


def decoded(line: str) -> list[bytes]:
    """The frames a receiver line reports, as unsigned re-encodings."""
    toks = line.split()[1:-2]
    return [bytes.fromhex(f[1:]) for t in toks for f in t.split("/")[0].split(",") if f]


def reencode(frame: bytes) -> bytes:
    import ttapi

    m = ttapi.decode(frame)
    return m.pack(m.get_seq(), m.get_srcSystem(), m.get_srcComponent())


# --- tests --------------------------------------------------------------------------------

def test_packetizer_matches_python(built: tuple[Path, Path]) -> None:
    rng = random.Random(SEED)
    cases, expect = [], []
    for _ in range(300):
        mtu = rng.choice([13, 21, 40, 64, 100, 100, 100, 255, 300])
        frames = make_frames(rng, rng.randint(0, 30))
        cases.append(" ".join(["P", str(mtu), *[f.hex() for f in frames]]))
        expect.append((frames, mtu))
    j, p = run_both(built, cases)
    for k, (a, b) in enumerate(zip(j, p, strict=True)):
        assert a == b, f"case {k}: {cases[k][:200]}\njava   {a[:300]}\npython {b[:300]}"
    # and the packets obey the rule: all bytes, in order, none over the MTU, a fitting frame never split
    for line, (frames, mtu) in zip(j, expect, strict=True):
        pkts = [bytes.fromhex(x) for t in line.split()[1:] for x in t.split("/")[0].split(",") if x]
        assert b"".join(pkts) == b"".join(frames)
        assert all(0 < len(x) <= mtu for x in pkts)
        assert line.endswith("/0")
        assert all(int(t.split("/")[1]) < mtu for t in line.split()[1:])  # a full packet goes out at once


def test_receiver_matches_python(built: tuple[Path, Path]) -> None:
    rng = random.Random(SEED + 1)
    cases, sent, clean = [], [], []
    for k in range(1500):
        mtu = rng.choice([40, 64, 100, 100, 100, 100, 255])
        frames = make_frames(rng, rng.randint(1, 25))
        packets = pack(frames, mtu)
        kind = k % 10
        if kind == 0:
            clean.append(len(cases))
        elif kind == 1:  # cut anywhere, not by the rule
            stream = b"".join(frames)
            cuts = sorted(rng.sample(range(1, len(stream)), min(len(stream) - 1, rng.randint(1, 12))))
            packets = [stream[a:b] for a, b in zip([0, *cuts], [*cuts, len(stream)], strict=True)]
            packets = impair(rng, packets, frames, mtu) if rng.random() < 0.5 else packets
        elif kind == 2:  # pure garbage, dense in magic bytes
            packets = [bytes(rng.choice([0xFD, rng.randrange(256)]) for _ in range(rng.randint(0, 400)))
                       for _ in range(rng.randint(1, 8))]
        else:
            packets = impair(rng, packets, frames, mtu)
        cases.append(receive_case(packets))
        sent.append(frames)
    j, p = run_both(built, cases)
    for k, (a, b) in enumerate(zip(j, p, strict=True)):
        assert a == b, f"case {k}: {cases[k][:300]}\njava   {a[:400]}\npython {b[:400]}"
    # the reference itself: a clean stream delivers every frame in order; nothing is ever made up
    for k in clean:
        assert decoded(j[k]) == [reencode(f) for f in sent[k]]
    made = {reencode(f) for f in MADE}
    assert all(f in made for line in j for f in decoded(line)), "a frame that was never sent came out"
    # every decision path was taken somewhere
    totals = [0] * 6
    for line in j:
        for i, v in enumerate(line.split()[-1].split(":")):
            totals[i] += int(v)
    packets_, frames_, bad, dropped, rescans, unknown = totals
    assert packets_ > 10000 and frames_ > 10000 and bad > 100 and dropped > 100 and rescans > 100, totals
    assert unknown > 100, totals  # frames of messages the dialect lacks, counted alike


def test_receiver_no_made_up_frames_without_garbage(built: tuple[Path, Path]) -> None:
    """Lost, reordered, duplicated packets and urgent packets between pieces: every frame that
    comes out was sent (no false assembly), in both implementations (they are compared too)."""
    rng = random.Random(SEED + 2)
    cases, allowed = [], []
    for _ in range(300):
        frames = make_frames(rng, rng.randint(2, 20))
        packets = pack(frames, 100)
        urgent = make_frames(rng, 4)
        for _ in range(rng.randint(1, 4)):
            op = rng.choice(["lose", "swap", "dup", "slip"])
            i = rng.randrange(len(packets))
            if op == "lose" and len(packets) > 1:
                del packets[i]
            elif op == "swap" and len(packets) > 1:
                i = min(i, len(packets) - 2)
                packets[i], packets[i + 1] = packets[i + 1], packets[i]
            elif op == "dup":
                packets.insert(i, packets[i])
            else:
                packets.insert(i, rng.choice([f for f in urgent if len(f) <= 100] or [b""]))
        cases.append(receive_case(packets))
        allowed.append({reencode(f) for f in frames + urgent})
    j, p = run_both(built, cases)
    assert j == p
    made_up = sum(1 for k, line in enumerate(j) for f in decoded(line) if f not in allowed[k])
    assert made_up == 0


def test_slipped_urgent_frames_and_long_frame_both_delivered(built: tuple[Path, Path]) -> None:
    """The scenario the packing rule is for: a 267-byte frame in three packets, a packet of urgent
    frames slipped between each pair of pieces; everything arrives, the urgent ones first."""
    import ttapi

    rng = random.Random(SEED + 3)
    wide = make_frames(random.Random(1), 40)
    wide = next(f for f in wide if len(f) == 267)
    urgent = [ttapi.Encoder(1, 1).encode(ttapi.TtCommandAck(command_id=i, result=2, progress=100)) for i in range(2)]
    pieces = pack([wide], 100)
    assert len(pieces) == 3
    case = receive_case([pieces[0], urgent[0], pieces[1], urgent[1], pieces[2]])
    j, p = run_both(built, [case])
    assert j == p
    got = decoded(j[0])
    assert got == [reencode(urgent[0]), reencode(urgent[1]), reencode(wide)], (got, rng)


def test_udplink_reads_datagrams_as_packets(built: tuple[Path, Path]) -> None:
    """UdpLink over real loopback UDP: a long frame cut into DTT packets with an urgent datagram
    slipped between its pieces is reassembled; a packet taken for a continuation that never
    comes is given back after IDLE_FLUSH_MILLIS of quiet, its frame delivered then."""
    import socket
    import time

    import ttapi

    cls, _ = built
    proc = subprocess.Popen(["java", "-cp", str(cls), "UdpCheck"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stdout is not None and proc.stdin is not None
        first = proc.stdout.readline().split()
        assert first[0] == "PORT", first
        port = int(first[1])
        wide = ttapi.Encoder(1, 1).encode(ttapi.TtFileDataWide(transfer_id=1, offset=7, data=bytes(range(1, 248))))
        urgent = ttapi.Encoder(2, 2).encode(ttapi.Heartbeat(type=2))
        late = ttapi.Encoder(3, 3).encode(ttapi.Heartbeat(type=3))
        marker = ttapi.Encoder(4, 4).encode(ttapi.Heartbeat(type=4))
        pieces = pack([wide], 100)
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            for p in [pieces[0], urgent, pieces[1], pieces[2]]:
                s.sendto(p, ("127.0.0.1", port))
                time.sleep(0.01)
            time.sleep(0.5)
            # a whole frame (delivered at once: the clock the late one is judged by), the head of
            # another long frame, then a packet that looks like its continuation (a stray byte
            # before a whole frame): only the quiet after it tells it was not one
            s.sendto(marker, ("127.0.0.1", port))
            s.sendto(pieces[0], ("127.0.0.1", port))
            s.sendto(b"\x00" + late, ("127.0.0.1", port))
            time.sleep(1.0)
        out, err = proc.communicate("", timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    lines = out.splitlines()
    assert lines[-1] == "DONE", out + err
    msgs = [x.split()[1:5] for x in lines if x.startswith("MSG")]
    assert msgs == [["0", "0", "2", "2"], [str(ttapi.TtFileDataWide.MSG_ID), "0", "1", "1"], ["0", "0", "4", "4"],
                    ["0", "0", "3", "3"]], out
    times = [int(x.split()[5]) for x in lines if x.startswith("MSG")]
    # the late frame waits for the idle flush (0.2 s of quiet) after the marker sent just before
    # it, both timed by the Java end's clock (a loaded machine delays the one and the other alike)
    assert 180 <= times[3] - times[2] < 1200, times
    stats = next(x for x in lines if x.startswith("STATS"))
    assert "carriesDropped=1" in stats and "rescans=1" in stats, stats
