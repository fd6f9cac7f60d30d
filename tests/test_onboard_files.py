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


def test_the_tablets_telemetry_keeps_its_wall_clock_rate_at_any_speed(tmp_path: Path, start: Any) -> None:
    """HEARTBEAT (1 Hz) and --telemetry-hz (2) go to the tablet per second of the wall clock, as
    the link runs: at --speed 4 they went four times as often, and a download from the onboard
    end's --serve moved at 0.53 of the downlink instead of 0.59 (recv-file --serve: 0.63; the
    rest is this telemetry, about 280 B/s of the 6700)."""
    import socket
    import time

    from conftest import shipped

    b = shipped()
    port = free_port()
    start("onboard", "emulate", "onboard", "--listen", f"udpin:{LOCAL}:{port}", "--no-gcs", "--speed", "4"
          ).wait_for(f"onboard 1: tablet link udpin:{LOCAL}:{port}", timeout=30)
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sock.bind((LOCAL, 0))
    sock.settimeout(0.2)
    hello = b.encoder(255, 190).encode(b.Heartbeat(type=6, autopilot=8))
    parser = b.parser()
    counts: dict[str, int] = {}
    try:
        sock.sendto(hello, (LOCAL, port))
        first = time.monotonic() + 1.0  # heard, and settled
        end = first + 4.0
        while time.monotonic() < end:
            try:
                data, _ = sock.recvfrom(65535)
            except TimeoutError:
                continue
            if time.monotonic() < first:
                continue
            for msg in parser.feed(data):
                name = f"{type(msg).__name__}/{msg.get_srcComponent()}"
                counts[name] = counts.get(name, 0) + 1
    finally:
        sock.close()
    assert 3 <= counts.get("Heartbeat/240", 0) <= 6, counts  # 1 Hz for 4 s (16 on the vehicle's clock)
    assert 6 <= counts.get("TtNavSatFix/240", 0) <= 10, counts  # 2 Hz (32 before)
