"""Deflated transfers between real processes on 127.0.0.1: send-file, recv-file and link relay
at the M100's rates with loss, a killed sender resumed, a fetch, the summary's words."""

from __future__ import annotations

import re
import signal
import time
from pathlib import Path

import pytest

from conftest import assert_no_traceback, run_ttctl
from e2e_lib import LOCAL, Start, free_port, receiver, relay, send
from machine import scaled
from test_sendrecv_e2e import _saved_bytes
from ttctl.bench.textfiles import flight_log_csv, mission_yaml


@pytest.mark.parametrize("model", ["random", "burst"])
def test_text_through_the_m100_relay_at_10_percent_loss(tmp_path: Path, start: Start, model: str) -> None:
    log = tmp_path / "log.csv"
    log.write_bytes(flight_log_csv(seconds=15))  # 8 KB: 100 packets raw, a third of that deflated
    size = log.stat().st_size
    a, b = free_port(), free_port()
    air = relay(start, a, b, "--profile", "m100", "--loss", "0.1", "--loss-model", model, "--seed", "5",
                "--stats-interval", "0")
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--count", "1", "--profile", "m100")
    proc, r = send(str(log), "--to", f"udpout:{LOCAL}:{a}", "--profile", "m100", timeout=90)
    assert proc.returncode == 0, proc.stderr
    assert r["ok"] and r["bytes"] == size and r["deflated_bytes"] < size / 3, r
    assert r["efficiency"] > 1.5, r  # file bytes per second above what the link carries
    assert recv.wait() == 0
    assert (tmp_path / "inbox" / "log.csv").read_bytes() == log.read_bytes()
    assert f"accepted log.csv ({size} bytes) from 255/190, deflated to {r['deflated_bytes']} B on the link" \
        in recv.stdout
    air.signal(signal.SIGINT)
    assert air.wait() == 0
    m = re.search(r"up (\d+) in, (\d+) out, (\d+) lost", air.stderr.strip().splitlines()[-1])
    assert m and int(m.group(3)) > 0, air.stderr  # the loss was real
    assert int(m.group(1)) < size / 80, m.group(0)  # fewer packets than the raw file needs without any loss


def test_summary_says_the_compression_and_no_compress_turns_it_off(tmp_path: Path, start: Start) -> None:
    yaml = tmp_path / "mission.yaml"
    yaml.write_bytes(mission_yaml())
    port = free_port()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--count", "2", "--rate", "50000")
    proc = run_ttctl("send-file", str(yaml), "--to", f"udpout:{LOCAL}:{port}", "--rate", "50000", timeout=60)
    assert_no_traceback(proc)
    assert proc.returncode == 0, proc.stderr
    m = re.search(r"deflate (\d+\.\d)x: ([\d,]+) B on the link for ([\d,]+) B", proc.stdout)
    assert m and int(m.group(3).replace(",", "")) == len(mission_yaml()), proc.stdout
    proc2, r = send(str(yaml), "--name", "raw.yaml", "--to", f"udpout:{LOCAL}:{port}", "--rate", "50000",
                    "--no-compress")
    assert proc2.returncode == 0 and r["deflated_bytes"] is None and r["bytes_sent"] >= len(mission_yaml())
    assert recv.wait() == 0
    assert (tmp_path / "inbox" / "raw.yaml").read_bytes() == (tmp_path / "inbox" / "mission.yaml").read_bytes() \
        == mission_yaml()


def test_a_killed_deflating_sender_resumes(tmp_path: Path, start: Start) -> None:
    log = tmp_path / "log.csv"
    log.write_bytes(flight_log_csv(seconds=600))
    a, b = free_port(), free_port()
    relay(start, a, b, "--profile", "lan", "--rate", "20000", "--stats-interval", "0")
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--count", "1")
    first = start("send1", "send-file", str(log), "--to", f"udpout:{LOCAL}:{a}", "--rate", "20000", "--json")
    inbox = tmp_path / "inbox"
    end = time.monotonic() + scaled(30)
    while _saved_bytes(inbox) < 16 * 1024:
        assert time.monotonic() < end and first.p.poll() is None, (first.stdout, first.stderr, recv.stdout)
        time.sleep(0.02)
    first.kill()
    saved = _saved_bytes(inbox)
    proc, r = send(str(log), "--to", f"udpout:{LOCAL}:{a}", "--rate", "20000")
    assert proc.returncode == 0, proc.stderr
    assert r["ok"] and r["deflated_bytes"] and r["bytes_sent"] < r["deflated_bytes"] - saved + 8 * 1024, r
    assert r["resumed_bytes"] > 0
    assert recv.wait() == 0
    assert (inbox / "log.csv").read_bytes() == log.read_bytes()
    assert not list((inbox / ".ttctl-partial").glob("*"))


def test_a_fetch_comes_deflated(tmp_path: Path, start: Start) -> None:
    served = tmp_path / "served"
    served.mkdir()
    (served / "log.csv").write_bytes(flight_log_csv(seconds=120))
    port = free_port()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--serve", str(served), "--rate", "200000")
    dl = tmp_path / "dl"
    proc, r = send("log.csv", "--from", f"udpout:{LOCAL}:{port}", "--dir", str(dl), "--rate", "200000")
    assert proc.returncode == 0, proc.stderr
    assert r["ok"] and r["bytes"] == len(flight_log_csv(seconds=120)) and r["deflated_bytes"] < r["bytes"] / 3
    assert (dl / "log.csv").read_bytes() == (served / "log.csv").read_bytes()
    recv.signal(signal.SIGINT)
    assert recv.wait() == 0


def test_a_fetch_resumes_what_arrived_as_it_is(tmp_path: Path, start: Start) -> None:
    """Part of the file is here as it was sent before (raw: by a server that did not deflate);
    the server now offers it deflated, the requester says it holds the file as it is, the server
    sends it as it is and only the rest moves."""
    import hashlib

    from ttctl.proto.storage import ReceiveDir

    served = tmp_path / "served"
    served.mkdir()
    log = flight_log_csv(seconds=120)
    (served / "log.csv").write_bytes(log)
    dl = tmp_path / "dl"
    part = ReceiveDir(dl).partial("log.csv", len(log), hashlib.sha256(log).digest())
    part.write(0, log[:30_000])
    part.save()
    part.close()
    port = free_port()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--serve", str(served), "--rate", "200000")
    proc, r = send("log.csv", "--from", f"udpout:{LOCAL}:{port}", "--dir", str(dl), "--rate", "200000")
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert r["deflated_bytes"] is None and (dl / "log.csv").read_bytes() == log
    assert r["frames_received"] * 80 < len(log) - 20_000, r  # only the rest moved
    recv.signal(signal.SIGINT)
    assert recv.wait() == 0
