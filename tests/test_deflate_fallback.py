"""A deflating `ttctl send-file` against the receivers that do not inflate yet (the generated C++
onboard node and the Java FileTransfers inbox): each refuses the DEFLATE offer with
REFUSED_UNSUPPORTED in words naming the flag, and the sender offers the file again as it is
and completes; the receiver holds the file, nothing else."""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

import pytest

from cpp_node_lib import needs_gxx, sha
from e2e_lib import LOCAL, Start, send
from ttctl.bench.textfiles import mission_yaml

REFUSAL = "offer flags 0x04 not understood here: this receiver does not decompress"


@needs_gxx
def test_the_cpp_node_refuses_deflate_and_the_sender_falls_back(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                                 cpp_nodes: Any) -> None:
    text = tmp_path / "mission.yaml"
    text.write_bytes(mission_yaml())
    inbox = tmp_path / "inbox"
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox))
    proc, r = send(str(text), "--to", f"udpout:{LOCAL}:{node.port}", "--rate", "8000", timeout=60)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert r["deflate_fallback"] == REFUSAL and r["deflated_bytes"] is None, r
    assert sha(inbox / "mission.yaml") == sha(text)
    refused = node.events("refused")
    assert len(refused) == 1 and refused[0]["reason"] == REFUSAL, refused
    assert sorted(p.name for p in inbox.iterdir() if p.is_file()) == ["mission.yaml"]
    node.stop()


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
