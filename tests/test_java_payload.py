"""PayloadLink, the generated Java runtime's link over DJI Mobile SDK v5's payload data channel
(IPayloadManager, 5.2+; the Payload SDK low-speed channel's 128-byte packets), wired as
docs/dji/tablet-java.md wires it, on stand-ins for the MSDK v5 classes it names
(tests/java/msdk5: DJI's packages and signatures, written from DJI's API reference; packets over
UDP, at most 128 bytes, 3 KB/s, completions on the SDK's thread). The tablet program is
tests/java/payload/PayloadTablet.java, built with javac --release 11 -Xlint:all -Werror.

- End to end: against `ttctl emulate onboard` through `ttctl link relay --profile psdk` at 10 %
  loss: a command acknowledged, an upload and a fetch whose SHA-256 match.
- Bad input: the SDK refuses every send (its words, description and code, reach the command's
  reason, problem() and the state listener; the link backs off), every SDK call throws, the
  SDK's thread floods the listener (200 000 packets, a 64 KiB one every 100th, in a 64 MiB heap):
  no callback holds the SDK's thread, the heap stays small.
"""

from __future__ import annotations

import hashlib
import random
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from conformance_lib import build_java
from conftest import ROOT
from e2e_lib import LOCAL, Start, free_port, relay

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

# the longest an app callback may hold the SDK's thread: a copy and a short lock (a GC pause or
# a busy machine's scheduling on top)
CALLBACK_LIMIT_MS = 250.0


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    drivers = sorted((ROOT / "tests/java/msdk5").rglob("*.java")) + [ROOT / "tests/java/payload/PayloadTablet.java"]
    cls, _ = build_java(tmp_path_factory.mktemp("java_payload"), drivers)
    return cls


def tablet(classes: Path, cwd: Path, udp_port: int, *args: str, heap: str = "256m",
           timeout: float = 300) -> tuple[dict[str, str], str]:
    proc = subprocess.run(["java", f"-Xmx{heap}", f"-Dttctl.msdk.udp={LOCAL}:{udp_port}", "-cp", str(classes),
                           "PayloadTablet", *args], capture_output=True, text=True, timeout=timeout, cwd=cwd)
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, text[-4000:]
    lines = [ln for ln in proc.stdout.splitlines() if ln.startswith("RESULT ")]
    assert lines, text[-4000:]
    return dict(re.findall(r"(\w+)=(\S+)", lines[-1])), text


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def test_upload_fetch_and_command_through_the_psdk_relay(classes: Path, tmp_path: Path, start: Start) -> None:
    a, b = free_port(), free_port()
    (tmp_path / "served").mkdir()
    back = tmp_path / "served" / "flight.log"
    back.write_bytes(random.Random(26).randbytes(6000))
    up = tmp_path / "mission.bin"
    up.write_bytes(random.Random(27).randbytes(8000))
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{b}", "--inbox",
                 str(tmp_path / "inbox"), "--serve", str(tmp_path / "served"), "--no-entry-points", "--profile",
                 "psdk")
    node.wait_for("onboard 1:")
    air = relay(start, a, b, "--profile", "psdk", "--loss", "0.1", "--seed", "26", "--stats-interval", "0")
    r, text = tablet(classes, tmp_path, a, "run=e2e", f"send={up}", "fetch=flight.log", f"dir={tmp_path / 'got'}",
                     "timeout=60")
    assert r["mtu"] == "128" and r["command_ack"] == "TT_COMMAND_ACK", text[-3000:]
    assert r["send_ok"] == "true" and r["fetch_ok"] == "true", text[-3000:]
    assert sha(tmp_path / "inbox" / "mission.bin") == sha(up) == r["send_sha256"]
    assert sha(tmp_path / "got" / "flight.log") == sha(back) == r["fetch_sha256"]
    assert float(r["longest_sdk_callback_ms"]) < CALLBACK_LIMIT_MS, r
    # the relay never dropped a datagram as longer than the channel's 128 bytes
    assert "longer than" not in air.stderr + node.stderr, air.stderr[-2000:]


@pytest.mark.parametrize("mode", ["refuse", "throw"])
def test_the_sdk_refusing_every_send_is_said_in_its_words(classes: Path, tmp_path: Path, mode: str) -> None:
    r, text = tablet(classes, tmp_path, free_port(), f"run={mode}", timeout=120)
    assert r["reason_has_words"] == "true", text[-3000:]  # the command's failure says what the SDK said
    assert r["problem_has_words"] == "true" and r["told_state"] == "true" and r["refusing"] == "true", text[-3000:]
    # backing off: at most one send a second once refusals pile up (not a spin)
    assert int(r["sends_in_3s"]) <= 5, r
    assert float(r["longest_sdk_callback_ms"]) < CALLBACK_LIMIT_MS, r


def test_a_listener_flood_neither_blocks_the_sdk_nor_grows_the_heap(classes: Path, tmp_path: Path) -> None:
    r, _ = tablet(classes, tmp_path, free_port(), "run=flood", "n=200000", heap="64m", timeout=120)
    assert int(r["dropped"]) + int(r["parsed"]) == 200000, r
    assert int(r["heap_mb"]) < 32, r
    assert float(r["longest_sdk_callback_ms"]) < CALLBACK_LIMIT_MS, r
