"""`ttctl bench latency`: command latency idle and during transfers, on the link model (virtual
time) and live against real processes on 127.0.0.1."""

from __future__ import annotations

import json
import time
from pathlib import Path
from typing import Any

from conftest import assert_no_traceback, run_ttctl
from e2e_lib import LOCAL, data_file, free_port, one_line, relay
from ttctl.bench import latency as lat
from ttctl.bench.transfer import command_latency
from ttctl.link.model import load_profile

PHASE_FIELDS = {"phase", "count", "failed", "retries", "p50_ms", "p95_ms", "max_ms", "transfers", "transfer_bytes",
                "note", "p95_ratio_to_idle", "p50_ratio_to_idle"}


def _model(*extra: str) -> dict[str, Any]:
    proc = run_ttctl("bench", "latency", "--json", *extra, timeout=60)
    assert_no_traceback(proc)
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def test_model_is_deterministic_for_a_seed_and_reports_every_field() -> None:
    a = _model("--count", "30", "--seed", "3")
    b = _model("--count", "30", "--seed", "3")
    assert a == b
    c = _model("--count", "30", "--seed", "4")
    assert [p["p50_ms"] for p in c["phases"]] != [p["p50_ms"] for p in a["phases"]] or \
        [p["max_ms"] for p in c["phases"]] != [p["max_ms"] for p in a["phases"]]
    assert a["mode"] == "model" and a["profile"] == "m100" and a["count"] == 30
    assert [p["phase"] for p in a["phases"]] == ["idle", "upload", "download"]
    for p in a["phases"]:
        assert set(p) == PHASE_FIELDS
        assert p["count"] == 30 and p["failed"] == 0
        assert p["p50_ms"] <= p["p95_ms"] <= p["max_ms"]
    up, down = a["phases"][1], a["phases"][2]
    assert up["transfer_bytes"] > 0 and down["transfer_bytes"] > 0  # the link really was busy
    assert down["transfers"] > 1  # 64 KiB down lasts ~10 s: sent again for the 30 commands
    assert {c["check"] for c in a["checks"]} == {"command p95 during upload", "command p95 during download"}


def test_model_during_transfer_within_the_schedulers_bound() -> None:
    """A command waits at most for the packet on the air: during-upload p95 <= idle p95 + one
    full packet's time + a small margin; and the upload does cost about that packet time."""
    prof = load_profile("m100")
    packet = lat.packet_time(prof, 10.0)
    phases = lat.run_model(prof, 10.0, 60, 5, 1.0, 65536)
    idle, up, down = phases
    assert idle.p95_ms is not None and up.p95_ms is not None and down.p95_ms is not None
    assert up.p95_ms <= idle.p95_ms + 1000 * packet + 50
    assert down.p95_ms <= idle.p95_ms + 1000 * packet + 50
    assert up.p95_ms > idle.p95_ms + 0.5 * 1000 * packet  # measured during a busy uplink, not idle again
    assert idle.p50_ms is not None and idle.p50_ms > 1000 * (prof.up.latency_s + prof.down.latency_s)
    rep = lat.report(phases, {}, packet + 0.05)
    assert all(c["ok"] for c in rep["checks"])
    # and the check can fail: a bound below what the upload costs
    rep = lat.report(phases, {}, 0.01)
    assert not next(c for c in rep["checks"] if c["check"] == "command p95 during upload")["ok"]


def test_bench_transfer_shares_the_measurement() -> None:
    prof = load_profile("m100")
    cmds, files, _ = lat.model_commands(prof, 10.0, "upload", 20, 7, 2.0,
                                        int(prof.capacity_Bps("up", 10.0) * 2.0 * 25), restart=False)
    assert command_latency(prof, 10.0, True, count=20) == [c.latency for c in cmds]
    assert files == 1


def test_live_through_the_relay(start: Any, tmp_path: Path) -> None:
    (tmp_path / "inbox").mkdir()
    (tmp_path / "serve").mkdir()
    data_file(tmp_path / "serve", "big.bin", 64 * 1024)
    onboard, edge = free_port(), free_port()
    p = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{onboard}", "--inbox",
              str(tmp_path / "inbox"), "--serve", str(tmp_path / "serve"), "--profile", "m100")
    p.wait_for("tablet link")
    relay(start, edge, onboard, "--profile", "m100", "--seed", "1")
    t0 = time.monotonic()
    proc = run_ttctl("bench", "latency", "--to", f"udpout:{LOCAL}:{edge}", "--count", "10", "--interval", "0.5",
                     "--fetch", "big.bin", "--json", timeout=90)
    assert_no_traceback(proc)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert time.monotonic() - t0 < 60
    rep = json.loads(proc.stdout)
    assert rep["mode"] == "live" and rep["upload_name"].startswith("ttctl-bench/latency-")
    assert "download: command 10/10" in proc.stderr  # progress on stderr
    idle, up, down = rep["phases"]
    prof = load_profile("m100")
    relay_rtt = 1000 * (prof.up.latency_s + prof.down.latency_s)
    for ph in (idle, up, down):
        assert set(ph) == PHASE_FIELDS and ph["count"] == 10 and ph["failed"] == 0, ph
        assert relay_rtt < ph["p50_ms"] < 2000, ph
    assert up["transfer_bytes"] > 0 and down["transfer_bytes"] > 0, rep
    assert up["p95_ms"] <= idle["p95_ms"] + rep["packet_time_ms"] + 200
    assert down["p95_ms"] <= idle["p95_ms"] + rep["packet_time_ms"] + 200
    # what it sent landed under ttctl-bench/ at the receiver (the inbox), nowhere else
    assert [x.name for x in (tmp_path / "inbox").iterdir() if not x.name.startswith(".")] in ([], ["ttctl-bench"])
    # a fetch the peer refuses: said in the report, exit 1
    proc = run_ttctl("bench", "latency", "--to", f"udpout:{LOCAL}:{edge}", "--count", "2", "--interval", "0.2",
                     "--fetch", "nosuch.bin", "--json", timeout=60)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    down = json.loads(proc.stdout)["phases"][2]
    assert down["count"] == 0 and "there is no nosuch.bin" in down["note"]


def test_unreachable_peer_one_line_exit_2(tmp_path: Path) -> None:
    t0 = time.monotonic()
    proc = run_ttctl("bench", "latency", "--to", f"udpout:{LOCAL}:{free_port()}", "--timeout", "2", timeout=30)
    assert time.monotonic() - t0 < 10
    assert proc.returncode == 2, proc.stderr
    assert_no_traceback(proc)
    line = one_line(proc.stderr)
    assert line.startswith("ttctl: error: no answer from 1/240") and "within 2 s" in line
    assert proc.stdout == ""


def test_bad_input_exit_2() -> None:
    proc = run_ttctl("bench", "latency", "--fetch", "x.bin", timeout=30)
    assert proc.returncode == 2 and "--fetch applies to live runs" in proc.stderr
    proc = run_ttctl("bench", "latency", "--profile", "nosuch", timeout=30)
    assert proc.returncode == 2 and "unknown link profile" in one_line(proc.stderr)
