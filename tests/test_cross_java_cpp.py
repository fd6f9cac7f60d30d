"""The two generated runtimes against each other, with no Python end in between: the Java tablet
(tests/java/transfer/TabletDriver.java on the generated runtime) and the C++ onboard node
(tests/cpp/node/onboard_node.cpp, built from the generated skeleton as a user edits it), through
`ttctl link relay --profile m100` at 10 % random and burst loss. An upload into the node's inbox
and a fetch from its served folder at once, commands before and during: both files intact, every
command acknowledged, and each executed exactly once by the node however often the relay made
the tablet retry. Then the same signed (MAVLink 2 signing, one key at both ends)."""

from __future__ import annotations

import random
import shutil
from pathlib import Path
from typing import Any

import pytest

from conformance_lib import build_java
from conftest import ROOT
from cpp_node_lib import PROGRAM, WARN, Node, generate, gxx, sha
from e2e_lib import LOCAL, Start, free_port, relay

pytestmark = pytest.mark.skipif(shutil.which("g++") is None or shutil.which("javac") is None,
                                reason="needs g++ and a JDK")

RATE = 8000  # B/s both ways: the relay's, the node's and the tablet's pace
SIZE = 24 * 1024


@pytest.fixture(scope="module")
def programs(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """(the C++ node, the Java classes), each from a freshly generated tree."""
    tmp = tmp_path_factory.mktemp("cross")
    exe = tmp / "onboard_node"
    gxx(*WARN, "-O2", *generate(tmp), str(PROGRAM), "-o", str(exe))
    classes, _ = build_java(tmp / "java", sorted((ROOT / "tests" / "java" / "transfer").glob("*.java")))
    return exe, classes


# signed: TT_FILE_DATA_FIT frames of one 100-byte packet (66 file bytes) both ways
@pytest.mark.parametrize(("model", "signed"), [("random", False), ("burst", False), ("random", True)])
def test_java_tablet_and_cpp_node(programs: tuple[Path, Path], tmp_path: Path, start: Start, model: str,
                                  signed: bool) -> None:
    from test_java_transfer import Driver

    exe, classes = programs
    inbox, serve = tmp_path / "inbox", tmp_path / "serve"
    serve.mkdir()
    up = tmp_path / "up.bin"
    up.write_bytes(random.Random(1).randbytes(SIZE))
    back = serve / "logs" / "back.bin"
    back.parent.mkdir()
    back.write_bytes(random.Random(2).randbytes(SIZE))
    key_args: list[str] = []
    driver_key: dict[str, Any] = {}
    if signed:
        key = random.Random(3).randbytes(32).hex()
        (tmp_path / "key").write_text(key + "\n")
        key_args = ["--key", str(tmp_path / "key")]
        driver_key = {"key": key}
    b = free_port()
    node = Node(exe, tmp_path, "node", "--listen", f"udpin:{LOCAL}:{b}", "--inbox", str(inbox), "--serve", str(serve),
                "--rate", str(RATE), *key_args)
    try:
        a = free_port()
        relay(start, a, b, "--profile", "m100", "--rate", str(RATE), "--loss", "0.1", "--loss-model", model,
              "--seed", "7", "--stats-interval", "0")
        d = Driver(classes, tmp_path, "java", link="dji" if signed else "udp", port=a, rate=RATE, timeout=30,
                   send=up.name, fetch="logs/back.bin", dir="got", idle=3, during=700, **driver_key)
        r = d.finish(180)
        assert r["send_ok"] and r["fetch_ok"], r["_text"][-3000:]
        assert sha(inbox / "up.bin") == sha(up) == r["send_sha256"]
        assert sha(tmp_path / "got" / "logs" / "back.bin") == sha(back) == r["fetch_sha256"]
        assert not list((tmp_path / "got").rglob("*.part"))
        acked = len(r["idle_ms"]) + len(r["during_ms"])
        # the 3 idle commands and at least one while files move (how many fit in the transfer depends on
        # the machine's load and the losses: a fresh-clone run had one, retried for 3.6 s, in a quick upload)
        assert r["idle_failed"] == 0 and not r["during_errors"] and r["refused"] == 0, r
        assert len(r["idle_ms"]) == 3 and len(r["during_ms"]) >= 1, r
        commands = node.events("command")
        ran = [c for c in commands if not c["repeated"]]
        assert len(ran) == acked, commands  # each command the tablet sent ran once, retried or not
        assert len({c["command_id"] for c in ran}) == len(ran)
        stats = node.stop()
        assert stats["executed"] == acked and stats["duplicates"] == len(commands) - len(ran), stats
        print("MEASURED", {"model": model, "signed": signed, "commands": acked, "repeated_acks": stats["duplicates"],
                           "send_efficiency": round(r["send_efficiency"], 3),
                           "fetch_efficiency": round(r["fetch_efficiency"], 3)})
    finally:
        node.kill()
