"""MAVLink 2 signing in the generated Java runtime (Signing, and its use by Parser and
PacketReceiver), against real pymavlink (the oracle, mavgen's Python for ttapi) and the generated
Python runtime: frames signed by Java verify in both, byte for byte what Python signs at the same
timestamp; frames they sign verify in Java; tampered (any byte), replayed (same frame again, older
timestamp, a new stream more than a minute old), wrong-key and refused unsigned frames are
refused; allowUnsigned; signing from several threads. The Java side is
tests/java/signing/SigningDriver.java, one JVM per test reading commands on stdin."""

from __future__ import annotations

import shutil
import subprocess
import time
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from conformance_lib import build_java
from conftest import ROOT

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

DRIVERS = ROOT / "tests" / "java" / "signing"
KEY = bytes(range(1, 33))
OTHER_KEY = bytes(range(2, 34))
MINUTE = 6_000_000


def now() -> int:
    return int((time.time() - 1420070400) * 100_000)


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    cls, _ = build_java(tmp_path_factory.mktemp("java_signing"), sorted(DRIVERS.glob("*.java")))
    return cls


@pytest.fixture(scope="module")
def pm(tmp_path_factory: pytest.TempPathFactory) -> ModuleType:
    from conformance_lib import pymavlink_module

    return pymavlink_module("ttapi", tmp_path_factory.mktemp("pm"))


def java(classes: Path, *commands: str) -> list[str]:
    """The driver's answers, one per command."""
    proc = subprocess.run(["java", "-cp", str(classes), "SigningDriver"], input="\n".join(commands) + "\n",
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-4000:]
    lines = proc.stdout.splitlines()
    assert lines[-1] == "DONE" and len(lines) == len(commands) + 1, proc.stdout[-2000:]
    return lines[:-1]


def new(key: bytes = KEY, link: int = 7, allow: bool = False, clock: int | None = None) -> str:
    return f"NEW {key.hex()} {link} {int(allow)} {'sys' if clock is None else clock}"


def messages() -> list[Any]:
    import ttapi

    return [ttapi.Heartbeat(type=2, custom_mode=77), ttapi.TtCommandAck(command_id=513, result=2, progress=100),
            ttapi.TtFileDataWide(transfer_id=3, offset=1 << 20, data=bytes(range(1, 248))),
            ttapi.TtFileData(transfer_id=3, offset=5, data=b"abc"), ttapi.SystemTime(time_unix_usec=1, time_boot_ms=2)]


def unsigned_frames() -> list[bytes]:
    return [m.pack(seq=i * 37 % 256, sysid=1 + i, compid=190 + i) for i, m in enumerate(messages())]


def signed_at(msg: Any, ts: int, sysid: int = 1, compid: int = 1, link: int = 1, key: bytes = KEY,
              seq: int = 0) -> bytes:
    """A frame the generated Python runtime signs with timestamp `ts` exactly."""
    import ttapi

    class At(ttapi.Signing):
        def next_timestamp(self) -> int:
            return ts

    return ttapi.encode(msg, seq, sysid, compid, At(key, link_id=link))


def pm_verifier(pm: ModuleType, key: bytes = KEY) -> Any:
    mav = pm.MAVLink(None, srcSystem=255, srcComponent=190)
    mav.signing.secret_key = key
    mav.signing.timestamp = now()
    mav.robust_parsing = True
    return mav


# --- Java signs ----------------------------------------------------------------------------

def test_java_signed_frames_verify_in_pymavlink_and_python(classes: Path, pm: ModuleType) -> None:
    import ttapi

    frames = unsigned_frames()
    out = java(classes, new(link=7), *[f"SIGN {f.hex()}" for f in frames])
    signed = [bytes.fromhex(x.split()[1]) for x in out[1:]]
    assert all(len(s) == len(f) + 13 and s[2] == 1 and s[-13] == 7 for s, f in zip(signed, frames, strict=True))
    stamps = [int.from_bytes(s[-12:-6], "little") for s in signed]
    assert stamps == sorted(set(stamps)) and abs(stamps[0] - now()) < 10 * 100_000  # 10 us units, now

    mav = pm_verifier(pm)
    got = mav.parse_buffer(b"".join(signed)) or []
    assert [m.get_msgId() for m in got] == [m.MSG_ID for m in messages()]
    assert all(m.get_signed() for m in got) and mav.signing.goodsig_count == len(frames)
    assert mav.signing.badsig_count == 0
    wrong = pm_verifier(pm, OTHER_KEY)
    refused = wrong.parse_buffer(b"".join(signed)) or []
    assert all(m.get_type() == "BAD_DATA" for m in refused) and wrong.signing.badsig_count == len(frames)

    sig = ttapi.Signing(KEY)
    decoded = [ttapi.decode(s, signing=sig) for s in signed]
    assert [type(m) for m in decoded] == [type(m) for m in messages()] and all(m.get_signed() for m in decoded)
    assert [(m.get_seq(), m.get_srcSystem()) for m in decoded] == [(f[4], f[5]) for f in frames]


def test_java_signs_byte_for_byte_as_python(classes: Path) -> None:
    import ttapi

    t0 = now() + 10 * MINUTE  # ahead of both clocks: both sign t0+1, t0+2, ...
    out = java(classes, new(link=9, clock=t0), *[f"SIGN {f.hex()}" for f in unsigned_frames()])
    py = ttapi.Signing(KEY, link_id=9, timestamp=t0)
    expect = [ttapi.encode(m, i * 37 % 256, 1 + i, 190 + i, py) for i, m in enumerate(messages())]
    assert [bytes.fromhex(x.split()[1]) for x in out[1:]] == expect
    # signing an already signed frame changes nothing; garbage is refused with an exception, not a crash
    out = java(classes, new(), f"SIGN {expect[0].hex()}", "SIGN fd0102", f"SIGN {expect[0][:-14].hex()}")
    assert out[1] == f"SIGNED {expect[0].hex()}"
    assert out[2].startswith("ERR java.lang.IllegalArgumentException") and out[3].startswith("ERR java.lang.Illegal")


# --- Java verifies -------------------------------------------------------------------------

def test_pymavlink_and_python_signed_frames_verify_in_java(classes: Path, pm: ModuleType) -> None:
    import ttapi

    mav = pm.MAVLink(None, srcSystem=42, srcComponent=190)
    mav.signing.secret_key = KEY
    mav.signing.sign_outgoing = True
    mav.signing.link_id = 4
    mav.signing.timestamp = now()
    pm_frames = [bytes(pm.MAVLink_heartbeat_message(6, 8, 0, 0, 4, 3).pack(mav)) for _ in range(3)]
    pm_frames.append(bytes(pm.MAVLink_tt_file_data_wide_message(transfer_id=1, offset=9,
                                                                 data=list(range(1, 248))).pack(mav)))
    assert all(f[2] == 1 for f in pm_frames) and len(pm_frames[-1]) == 280
    enc = ttapi.Encoder(sysid=5, compid=6, signing=ttapi.Signing(KEY, link_id=2))
    py_frames = [enc.encode(m) for m in messages()]
    out = java(classes, new(), *[f"CHECK {f.hex()}" for f in pm_frames + py_frames],
               f"CHECK {pm_frames[0].hex()}", f"CHECK {py_frames[-1].hex()}",
               new(), f"PARSE {b''.join(pm_frames + py_frames).hex()}",
               new(), f"RECV {' '.join(p.hex() for p in pack(pm_frames + py_frames))}")
    n = len(pm_frames + py_frames)
    assert out[1:n + 1] == ["RESULT OK"] * n
    assert out[n + 1:n + 3] == ["RESULT REPLAYED"] * 2
    assert out[n + 4].startswith(f"PARSED {n} 0 ") and out[n + 4].count(" S") == n
    assert out[n + 6].startswith(f"RECEIVED {n} 0 ") and out[n + 6].count(" S") == n


def pack(frames: list[bytes]) -> list[bytes]:
    from ttctl.wire.packets import packetize

    return packetize(frames, 100)


@pytest.mark.parametrize("which", [0, 2])  # a 34-byte HEARTBEAT and a 280-byte TT_FILE_DATA_WIDE
def test_any_tampered_byte_is_refused(classes: Path, which: int) -> None:
    good = signed_at(messages()[which], now(), sysid=3)
    cmds, kinds = [new()], []
    for i in range(len(good)):
        for x in (0x01, 0x80, 0xFF):
            bad = bytearray(good)
            bad[i] ^= x
            cmds.append(f"CHECK {bytes(bad).hex()}")
            kinds.append("UNSIGNED_REFUSED" if i == 2 and not bad[2] & 1 else "BAD_SIGNATURE")
    cmds += [f"CHECK {good.hex()}", f"CHECK {good.hex()}"]
    out = java(classes, *cmds)
    assert out[1:-2] == [f"RESULT {k}" for k in kinds]
    assert out[-2:] == ["RESULT OK", "RESULT REPLAYED"]  # refusals recorded nothing; an accepted frame once only
    # through a Parser: of all the tampered copies and the good frame, only the good frame comes out
    stream = b"".join(bytes.fromhex(c.split()[1]) for c in cmds[1:-2]) + good
    out = java(classes, new(), f"PARSE {stream.hex()}", f"PARSE0 {good.hex()}")
    assert out[1].startswith("PARSED 1 ") and out[1].endswith(f" S{messages()[which].MSG_ID}:0:3:1")
    assert out[2].startswith("PARSED 1 0 S")


def test_replayed_and_stale_timestamps_are_refused(classes: Path) -> None:
    hb = messages()[0]
    t = now() + 100 * MINUTE  # the Java clock, fixed
    a, b, c = (signed_at(hb, t - 300 + k * 100, sysid=1) for k in range(3))
    other_stream_older = signed_at(hb, t - 1000, sysid=2)  # per-stream: older than b is fine
    other_link = signed_at(hb, t - 1000, sysid=1, link=9)
    stale = signed_at(hb, t - MINUTE - 1, sysid=3)  # a new stream more than a minute behind us
    recent = signed_at(hb, t - MINUTE + 100, sysid=4)
    ahead = signed_at(hb, t + 50 * MINUTE, sysid=5)
    out = java(classes, new(clock=t), *[f"CHECK {f.hex()}" for f in (b, a, b, c, other_stream_older, other_link,
                                                                     stale, recent, ahead)], "TS")
    assert out[1:10] == ["RESULT OK", "RESULT REPLAYED", "RESULT REPLAYED", "RESULT OK", "RESULT OK", "RESULT OK",
                         "RESULT REPLAYED", "RESULT OK", "RESULT OK"]
    assert out[10] == f"TS {t + 50 * MINUTE}"  # an accepted timestamp ahead of ours moves ours forward
    # our own next timestamp follows it: never behind what we accepted
    out = java(classes, new(clock=t), f"CHECK {ahead.hex()}", f"SIGN {hb.pack().hex()}")
    signed = bytes.fromhex(out[2].split()[1])
    assert int.from_bytes(signed[-12:-6], "little") == t + 50 * MINUTE + 1


def test_wrong_key_and_unsigned_frames(classes: Path) -> None:
    hb = messages()[0]
    wrong = signed_at(hb, now(), key=OTHER_KEY)
    good = signed_at(hb, now(), sysid=9)
    plain = hb.pack(seq=1, sysid=8, compid=1)
    out = java(classes, new(allow=False), f"CHECK {wrong.hex()}", f"CHECK {plain.hex()}",
               f"PARSE {(plain + wrong + good).hex()}",
               f"RECV {plain.hex()} {wrong.hex()}",
               f"PARSE0 {(plain + wrong).hex()}", f"RECV0 {plain.hex()} {wrong.hex()}",
               new(allow=True), f"CHECK {wrong.hex()}", f"CHECK {plain.hex()}", f"CHECK {good.hex()}",
               f"PARSE {(plain + wrong).hex()}")
    assert out[1:3] == ["RESULT BAD_SIGNATURE", "RESULT UNSIGNED_REFUSED"]
    assert out[3] == "PARSED 1 2 S0:0:9:1"
    assert out[4] == "RECEIVED 0 2"
    assert out[5] == "PARSED 2 0 U0:1:8:1 S0:0:1:1"  # without a Signing: as before, signed frames unverified
    assert out[6] == "RECEIVED 2 0 U0:1:8:1 S0:0:1:1"
    assert out[8:11] == ["RESULT BAD_SIGNATURE", "RESULT OK", "RESULT OK"]
    assert out[11] == "PARSED 1 1 U0:1:8:1"


def test_packet_receiver_verifies_spanning_and_slipped_frames_once(classes: Path) -> None:
    """A signed 280-byte frame in three packets with signed urgent packets slipped between the
    pieces: every frame is delivered exactly once (a packet's first frame is probed before it is
    scanned: the probe must not count as having seen its timestamp); replays are refused."""
    t = now()
    wide = signed_at(messages()[2], t + 10, sysid=1)
    u1, u2 = signed_at(messages()[0], t + 11, sysid=2), signed_at(messages()[1], t + 12, sysid=2)
    pieces = pack([wide])
    assert len(pieces) == 3
    packets = [pieces[0], u1, pieces[1], u2, pieces[2]]
    cut = [pieces[0], u1, pieces[2]]  # the middle piece lost
    out = java(classes, new(), "RECV " + " ".join(p.hex() for p in packets),
               "RECV " + " ".join(p.hex() for p in packets),
               new(), "RECV " + " ".join(p.hex() for p in cut))
    assert out[1] == "RECEIVED 3 0 S0:0:2:1 S50004:0:2:1 S50015:0:1:1".replace(
        "S50004", f"S{messages()[1].MSG_ID}").replace("S50015", f"S{messages()[2].MSG_ID}")
    assert out[2].startswith("RECEIVED 0 ")  # the same packets again: all replays
    assert out[4].startswith("RECEIVED 1 ") and out[4].endswith(" S0:0:2:1")


def test_signing_is_thread_safe_and_keys_are_checked(classes: Path) -> None:
    out = java(classes, new(), "THREADS 4 500", new(clock=now()), "THREADS 4 500", "BADKEY",
               "CHECK fd", "CHECK 00112233445566778899aabbccddeeff", "CHECK " + "fd" * 300)
    assert out[1] == "THREADS 2000 2000 2000"
    assert out[3] == "THREADS 2000 2000 2000"  # a stopped clock: still a new timestamp each time
    assert out[4] == "BADKEY 5"
    assert out[5:] == ["RESULT BAD_SIGNATURE"] * 3
