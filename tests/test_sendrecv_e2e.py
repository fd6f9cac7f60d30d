"""send-file, recv-file and link relay as real processes on 127.0.0.1: every process has a
timeout and is killed at the end of its test."""

from __future__ import annotations

import contextlib
import json
import re
import signal
import socket
import subprocess
import time
from pathlib import Path

import pytest

from conftest import assert_no_traceback, run_ttctl
from e2e_lib import LOCAL, SIZE, Start, data_file, free_port, one_line, receiver, relay, send
from machine import scaled

# -- delivery ----------------------------------------------------------------------------------

def test_direct_udp(tmp_path: Path, start: Start) -> None:
    src = data_file(tmp_path, "a.bin")
    port = free_port()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--count", "1")
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.sendto(b"\xfd" * 101, (LOCAL, port))  # one byte over DJI's limit: dropped, counted
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{port}")
    assert proc.returncode == 0, proc.stderr
    assert r["ok"] and r["code"] == "COMPLETE" and r["bytes"] == SIZE and r["name"] == "a.bin"
    assert r["capacity_Bps"] is None and r["efficiency"] is None  # unpaced: capacity unknown
    assert recv.wait() == 0
    assert (tmp_path / "inbox" / "a.bin").read_bytes() == src.read_bytes()
    assert "accepted a.bin (65536 bytes) from 255/190" in recv.stdout
    assert re.search(r"complete a\.bin: 65536 bytes in [\d.]+ s from 255/190 -> ", recv.stdout), recv.stdout
    assert "dropped 1 datagram(s) longer than 100 bytes" in recv.stderr


def test_through_relay_with_loss(tmp_path: Path, start: Start) -> None:
    src = data_file(tmp_path, "a.bin", seed=2)
    a, b = free_port(), free_port()
    air = relay(start, a, b, "--profile", "lan", "--loss", "0.1", "--seed", "3", "--stats-interval", "0.5")
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--count", "1", "--profile", "lan", "--json")
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{a}", "--profile", "lan")
    assert proc.returncode == 0, proc.stderr
    assert r["ok"] and r["capacity_Bps"] == 1_000_000 and 0 < r["efficiency"] <= 1
    assert r["retransmitted_bytes"] > 0  # 10% loss: something had to be sent again
    assert recv.wait() == 0
    assert (tmp_path / "inbox" / "a.bin").read_bytes() == src.read_bytes()
    events = [json.loads(line) for line in recv.stdout.splitlines()]
    assert [e["event"] for e in events] == ["accepted", "complete"]
    air.signal(signal.SIGINT)
    assert air.wait() == 0
    last = air.stderr.strip().splitlines()[-1]
    m = re.search(r"up (\d+) in, (\d+) out, (\d+) lost", last)
    assert m and int(m.group(3)) > 0 and int(m.group(1)) > int(m.group(2)), last


def test_through_relay_with_an_outage(tmp_path: Path, start: Start) -> None:
    """Nothing crosses the relay for its first 4 s: the sender keeps offering and delivers once
    the link is back."""
    src = data_file(tmp_path, "a.bin", 20_000, seed=5)
    a, b = free_port(), free_port()
    t0 = time.monotonic()
    air = relay(start, a, b, "--profile", "lan", "--loss", "0", "--outage", "0:4", "--stats-interval", "0")
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--count", "1", "--profile", "lan")
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{a}", "--profile", "lan", "--timeout", "20")
    assert proc.returncode == 0, proc.stderr
    assert r["ok"] and time.monotonic() - t0 >= 4.0  # done only once the link was back
    assert recv.wait() == 0
    assert (tmp_path / "inbox" / "a.bin").read_bytes() == src.read_bytes()
    air.signal(signal.SIGINT)
    assert air.wait() == 0
    m = re.search(r"up (\d+) in, (\d+) out, (\d+) lost", air.stderr.strip().splitlines()[-1])
    assert m and int(m.group(3)) > 0, air.stderr  # --loss 0: only the outage lost them


def test_m100_at_10m(tmp_path: Path, start: Start) -> None:
    """The realistic link: a 4 KiB file up the M100's 500 B/s uplink, through the relay."""
    src = data_file(tmp_path, "small.bin", 4096, seed=4)
    a, b = free_port(), free_port()
    relay(start, a, b, "--profile", "m100", "--distance", "10", "--seed", "1")
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--count", "1", "--profile", "m100")
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{a}", "--profile", "m100", "--distance", "10")
    assert proc.returncode == 0, proc.stderr
    assert r["capacity_Bps"] == pytest.approx(500, rel=0.05)
    assert r["efficiency"] > 0.5, r  # handshake and tail included, on a 4 KiB file
    assert recv.wait() == 0
    assert (tmp_path / "inbox" / "small.bin").read_bytes() == src.read_bytes()


def test_tcp(tmp_path: Path, start: Start) -> None:
    src = data_file(tmp_path, "t.bin", seed=5)
    port = free_port(socket.SOCK_STREAM)
    recv = receiver(start, tmp_path, f"tcpin:{LOCAL}:{port}", "--count", "1")
    proc, r = send(str(src), "--to", f"tcp:{LOCAL}:{port}", "--rate", "400000")
    assert proc.returncode == 0, proc.stderr
    assert r["ok"] and r["endpoint"] == f"tcp:{LOCAL}:{port}"
    assert recv.wait() == 0
    assert (tmp_path / "inbox" / "t.bin").read_bytes() == src.read_bytes()


def test_receiver_reaching_out_to_a_listening_sender(tmp_path: Path, start: Start) -> None:
    """recv-file with udpout says hello (a HEARTBEAT) until it hears the sender listening on udpin."""
    src = data_file(tmp_path, "r.bin", 10_000, seed=10)
    port = free_port()
    sender = start("send", "send-file", str(src), "--to", f"udpin:{LOCAL}:{port}", "--json", "--timeout", "20")
    time.sleep(0.5)  # the sender binds its port
    recv = receiver(start, tmp_path, f"udpout:{LOCAL}:{port}", "--count", "1")
    assert sender.wait(30) == 0, sender.stderr
    assert json.loads(sender.stdout)["ok"]
    assert recv.wait() == 0
    assert (tmp_path / "inbox" / "r.bin").read_bytes() == src.read_bytes()


# -- refusals ----------------------------------------------------------------------------------

def test_refusals(tmp_path: Path, start: Start) -> None:
    a = data_file(tmp_path, "a.bin", 3000, seed=6)
    other = data_file(tmp_path, "other.bin", 2000, seed=7)
    port = free_port()
    to = f"udpout:{LOCAL}:{port}"
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}")

    # a name no receiver would take: refused here, before anything is sent, in the receiver's words
    proc, r = send(str(a), "--to", to, "--name", "../evil.bin")
    assert proc.returncode == 2 and r["ok"] is False and r["code"] == "BAD_INPUT" and r["exit"] == 2  # JSON too
    assert one_line(proc.stderr) == ("ttctl: error: the name '../evil.bin' would be refused: the name has an empty, "
                                     "'.' or '..' component")

    proc, r = send(str(a), "--to", to)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    proc, r = send(str(a), "--to", to)  # the very same file again: verified there, nothing sent
    assert proc.returncode == 0 and r["ok"] and r["nothing_sent"] and r["bytes_sent"] == 0, r
    proc, r = send(str(other), "--to", to, "--name", "a.bin")
    assert proc.returncode == 1 and r["code"] == "REFUSED_EXISTS"
    assert r["message"] == "a.bin exists and overwriting is not allowed here"  # the receiver's own reason
    assert one_line(proc.stderr) == ("ttctl: error: refused by 1/240: a.bin exists and overwriting is not allowed "
                                     "here (to replace it: --overwrite here, and a receiver started with --overwrite)")
    assert r["bytes_sent"] == 0  # refused at the offer
    proc, r = send(str(other), "--to", to, "--name", "a.bin", "--overwrite")  # the receiver does not allow it
    assert proc.returncode == 1 and r["code"] == "REFUSED_EXISTS"
    assert (tmp_path / "inbox" / "a.bin").read_bytes() == a.read_bytes()
    assert "a.bin exists and overwriting is not allowed here" in recv.stdout
    assert not list((tmp_path / "inbox").glob("*evil*")) and not (tmp_path / "evil.bin").exists()
    assert "evil" not in recv.stdout

    recv.signal(signal.SIGTERM)
    assert recv.wait() == 0
    assert_no_traceback(subprocess.CompletedProcess([], 0, recv.stdout, recv.stderr))


# -- resume ------------------------------------------------------------------------------------

def _saved_bytes(inbox: Path) -> int:
    total = 0
    for state in (inbox / ".ttctl-partial").glob("*.json"):
        with contextlib.suppress(OSError, ValueError, KeyError):  # being replaced: try again
            total = max(total, sum(b - a for a, b in json.loads(state.read_text())["ranges"]))
    return total


def test_resume_after_the_receiver_is_killed(tmp_path: Path, start: Start) -> None:
    src = data_file(tmp_path, "big.bin", seed=8)
    a, b = free_port(), free_port()
    relay(start, a, b, "--profile", "lan", "--rate", "20000", "--stats-interval", "0")
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", name="recv1")
    first = start("send1", "send-file", str(src), "--to", f"udpout:{LOCAL}:{a}", "--rate", "20000", "--json")
    inbox = tmp_path / "inbox"
    end = time.monotonic() + scaled(20)
    while _saved_bytes(inbox) < 16 * 1024:
        assert time.monotonic() < end and first.p.poll() is None, (first.stdout, first.stderr, recv.stdout)
        time.sleep(0.02)
    recv.kill()  # SIGKILL: no chance to save anything more
    first.kill()
    saved = _saved_bytes(inbox)
    assert saved < SIZE and not (inbox / "big.bin").exists()

    recv2 = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--count", "1", name="recv2")
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{a}", "--rate", "20000")
    assert proc.returncode == 0, proc.stderr
    assert r["ok"] and r["resumed_bytes"] >= saved - 8 * 1024  # a few frames stream before the first status
    assert r["bytes_sent"] < SIZE - saved + 8 * 1024, r  # the rest, give or take a few frames
    assert r["bytes_sent"] < 0.8 * SIZE, r
    assert recv2.wait() == 0
    assert (inbox / "big.bin").read_bytes() == src.read_bytes()
    assert f"accepted big.bin (65536 bytes) from 255/190, resuming with {saved} bytes already here" in recv2.stdout


# -- download ----------------------------------------------------------------------------------

def test_download_with_from_and_serve(tmp_path: Path, start: Start) -> None:
    served = tmp_path / "served"
    served.mkdir()
    src = data_file(served, "c.bin", 20_000, seed=9)
    port = free_port()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--serve", str(served), "--rate", "200000")
    dl = tmp_path / "dl"
    proc, r = send("c.bin", "--from", f"udpout:{LOCAL}:{port}", "--dir", str(dl), "--rate", "200000")
    assert proc.returncode == 0, proc.stderr
    assert r["ok"] and r["bytes"] == 20_000 and r["direction"] == "fetch"
    assert (dl / "c.bin").read_bytes() == src.read_bytes()

    proc, r = send("nope.bin", "--from", f"udpout:{LOCAL}:{port}", "--dir", str(dl))
    assert proc.returncode == 1 and r["code"] == "NOT_FOUND"
    assert one_line(proc.stderr) == "ttctl: error: not found at 1/240: there is no nope.bin in the served folder"

    recv.wait_for("served c.bin", where="stdout")
    assert "serving c.bin (20000 bytes) to 255/190" in recv.stdout
    recv.signal(signal.SIGINT)
    assert recv.wait() == 0


# -- failures ----------------------------------------------------------------------------------

def test_no_receiver_times_out(tmp_path: Path) -> None:
    src = data_file(tmp_path, "a.bin", 1000)
    port = free_port()
    t0 = time.monotonic()
    proc = run_ttctl("send-file", str(src), "--to", f"udpout:{LOCAL}:{port}", "--timeout", "1.5", timeout=30)
    assert proc.returncode == 1
    assert time.monotonic() - t0 < 10
    assert one_line(proc.stderr) == (f"ttctl: error: timed out: no answer from 1/240 at udpout:{LOCAL}:{port} "
                                     "within 1.5 s (is a receiver running there?)")
    assert proc.stdout == ""


def test_timeout_says_what_was_heard(tmp_path: Path, start: Start) -> None:
    """An onboard end without --inbox takes no files but talks (heartbeats, telemetry): the
    timeout says it was heard, not that nobody is there."""
    src = data_file(tmp_path, "a.bin", 1000)
    port = free_port()
    p = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{port}")
    p.wait_for("onboard")
    proc = run_ttctl("send-file", str(src), "--to", f"udpout:{LOCAL}:{port}", "--timeout", "3", timeout=30)
    assert proc.returncode == 1, proc.stderr
    line = one_line(proc.stderr)
    assert re.fullmatch(rf"ttctl: error: timed out: 1/240 at udpout:{LOCAL}:{port} did not answer this transfer's "
                        r"\d+ offers within 3 s, though \d+ other frames came from it \(the last \d+\.\d s ago\): "
                        r"it takes no files there \(an onboard end without --inbox\?\), or the link lost every one",
                        line), line


def test_sender_interrupted(tmp_path: Path, start: Start) -> None:
    src = data_file(tmp_path, "a.bin", 1000)
    p = start("send", "send-file", str(src), "--to", f"udpout:{LOCAL}:{free_port()}", "--timeout", "30")
    time.sleep(1.0)
    p.signal(signal.SIGINT)
    assert p.wait() == 130
    assert p.stderr == "ttctl: interrupted\n"


def test_bad_input_is_one_line(tmp_path: Path) -> None:
    src = data_file(tmp_path, "a.bin", 100)
    a_file = tmp_path / "plain.txt"
    a_file.write_text("x")
    busy = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    busy.bind((LOCAL, 0))
    busy_port = busy.getsockname()[1]
    to = f"udpout:{LOCAL}:9"
    cases = [
        (["send-file", str(tmp_path / "missing.bin"), "--to", to], "missing.bin: No such file or directory"),
        (["send-file", str(tmp_path), "--to", to], "is a directory, not a regular file"),
        (["send-file", str(src), "--to", "bogus"], "bad endpoint 'bogus'"),
        (["send-file", str(src), "--to", "udpout:127.0.0.1:99999"], "port must be in 1..65535"),
        (["send-file", str(src)], "give --to ENDPOINT"),
        (["send-file", str(src), "--to", to, "--from", to], "not both or neither"),
        (["send-file", str(src), "--to", to, "--profile", "nope"], "unknown link profile 'nope'"),
        (["send-file", str(src), "--to", to, "--rate", "0"], "--rate must be a positive"),
        (["send-file", str(src), "--to", "udpout:no-such-host.invalid:9"], "cannot resolve"),
        (["recv-file", "--listen", f"udpin:{LOCAL}:0", "--dir", str(a_file)], "is not a directory"),
        (["recv-file", "--listen", f"udpin:{LOCAL}:0", "--dir", str(a_file / "sub")], "--dir: cannot create"),
        (["recv-file", "--listen", f"udpin:{LOCAL}:{busy_port}", "--dir", str(tmp_path / "in")],
         "address already in use"),
        (["recv-file", "--listen", f"tcp:{LOCAL}:{free_port(socket.SOCK_STREAM)}", "--dir", str(tmp_path / "in")],
         "connection refused"),
        (["recv-file", "--listen", f"udpin:{LOCAL}:0", "--dir", str(tmp_path / "in"), "--serve", str(a_file)],
         "--serve"),
        (["link", "relay", "--listen", f"tcpin:{LOCAL}:1", "--to", f"udp:{LOCAL}:2"], "UDP only"),
        (["link", "relay", "--listen", f"udp:{LOCAL}:{busy_port}", "--to", f"udp:{LOCAL}:2"],
         "address already in use"),
        (["link", "relay", "--listen", f"udp:{LOCAL}:0", "--to", f"udp:{LOCAL}:2", "--loss", "1.5"],
         "loss must be in 0..1"),
        (["link", "relay", "--listen", f"udp:{LOCAL}:0", "--to", f"udp:{LOCAL}:2", "--loss-model", "x"],
         "loss model must be one of"),
        (["link", "relay", "--listen", f"udp:{LOCAL}:0", "--to", f"udp:{LOCAL}:2", "--outage", "10"],
         "--outage wants START:SECONDS"),
        (["link", "relay", "--listen", f"udp:{LOCAL}:0", "--to", f"udp:{LOCAL}:2", "--outage", "10:-1"],
         "an outage needs a start >= 0 and a positive duration"),
    ]
    try:
        for args, want in cases:
            proc = run_ttctl(*args, timeout=30)
            assert_no_traceback(proc)
            assert proc.returncode == 2, (args, proc.stderr)
            line = one_line(proc.stderr)
            assert line.startswith("ttctl: error: ") and want in line, (args, line)
    finally:
        busy.close()
    assert not (tmp_path / "in").exists()  # no refusal left a directory behind


def test_content_that_comes_back_after_another_replaced_it_is_complete_not_again(tmp_path: Path,
                                                                                  start: Start) -> None:
    """A, then B over it, then A over B: the third is a completion (the directory changed), not a
    'complete-again' of the first; --count counts distinct contents."""
    a, b = data_file(tmp_path, "a.bin", 3000, seed=1), data_file(tmp_path, "b.bin", 3000, seed=2)
    port = free_port()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--overwrite", "--json", "--rate", "200000")
    for src in (a, b, a):
        proc, r = send(str(src), "--name", "x.bin", "--overwrite", "--to", f"udpout:{LOCAL}:{port}", "--rate",
                       "200000")
        assert proc.returncode == 0 and r["ok"], proc.stderr
    assert (tmp_path / "inbox" / "x.bin").read_bytes() == a.read_bytes()
    recv.signal(signal.SIGINT)
    assert recv.wait() == 0
    events = [json.loads(line)["event"] for line in recv.stdout.splitlines()]
    assert events.count("complete") == 3 and "complete-again" not in events, events


def test_psdk_128_byte_packets_both_ways(tmp_path: Path, start: Start) -> None:
    """DJI's Payload SDK channel (`--profile psdk`: 128-byte packets): an upload and a fetch through
    the relay at 10 % loss, each whole, in 128-byte packets (TT_FILE_DATA_FIT, 107 file bytes a
    packet): fewer packets up than 80-byte frames would need for the file alone."""
    src = data_file(tmp_path, "up.bin", 20_000, seed=7)
    served = tmp_path / "served"
    served.mkdir()
    down = data_file(served, "down.bin", 12_000, seed=8)
    a, b = free_port(), free_port()
    air = relay(start, a, b, "--profile", "psdk", "--loss", "0.1", "--seed", "4", "--stats-interval", "0")
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--profile", "psdk", "--serve", str(served))
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{a}", "--profile", "psdk", "--no-compress")
    assert proc.returncode == 0, proc.stderr
    assert r["ok"] and r["capacity_Bps"] == pytest.approx(3000)
    assert (tmp_path / "inbox" / "up.bin").read_bytes() == src.read_bytes()
    air.signal(signal.SIGINT)
    assert air.wait() == 0
    m = re.search(r"up (\d+) in, (\d+) out, (\d+) lost", air.stderr.strip().splitlines()[-1])
    assert m and int(m.group(1)) < 20_000 / 80, air.stderr  # 128-byte packets carried it
    a2 = free_port()
    relay(start, a2, b, "--profile", "psdk", "--loss", "0.1", "--seed", "5", "--stats-interval", "0")
    got = tmp_path / "got"
    proc, r = send("down.bin", "--from", f"udpout:{LOCAL}:{a2}", "--dir", str(got), "--profile", "psdk",
                   "--no-compress")
    assert proc.returncode == 0, proc.stderr
    assert (got / "down.bin").read_bytes() == down.read_bytes()
    recv.signal(signal.SIGINT)
    assert recv.wait() == 0
    assert "longer than" not in recv.stderr + proc.stderr  # no end refused a packet as oversize
