"""Files arriving at `ttctl emulate onboard`, as real processes on loopback: it says what it
accepted, refused or failed in the words `recv-file` uses, the refuser's reason included."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from conftest import run_ttctl
from e2e_lib import LOCAL, free_port


def test_onboard_says_what_it_refused_with_its_reason(tmp_path: Path, start: Any) -> None:
    port = free_port()
    inbox = tmp_path / "inbox"
    inbox.mkdir()
    (inbox / "plan.bin").write_bytes(b"the one already here\n" * 10)
    (tmp_path / "plan.bin").write_bytes(bytes(range(256)) * 8)
    node = start("onboard", "emulate", "onboard", "--listen", f"udpin:{LOCAL}:{port}", "--no-gcs",
                 "--inbox", str(inbox))
    node.wait_for(f"onboard 1: tablet link udpin:{LOCAL}:{port}", timeout=30)
    proc = run_ttctl("send-file", "plan.bin", "--to", f"udpout:{LOCAL}:{port}", "--rate", "8000", "--timeout", "30",
                     cwd=tmp_path, timeout=60)
    assert proc.returncode != 0, proc.stdout + proc.stderr
    node.wait_for("refused plan.bin from ", timeout=10)
    line = next(x for x in node.stderr.splitlines() if "refused plan.bin from " in x)
    reason = line.split("refused plan.bin from ", 1)[1].split(": ", 1)[1]
    assert reason and reason in proc.stdout + proc.stderr  # the sender was told the same words
    assert (inbox / "plan.bin").read_bytes() == b"the one already here\n" * 10
    assert not (inbox / ".ttctl-partial").exists()
