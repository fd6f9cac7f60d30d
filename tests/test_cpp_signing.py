"""MAVLink 2 signing in the generated C++ runtime (signing.hpp), against two oracles: pymavlink's
signing support and the generated Python runtime (ttapi.mavlink.Signing). Real `ttctl gen`,
real g++ builds (warning-free with -Werror, and under ASan/UBSan), real processes:
tests/cpp/signing_packets/driver.cpp.

- SHA-256 equals hashlib's on random inputs of 0..300 bytes and every block boundary;
- frames C++ signs verify in pymavlink and in Python, with the very signature Python computes;
  frames pymavlink and Python sign verify in C++;
- tampered (every single byte), replayed, older, too old, wrong-key and unsigned (when refused)
  frames are refused, with the same verdicts as Python's Signing;
- the Parser drops (and counts) the frames its Signing refuses; nothing allocates."""

from __future__ import annotations

import random
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import pytest

from conftest import ROOT, TTAPI, run_ttctl

WARN = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
STRICT = ["-Wshadow", "-Wconversion", "-Wsign-conversion"]
DRIVER = ROOT / "tests" / "cpp" / "signing_packets" / "driver.cpp"
KEY = bytes(range(1, 33))
OTHER_KEY = bytes(range(100, 132))
EPOCH_2015 = 1420070400


def now_ts() -> int:
    return int((time.time() - EPOCH_2015) * 100_000)


def gxx(*args: str) -> None:
    proc = subprocess.run(["g++", *args], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-4000:]


def build_driver(tmp: Path) -> dict[str, Path]:
    """ttapi generated into `tmp`, the driver built plain (strict warnings, -Werror) and with
    the sanitizers, in parallel."""
    out = tmp / "out"
    proc = run_ttctl("gen", str(TTAPI), "--lang", "cpp", "-o", str(out), timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    inc = ["-I", str(out / "cpp")]
    bins = {"plain": tmp / "driver", "asan": tmp / "driver_asan"}
    with ThreadPoolExecutor(max_workers=2) as pool:
        jobs = [
            pool.submit(gxx, *WARN, *STRICT, "-O2", *inc, str(DRIVER), "-o", str(bins["plain"])),
            pool.submit(gxx, *WARN, "-O1", "-g", "-fsanitize=address,undefined", "-fno-sanitize-recover=all",
                        "-DTTCTL_TEST_SANITIZE", *inc, str(DRIVER), "-o", str(bins["asan"])),
        ]
        for job in jobs:
            job.result()
    return {"out": out, **bins}


def run(exe: Path, *args: str, lines: list[str]) -> list[str]:
    proc = subprocess.run([str(exe), *args], input="".join(x + "\n" for x in lines), capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 0 and proc.stderr == "", proc.stderr[-3000:]
    return proc.stdout.splitlines()


@pytest.fixture(scope="module")
def drv(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    return build_driver(tmp_path_factory.mktemp("cpp_signing"))


def unsigned_frames(seed: int, count: int = 40) -> list[bytes]:
    """Unsigned frames of ttapi messages (common.xml ones that pymavlink knows, and ttapi's own)."""
    import ttapi

    rng = random.Random(seed)
    enc = ttapi.Encoder(sysid=1, compid=240)
    out = []
    for _ in range(count):
        kind = rng.randrange(5)
        if kind == 0:
            msg: Any = ttapi.Heartbeat(type=2, custom_mode=rng.randrange(2**32))
        elif kind == 1:
            msg = ttapi.ParamSet(target_system=1, target_component=1, param_id="P" * rng.randint(1, 16),
                                 param_value=rng.random(), param_type=9)
        elif kind == 2:
            msg = ttapi.TtCommandAck(command_id=rng.randrange(65536), result=2, progress=100)
        elif kind == 3:
            msg = ttapi.TtFileDataWide(transfer_id=1, offset=rng.randrange(2**32), data=rng.randbytes(247))
        else:
            msg = ttapi.SystemTime(time_unix_usec=rng.randrange(2**63), time_boot_ms=rng.randrange(2**32))
        out.append(enc.encode(msg))
    return out


def cpp_sign(exe: Path, frames: list[bytes], key: bytes, link: int, start: int) -> list[bytes]:
    got = run(exe, "sign", key.hex(), str(link), str(start), lines=[f.hex() for f in frames])
    assert len(got) == len(frames) and "error" not in got
    return [bytes.fromhex(x) for x in got]


def cpp_verify(exe: Path, frames: list[bytes], key: bytes = KEY, ts: int | None = None,
               allow_unsigned: bool = False) -> list[str]:
    args = ["verify", key.hex(), *(["--allow-unsigned"] if allow_unsigned else []),
            *(["--timestamp", str(ts)] if ts is not None else [])]
    got = run(exe, *args, lines=[f.hex() for f in frames])
    assert len(got) == len(frames)
    return got


def py_verdicts(frames: list[bytes], key: bytes = KEY, ts: int | None = None,
                allow_unsigned: bool = False) -> list[bool]:
    """What the generated Python runtime says of each frame, one Signing for all."""
    from ttapi import mavlink

    signing = mavlink.Signing(key, allow_unsigned=allow_unsigned, timestamp=ts)
    out = []
    for f in frames:
        try:
            mavlink.decode(f, signing=signing)
            out.append(True)
        except mavlink.DecodeError:
            out.append(False)
    return out


# --- SHA-256 --------------------------------------------------------------------------------------

@pytest.mark.parametrize("build", ["plain", "asan"])
def test_sha256_matches_hashlib(drv: dict[str, Path], build: str) -> None:
    import hashlib

    rng = random.Random(256)
    inputs = [rng.randbytes(n) for n in range(301)]
    inputs += [bytes([0x61]) * n for n in (55, 56, 57, 63, 64, 65, 119, 120, 127, 128, 129, 1000, 4096)]
    inputs += [rng.randbytes(rng.randint(0, 5000)) for _ in range(30)]
    got = run(drv[build], "sha256", lines=[x.hex() for x in inputs])
    assert got == [hashlib.sha256(x).hexdigest() for x in inputs]


# --- interoperability ------------------------------------------------------------------------------

def test_cpp_signed_frames_verify_in_pymavlink_and_python(drv: dict[str, Path]) -> None:
    from pymavlink.dialects.v20 import common as pm

    from ttapi import mavlink

    frames = unsigned_frames(1)
    t0 = now_ts()
    signed = cpp_sign(drv["plain"], frames, KEY, 7, t0)
    for k, (f, s) in enumerate(zip(frames, signed, strict=True)):
        assert len(s) == len(f) + 13 and s[2] == 0x01 and s[-13] == 7
        assert int.from_bytes(s[-12:-6], "little") == t0 + 1 + k  # max(now, last + 1), from t0
        # the very signature the Python runtime computes (over the frame with the flag and its new CRC)
        assert mavlink.Signing(KEY).signature(s[:-13], 7, t0 + 1 + k) == s[-13:]
        assert mavlink.decode(s).get_signed()  # the new CRC is right
    # Python: every frame verifies, in order, with one Signing
    assert py_verdicts(signed, ts=t0) == [True] * len(signed)
    # pymavlink: the same, with its own signing state (decode() verifies when a key is set)
    mav = pm.MAVLink(None)
    mav.signing.secret_key = KEY
    mav.signing.timestamp = t0
    for s in signed:
        if (s[7] | s[8] << 8 | s[9] << 16) in pm.mavlink_map:
            msg = mav.decode(bytearray(s))
            assert msg.get_signed()
        else:  # a ttapi message pymavlink does not know: its signature check alone
            assert mav.check_signature(bytearray(s), s[5], s[6])
    assert mav.signing.badsig_count == 0 and mav.signing.goodsig_count > 10
    # and pymavlink refuses a frame signed with another key
    wrong = cpp_sign(drv["plain"], frames[:1], OTHER_KEY, 8, t0)[0]
    assert not mav.check_signature(bytearray(wrong), wrong[5], wrong[6])


def test_pymavlink_and_python_signed_frames_verify_in_cpp(drv: dict[str, Path]) -> None:
    from pymavlink.dialects.v20 import common as pm

    import ttapi
    from ttapi import mavlink

    t0 = now_ts()
    mav = pm.MAVLink(None, srcSystem=3, srcComponent=1)
    mav.signing.secret_key = KEY
    mav.signing.link_id = 2
    mav.signing.timestamp = t0
    mav.signing.sign_outgoing = True
    pm_frames = [bytes(pm.MAVLink_heartbeat_message(2, 3, 0, i, 4, 3).pack(mav)) for i in range(10)]
    pm_frames += [bytes(pm.MAVLink_param_set_message(1, 1, b"RATE", i / 3, 9).pack(mav)) for i in range(10)]
    signing = mavlink.Signing(KEY, link_id=5, timestamp=t0)
    enc = ttapi.Encoder(sysid=4, compid=240, signing=signing)
    py_frames = [enc.encode(ttapi.TtFileDataWide(transfer_id=1, offset=i, data=bytes([i]) * 247)) for i in range(10)]
    py_frames += [enc.encode(ttapi.Heartbeat(type=2)) for _ in range(10)]
    assert all(f[2] == 0x01 for f in pm_frames + py_frames)
    for build in ("plain", "asan"):
        assert cpp_verify(drv[build], pm_frames + py_frames, ts=t0) == ["ok"] * 40
        # interleaved streams too, each in its own order
        mixed = [f for pair in zip(pm_frames, py_frames, strict=True) for f in pair]
        assert cpp_verify(drv[build], mixed, ts=t0) == ["ok"] * 40
        assert cpp_verify(drv[build], pm_frames + py_frames, key=OTHER_KEY, ts=t0) == ["refused:bad_signature"] * 40


# --- refusals ------------------------------------------------------------------------------------

def check_against_python(got: list[str], frames: list[bytes], **kw: Any) -> None:
    assert [g == "ok" for g in got] == py_verdicts(frames, **kw)


def test_every_single_byte_flipped_is_refused(drv: dict[str, Path]) -> None:
    rng = random.Random(3)
    t0 = now_ts()
    signed = cpp_sign(drv["plain"], unsigned_frames(2, 4), KEY, 1, t0)
    for s in signed:
        tampered = []
        for i in range(len(s)):
            b = bytearray(s)
            b[i] ^= rng.randint(1, 255)
            tampered.append(bytes(b))
        got = cpp_verify(drv["plain"], [*tampered, s], ts=t0)
        assert got[-1] == "ok"  # the original, after all its tampered copies
        assert all(g.startswith("refused:") for g in got[:-1])
        # a byte of the signature block (not covered by the CRC) fails the signature itself
        assert all(g == "refused:bad_signature" for g in got[len(s) - 13:-1]), got[len(s) - 13:]
        check_against_python(got, [*tampered, s], ts=t0)


def test_replayed_old_too_old_wrong_key_and_unsigned_are_refused(drv: dict[str, Path]) -> None:
    exe = drv["plain"]
    t0 = now_ts()
    frames = unsigned_frames(4, 6)
    a = cpp_sign(exe, frames, KEY, 1, t0)  # timestamps t0+1 .. t0+6
    cases: list[tuple[list[bytes], list[str], dict[str, Any]]] = [
        ([a[0], a[0]], ["ok", "refused:replayed"], {}),
        ([a[3], a[2], a[4]], ["ok", "refused:replayed", "ok"], {}),
        # a stream heard for the first time: at most a minute behind us
        (cpp_sign(exe, frames[:1], KEY, 2, t0 - 6_000_100), ["refused:too_old"], {}),
        (cpp_sign(exe, frames[:1], KEY, 2, t0 - 5_900_000), ["ok"], {}),
        # ahead of us: accepted, and moves our timestamp (so a new stream behind it is too old)
        ([*cpp_sign(exe, frames[:1], KEY, 3, t0 + 50_000_000), *cpp_sign(exe, frames[1:2], KEY, 4, t0)],
         ["ok", "refused:too_old"], {}),
        (cpp_sign(exe, frames[:2], OTHER_KEY, 1, t0), ["refused:bad_signature"] * 2, {}),
        (frames[:2], ["refused:unsigned"] * 2, {}),
        (frames[:2] + a[:1], ["ok", "ok", "ok"], {"allow_unsigned": True}),
        ([frames[0][:-1], a[0][:-1], a[0] + b"\x00"], ["refused:bad_frame"] * 3, {}),
    ]
    for frames_in, want, kw in cases:
        for build in ("plain", "asan"):
            got = cpp_verify(drv[build], frames_in, ts=t0, **kw)
            assert got == want, (want, kw)
        check_against_python(got, frames_in, ts=t0, **kw)


def test_stream_table_is_bounded_and_evicts_the_least_recent(drv: dict[str, Path]) -> None:
    """32 streams are remembered; the 33rd replaces the one heard from least recently, whose
    replay then counts as a new stream (accepted within the minute) -- the documented price of
    a table without heap."""
    import ttapi

    t0 = now_ts()
    frames = [ttapi.Encoder(sysid=1, compid=c).encode(ttapi.Heartbeat()) for c in range(40)]
    signed = [cpp_sign(drv["plain"], [f], KEY, 0, t0 + i)[0] for i, f in enumerate(frames)]
    got = cpp_verify(drv["plain"], [*signed[:33], signed[0], signed[32], signed[1]], ts=t0)
    assert got == ["ok"] * 33 + ["ok", "refused:replayed", "ok"]
    got = cpp_verify(drv["plain"], [*signed[:32], signed[0]], ts=t0)
    assert got == ["ok"] * 32 + ["refused:replayed"]


# --- the parser ----------------------------------------------------------------------------------

def test_parser_verifies_and_counts_bad_signatures(drv: dict[str, Path]) -> None:
    from ttapi import mavlink

    exe = drv["plain"]
    rng = random.Random(9)
    t0 = now_ts()
    frames = unsigned_frames(5, 60)
    good = cpp_sign(exe, frames, KEY, 1, t0)
    wrong = cpp_sign(exe, frames[:5], OTHER_KEY, 2, t0)
    stream: list[bytes] = []
    want: list[bytes] = []
    bad = 0
    for i, g in enumerate(good):
        stream.append(g)
        want.append(g)
        if i % 10 == 3:
            stream.append(g)  # replayed
            bad += 1
        if i % 10 == 5:
            stream.append(wrong[i // 10 % 5])
            bad += 1
        if i % 10 == 7:
            stream.append(frames[i])  # unsigned
            bad += 1
        if i % 10 == 9:
            stream.append(rng.randbytes(rng.randint(1, 30)).replace(b"\xfd", b"\x00"))  # garbage
    data = b"".join(stream)
    cuts = sorted(rng.sample(range(1, len(data)), 200))
    chunks = [data[a:b] for a, b in zip([0, *cuts], [*cuts, len(data)], strict=True)]
    for build in ("plain", "asan"):
        out = run(drv[build], "parse", KEY.hex(), "--timestamp", str(t0), lines=[c.hex() for c in chunks])
        got = [bytes.fromhex(x[2:]) for x in out[:-1]]
        messages, bad_crc, _unknown, _flags, bad_signature, skipped = map(int, out[-1].split()[1:])
        assert got == want and messages == len(want)
        assert bad_signature == bad and bad_crc == 0
        assert skipped == len(data) - sum(map(len, want))
    # the Python Parser agrees on what is refused
    parser = mavlink.Parser(signing=mavlink.Signing(KEY, timestamp=t0))
    msgs = [m for c in chunks for m in parser.feed(c)] + parser.flush()
    assert len(msgs) == len(want) and parser.stats.bad_signature == bad
    # with unsigned frames allowed only the replays and the wrong key are refused
    out = run(exe, "parse", KEY.hex(), "--allow-unsigned", "--timestamp", str(t0), lines=[data.hex()])
    assert int(out[-1].split()[5]) == bad - 6 and len(out) - 1 == len(want) + 6
    # and without a Signing, everything with a valid CRC comes out
    out = run(exe, "parse", "-", lines=[data.hex()])
    assert len(out) - 1 == len(want) + bad and int(out[-1].split()[5]) == 0


def test_garbage_under_the_sanitizers(drv: dict[str, Path]) -> None:
    """Random bytes, random frames with random signature blocks, truncated signed frames: no
    crash, no leak, no undefined behaviour; nothing random verifies."""
    rng = random.Random(11)
    t0 = now_ts()
    signed = cpp_sign(drv["plain"], unsigned_frames(6, 30), KEY, 1, t0)
    lines = [rng.randbytes(rng.randint(0, 400)).hex() for _ in range(200)]
    lines += [(s[:-13] + rng.randbytes(13)).hex() for s in signed]
    lines += [s[:rng.randint(0, len(s) - 1)].hex() for s in signed]
    lines += [(b"\xfd" + rng.randbytes(rng.randint(0, 300))).hex() for _ in range(200)]
    got = run(drv["asan"], "verify", KEY.hex(), "--timestamp", str(t0), lines=lines)
    assert all(g.startswith("refused:") for g in got)
    out = run(drv["asan"], "parse", KEY.hex(), "--timestamp", str(t0), lines=lines)
    assert out[-1].startswith("S 0 ")
    out = run(drv["asan"], "packets", KEY.hex(), "--timestamp", str(t0), lines=lines + ["FLUSH"])
    assert out[-1].startswith(f"S {len(lines)} 0 ")  # FLUSH is no packet
    signed_again = run(drv["asan"], "sign", KEY.hex(), "1", lines=lines)
    assert len(signed_again) == len(lines)


def test_signing_allocates_nothing(drv: dict[str, Path]) -> None:
    """Encoder with a Signing, Signing::sign, a Parser and a PacketReceiver verifying: no call
    of operator new (replaced by a counter in the plain build)."""
    assert run(drv["plain"], "noalloc", KEY.hex(), lines=[]) == ["ok 80"]
    assert run(drv["asan"], "noalloc", KEY.hex(), lines=[]) == ["ok skipped"]


def test_generated_signing_and_packets_headers(drv: dict[str, Path], tmp_path: Path) -> None:
    """Each new header compiles on its own with strict warnings, and is formatted like the rest."""
    cpp = drv["out"] / "cpp"
    for h in ("signing.hpp", "packets.hpp"):
        src = tmp_path / f"only_{h}.cpp"
        src.write_text(f'#include "ttapi/{h}"\n\nint main()\n{{\n    return 0;\n}}\n')
        gxx(*WARN, *STRICT, "-fsyntax-only", "-I", str(cpp), str(src))
        lines = (cpp / "ttapi" / h).read_text().split("\n")
        assert lines[0] == "// Generated by ttctl gen from ttapi.xml; do not edit."
        assert lines[-1] == "" and lines[-2] != ""
        for no, line in enumerate(lines, 1):
            assert "\t" not in line and line == line.rstrip() and len(line) <= 120, f"{h}:{no}"
    runtime = (cpp / "ttapi" / "runtime.hpp").read_text()
    assert "not verified" not in runtime and '#include "signing.hpp"' in runtime
