"""Signing across the three generated runtimes: frames signed by C++ verify in Java and in the
Python runtime, frames signed by Java verify in C++ and Python, frames signed by Python verify in
both; in each, a replayed frame, any single flipped byte and the wrong key are refused. (Each
language is also checked against pymavlink in its own test file.) Real g++ and javac builds, one
process per language per run."""

from __future__ import annotations

import random
import shutil
import subprocess
import time
from pathlib import Path
from typing import Any

import pytest

import ttapi
from conftest import ROOT, TTAPI, run_ttctl

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("g++") is None,
                                reason="needs a JDK and g++")

KEY = bytes(range(100, 132))
OTHER = bytes(range(32))


def _now() -> int:
    return int((time.time() - 1420070400) * 100_000)


@pytest.fixture(scope="module")
def tools(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    base = tmp_path_factory.mktemp("signing_cross")
    out = base / "gen"
    proc = run_ttctl("gen", str(TTAPI), "--lang", "cpp,java", "-o", str(out), timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    exe = base / "driver"
    cpp = subprocess.Popen(["g++", "-std=c++17", "-O1", "-Wall", "-Wextra", "-Wpedantic", "-Werror", "-I",
                            str(out / "cpp"), str(ROOT / "tests" / "cpp" / "signing_packets" / "driver.cpp"), "-o",
                            str(exe)], stderr=subprocess.PIPE, text=True)
    classes = base / "classes"
    sources = [str(p) for p in (out / "java").rglob("*.java")] + \
        [str(p) for p in (ROOT / "tests" / "java" / "signing").glob("*.java")]
    javac = subprocess.run(["javac", "--release", "11", "-Xlint:all", "-Werror", "-encoding", "UTF-8", "-d",
                            str(classes), *sources], capture_output=True, text=True, timeout=600)
    assert javac.returncode == 0, javac.stderr[-4000:]
    _, err = cpp.communicate(timeout=600)
    assert cpp.returncode == 0, err[-4000:]
    return {"cpp": exe, "java": classes}


def _frames(seed: int) -> list[bytes]:
    rng = random.Random(seed)
    msgs: list[Any] = []
    for k in range(12):
        msgs += [ttapi.Heartbeat(type=2, custom_mode=rng.randrange(2**32)),
                 ttapi.TtCommandAck(command_id=rng.randrange(65536), result=2, progress=100),
                 ttapi.TtFileDataWide(transfer_id=k, offset=rng.randrange(2**32), data=rng.randbytes(247))]
    return [m.pack(seq=i % 256, sysid=1 + i % 3, compid=240) for i, m in enumerate(msgs)]


def _cpp(tools: dict[str, Path], *args: str, lines: list[bytes]) -> list[str]:
    proc = subprocess.run([str(tools["cpp"]), *args], input="".join(f.hex() + "\n" for f in lines),
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-2000:]
    return proc.stdout.splitlines()


def _java(tools: dict[str, Path], *commands: str) -> list[str]:
    proc = subprocess.run(["java", "-cp", str(tools["java"]), "SigningDriver"], input="\n".join(commands) + "\n",
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-2000:]
    lines = proc.stdout.splitlines()
    assert lines[-1] == "DONE" and len(lines) == len(commands) + 1, proc.stdout[-2000:]
    return lines[1:-1]  # without NEW's OK


def _java_new(key: bytes, link: int) -> str:
    return f"NEW {key.hex()} {link} 0 sys"


def _python_verdicts(frames: list[bytes], key: bytes) -> list[bool]:
    signing = ttapi.Signing(key)
    out = []
    for f in frames:
        try:
            ttapi.decode(f, signing=signing)
            out.append(True)
        except ttapi.DecodeError:
            out.append(False)
    return out


def _tampered(frames: list[bytes], seed: int) -> list[bytes]:
    rng = random.Random(seed)
    out = []
    for f in frames:
        b = bytearray(f)
        b[rng.randrange(1, len(b))] ^= 1 << rng.randrange(8)
        out.append(bytes(b))
    return out


def test_cpp_signed_frames_verify_in_java_and_python(tools: dict[str, Path]) -> None:
    signed = [bytes.fromhex(x) for x in _cpp(tools, "sign", KEY.hex(), "3", str(_now()), lines=_frames(1))]
    assert all(f[2] & 1 and len(f) == 12 + f[1] + 13 for f in signed)
    assert _java(tools, _java_new(KEY, 0), *[f"CHECK {f.hex()}" for f in signed]) == ["RESULT OK"] * len(signed)
    assert _python_verdicts(signed, KEY) == [True] * len(signed)
    # refusals, in Java: the same frames again (replays), tampered copies, the wrong key
    again = _java(tools, _java_new(KEY, 0), *[f"CHECK {f.hex()}" for f in signed + signed[:5]])
    assert again[-5:] == ["RESULT REPLAYED"] * 5
    tampered = _tampered(signed, 2)
    assert all(x != "RESULT OK" for x in _java(tools, _java_new(KEY, 0), *[f"CHECK {f.hex()}" for f in tampered]))
    assert all(x == "RESULT BAD_SIGNATURE" for x in _java(tools, _java_new(OTHER, 0),
                                                          *[f"CHECK {f.hex()}" for f in signed]))


def test_java_signed_frames_verify_in_cpp_and_python(tools: dict[str, Path]) -> None:
    out = _java(tools, _java_new(KEY, 9), *[f"SIGN {f.hex()}" for f in _frames(3)])
    signed = [bytes.fromhex(x.split()[1]) for x in out]
    assert all(x.startswith("SIGNED ") for x in out) and all(f[-13] == 9 for f in signed)
    assert _cpp(tools, "verify", KEY.hex(), lines=signed) == ["ok"] * len(signed)
    assert _python_verdicts(signed, KEY) == [True] * len(signed)
    assert _cpp(tools, "verify", KEY.hex(), lines=signed + signed[:3])[-3:] == ["refused:replayed"] * 3
    assert all(x.startswith("refused:") for x in _cpp(tools, "verify", KEY.hex(), lines=_tampered(signed, 4)))
    assert _cpp(tools, "verify", OTHER.hex(), lines=signed) == ["refused:bad_signature"] * len(signed)


def test_python_signed_frames_verify_in_cpp_and_java(tools: dict[str, Path]) -> None:
    enc = ttapi.Encoder(1, 240, ttapi.Signing(KEY, link_id=4))
    signed = [enc.encode(ttapi.decode(f)) for f in _frames(5)]
    assert _cpp(tools, "verify", KEY.hex(), lines=signed) == ["ok"] * len(signed)
    assert _java(tools, _java_new(KEY, 0), *[f"CHECK {f.hex()}" for f in signed]) == ["RESULT OK"] * len(signed)
    unsigned = _frames(6)[:4]
    assert _cpp(tools, "verify", KEY.hex(), lines=unsigned) == ["refused:unsigned"] * 4
    assert _java(tools, _java_new(KEY, 0), *[f"CHECK {f.hex()}" for f in unsigned]) == \
        ["RESULT UNSIGNED_REFUSED"] * 4
