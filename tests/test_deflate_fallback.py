"""A deflating `ttctl send-file` against a receiver that does not inflate yet (the generated C++
onboard node): it refuses the DEFLATE offer with REFUSED_UNSUPPORTED in words naming the flag,
and the sender offers the file again as it is and completes; the receiver holds the file,
nothing else. (The Java runtime inflates: tests/test_java_deflate.py.)"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from cpp_node_lib import needs_gxx, sha
from e2e_lib import LOCAL, send
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

