"""A deflating `ttctl send-file` against the receivers that do not inflate yet (the Java
FileTransfers inbox; the generated C++ onboard node built with TTCTL_NO_ZLIB is in
test_cpp_node_deflate.py): each refuses the DEFLATE offer with
REFUSED_UNSUPPORTED in words naming the flag, and the sender offers the file again as it is
and completes; the receiver holds the file, nothing else."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from cpp_node_lib import sha
from e2e_lib import LOCAL, Start
from ttctl.bench.textfiles import mission_yaml

REFUSAL = "offer flags 0x04 not understood here: this receiver does not decompress"


@pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None, reason="needs a JDK")
def test_the_java_inbox_refuses_deflate_and_the_sender_falls_back(tmp_path: Path, start: Start) -> None:
    from conformance_lib import build_java
    from e2e_lib import free_port
    from test_java_session import DRIVERS, drone_send, stop, tablet_inbox

    classes, _ = build_java(tmp_path / "build", DRIVERS)
    (tmp_path / "outbox").mkdir()
    port = free_port()
    j = tablet_inbox(classes, tmp_path, "tablet", port)
    text = tmp_path / "mission.yaml"
    text.write_bytes(mission_yaml())
    proc, r = drone_send(str(text), "--to", f"udpout:{LOCAL}:{port}", "--rate", "8000", "--timeout", "30")
    assert proc.returncode == 0 and r["ok"], proc.stdout + proc.stderr
    assert r["deflate_fallback"] == REFUSAL and r["deflated_bytes"] is None, r
    assert sha(tmp_path / "inbox" / "mission.yaml") == sha(text)
    stop(j, tmp_path)


@pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None, reason="needs a JDK")
def test_a_java_fetch_of_text_from_recv_file_serve_falls_back_to_the_file(tmp_path: Path, start: Start) -> None:
    """The server (recv-file --serve) offers the text deflated; the Java requester refuses that
    in words and the server sends the file as it is."""
    from conformance_lib import build_java
    from e2e_lib import free_port, receiver
    from test_java_transfer import DRIVERS, Driver
    from ttctl.bench.textfiles import flight_log_csv

    classes, _ = build_java(tmp_path / "build", sorted(DRIVERS.glob("*.java")))
    (tmp_path / "serve").mkdir()
    (tmp_path / "serve" / "log.csv").write_bytes(flight_log_csv(seconds=60))
    port = free_port()
    rx = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--rate", "50000", "--serve", str(tmp_path / "serve"))
    r = Driver(classes, tmp_path, "java", link="udp", port=port, rate=50000, timeout=30, fetch="log.csv",
               dir="got").finish(120)
    assert r["fetch_ok"], r["_text"][-3000:]
    assert sha(tmp_path / "got" / "log.csv") == sha(tmp_path / "serve" / "log.csv") == r["fetch_sha256"]
    rx.wait_for("served log.csv", where="stdout")
