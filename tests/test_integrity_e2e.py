"""The promise of send-file on real processes: exit 0 means the receiver holds that name with
that SHA-256, with many senders of equal ids, kills and restarts, relay loss and strangers; and
each refusal is one line with the receiver's reason, before any data moves, leaving nothing
behind. Every process has a timeout and is killed at the end of its test."""

from __future__ import annotations

import json
import os
import random
import signal
import socket
import time
from pathlib import Path

import pytest

from conftest import assert_no_traceback, run_ttctl
from e2e_lib import LOCAL, Start, data_file, free_port, one_line, receiver, send
from ttctl.bench.integrity import run as run_integrity

# -- the invariant, over randomised runs ------------------------------------------------------------


@pytest.mark.parametrize(("topology", "seed"), [("direct", 101), ("relay", 202)])
def test_exit_0_means_the_receiver_holds_that_file(tmp_path: Path, topology: str, seed: int) -> None:
    """Rounds of 1-4 concurrent send-file processes (equal ids, shared names, same and other
    bytes at equal sizes, random bytes or text that goes deflated, --overwrite or not), senders
    and the receiver killed with SIGKILL and started again, strangers sending garbage, through a lossy relay or not (see
    ttctl/bench/integrity.py for every check). `ttctl bench integrity` runs it longer."""
    report = run_integrity(tmp_path, rounds=10, seed=seed, relay=topology == "relay")
    assert report.violations == []
    assert report.rounds == 10 and report.delivered >= 8 and report.checks > 100
    # the compressed rounds ran: a text file went as its zlib stream (how many of the half of the sends
    # that are text get through depends on where the kills land, which the machine's speed moves)
    assert report.deflated >= 1
    assert report.stranger_datagrams > 100


def test_eight_send_file_processes_with_default_ids_at_once(tmp_path: Path, start: Start) -> None:
    port = free_port()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--count", "8", "--json", "--rate", "400000")
    files = [data_file(tmp_path, f"f{i}.bin", 20_000 + 1000 * (i % 2), seed=i) for i in range(8)]
    procs = [start(f"send{i}", "send-file", str(f), "--to", f"udpout:{LOCAL}:{port}", "--json", "--rate", "100000",
                   "--timeout", "20") for i, f in enumerate(files)]
    for p, f in zip(procs, files, strict=True):
        assert p.wait(60) == 0, p.stderr
        r = json.loads(p.stdout)
        assert r["ok"] and r["sha256"] == __import__("hashlib").sha256(f.read_bytes()).hexdigest()
    assert recv.wait(30) == 0
    for f in files:
        assert (tmp_path / "inbox" / f.name).read_bytes() == f.read_bytes()
    # one return address per sending process, each said once
    assert recv.stderr.count("answering") == 8, recv.stderr


def test_strangers_get_no_answer_and_change_nothing(tmp_path: Path, start: Start) -> None:
    port = free_port()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--count", "1", "--rate", "200000")
    src = data_file(tmp_path, "a.bin", 60_000, seed=3)
    strangers = [socket.socket(socket.AF_INET, socket.SOCK_DGRAM) for _ in range(3)]
    for s in strangers:
        s.bind((LOCAL, 0))
        s.setblocking(False)
    sender = start("send", "send-file", str(src), "--to", f"udpout:{LOCAL}:{port}", "--json", "--rate", "100000")
    rng = random.Random(1)
    flood = 0
    try:
        while sender.p.poll() is None and flood < 20_000:
            s = rng.choice(strangers)
            s.sendto(rng.randbytes(rng.randint(1, 100)), (LOCAL, port))
            flood += 1
            if flood % 50 == 0:
                time.sleep(0.002)
        assert sender.wait(30) == 0, sender.stderr
        time.sleep(0.3)
        for s in strangers:
            with pytest.raises(BlockingIOError):
                s.recv(2048)  # not one datagram came back to a stranger
    finally:
        for s in strangers:
            s.close()
    assert flood > 200
    assert recv.wait(30) == 0
    assert (tmp_path / "inbox" / "a.bin").read_bytes() == src.read_bytes()
    assert recv.stderr.count("answering") == 1, recv.stderr  # only the real sender became a peer


# -- refusals: one line, the receiver's reason, before any data ----------------------------------------

def test_refusals_carry_the_receivers_reason(tmp_path: Path, start: Start) -> None:
    port = free_port()
    inbox = tmp_path / "inbox"
    inbox.mkdir()
    (inbox / "sub").write_text("a file where a folder would be")
    (inbox / "dir.bin").mkdir()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--overwrite", "--json")
    a = data_file(tmp_path, "a.bin", 3000)
    to = f"udpout:{LOCAL}:{port}"

    proc, r = send(str(a), "--to", to, "--name", "sub/x.bin", "--overwrite")
    assert proc.returncode == 1 and r["code"] == "REFUSED_NAME" and r["bytes_sent"] == 0
    assert r["message"] == "sub exists here and is a file, not a directory"
    assert one_line(proc.stderr) == "ttctl: error: refused by 1/240: sub exists here and is a file, not a directory"

    proc, r = send(str(a), "--to", to, "--name", "dir.bin", "--overwrite")
    assert proc.returncode == 1 and r["code"] == "REFUSED_EXISTS" and r["bytes_sent"] == 0
    assert one_line(proc.stderr) == "ttctl: error: refused by 1/240: dir.bin exists here and is a directory"

    longest = "n" * 223  # the one limit both ends share
    proc, r = send(str(a), "--to", to, "--name", longest)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    proc, r = send(str(a), "--to", to, "--name", longest + "n")
    assert proc.returncode == 2 and r["ok"] is False and r["code"] == "BAD_INPUT" and r["exit"] == 2  # JSON too
    assert one_line(proc.stderr) == (f"ttctl: error: the name '{longest}n' would be refused: the name is 224 bytes "
                                     "of UTF-8; at most 223 are allowed")
    recv.signal(signal.SIGINT)
    assert recv.wait() == 0
    events = [json.loads(line) for line in recv.stdout.splitlines()]
    assert [(e["event"], e.get("reason")) for e in events if e["event"] == "refused"] == [
        ("refused", "sub exists here and is a file, not a directory"),
        ("refused", "dir.bin exists here and is a directory")]


def test_a_fifo_is_refused_at_once_not_waited_on(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    t0 = time.monotonic()
    proc = run_ttctl("send-file", str(fifo), "--to", f"udpout:{LOCAL}:9", timeout=20)
    assert_no_traceback(proc)
    assert proc.returncode == 2 and time.monotonic() - t0 < 10
    assert one_line(proc.stderr) == f"ttctl: error: {fifo} is a FIFO, not a regular file"


def test_timeout_bounds_time_without_progress(tmp_path: Path, start: Start) -> None:
    """Eight slow transfers fill the receiver; a ninth hears 'busy' every second or so and still
    gives up after --timeout, with the receiver's reason."""
    port = free_port()
    receiver(start, tmp_path, f"udpin:{LOCAL}:{port}")
    hogs = [start(f"hog{i}", "send-file", str(data_file(tmp_path, f"h{i}.bin", 50_000, seed=i)), "--to",
                  f"udpout:{LOCAL}:{port}", "--rate", "2000") for i in range(8)]
    time.sleep(1.5)
    t0 = time.monotonic()
    proc, r = send(str(data_file(tmp_path, "late.bin", 100)), "--to", f"udpout:{LOCAL}:{port}", "--timeout", "3")
    assert proc.returncode == 1 and r["code"] == "TIMEOUT"
    assert 3.0 <= time.monotonic() - t0 < 8.0
    assert one_line(proc.stderr) == ("ttctl: error: timed out: 1/240 stayed busy for 3 s (8 transfers are running "
                                     "here)")
    assert all(h.p.poll() is None for h in hogs)


# -- downloads --------------------------------------------------------------------------------------

def test_fetch_refusals_name_the_real_cause_and_leave_nothing(tmp_path: Path, start: Start) -> None:
    served = tmp_path / "served"
    (served / "link").mkdir(parents=True)
    port = free_port()
    receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--serve", str(served))
    frm = f"udpout:{LOCAL}:{port}"
    got = tmp_path / "got"

    proc, r = send("/etc/passwd", "--from", frm, "--dir", str(got))
    assert proc.returncode == 2
    assert one_line(proc.stderr) == ("ttctl: error: REMOTE_NAME '/etc/passwd' would be refused: absolute paths are "
                                     "not allowed")
    proc, r = send("link", "--from", frm, "--dir", str(got))
    assert proc.returncode == 1 and r["code"] == "REQUEST_REFUSED"
    assert one_line(proc.stderr) == "ttctl: error: refused by 1/240: link is a directory, not a file"
    proc, r = send("nothing.bin", "--from", frm, "--dir", str(got))
    assert proc.returncode == 1 and r["code"] == "NOT_FOUND"
    assert not got.exists()  # no --dir, no .ttctl-partial left behind by a fetch that failed


def test_recv_file_on_a_port_in_use_creates_nothing(tmp_path: Path) -> None:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as busy:
        busy.bind((LOCAL, 0))
        proc = run_ttctl("recv-file", "--listen", f"udpin:{LOCAL}:{busy.getsockname()[1]}", "--dir",
                         str(tmp_path / "new" / "inbox"), timeout=20)
    assert proc.returncode == 2 and "address already in use" in one_line(proc.stderr)
    assert not (tmp_path / "new").exists()


def test_two_receivers_never_share_a_directory(tmp_path: Path, start: Start) -> None:
    receiver(start, tmp_path, f"udpin:{LOCAL}:{free_port()}")
    proc = run_ttctl("recv-file", "--listen", f"udpin:{LOCAL}:{free_port()}", "--dir", str(tmp_path / "inbox"),
                     timeout=20)
    assert proc.returncode == 2
    assert one_line(proc.stderr) == f"ttctl: error: --dir: {tmp_path / 'inbox'} is in use by another ttctl receiver"


def test_relay_refuses_to_relay_to_itself(tmp_path: Path) -> None:
    for to in (f"udp:{LOCAL}:14777", "udp:localhost:14777"):
        proc = run_ttctl("link", "relay", "--listen", f"udp:{LOCAL}:14777", "--to", to, timeout=20)
        assert proc.returncode == 2, proc.stderr
        assert "it would relay to itself" in one_line(proc.stderr)


def test_integrity_soak_command(tmp_path: Path) -> None:
    proc = run_ttctl("bench", "integrity", "--rounds", "2", "--seed", "5", "--json", cwd=tmp_path, timeout=300)
    assert_no_traceback(proc)
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    assert set(report) == {"direct", "relay"}
    assert all(r["rounds"] == 2 and r["violations"] == [] and r["sends"] >= 2 for r in report.values())
    assert not list(tmp_path.iterdir())  # its scratch directory is gone


def test_soak_picks_other_ports_when_its_free_port_was_taken(tmp_path: Path) -> None:
    """A port picked free can be taken by another process before the receiver binds it: the
    receiver exits at once ('address in use') and the harness picks again, not a crash."""
    from ttctl.bench.integrity import Harness

    h = Harness(tmp_path / "work", 1, relay=True, strangers=False)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as taken:
        taken.bind(("127.0.0.1", 0))
        h.port = taken.getsockname()[1]
        try:
            h._start_ends()
            assert h.port != taken.getsockname()[1]
            assert h.receiver is not None and h.receiver.poll() is None
            assert h.relay is not None and h.relay.poll() is None
        finally:
            for p in (h.receiver, h.relay):
                if p is not None and p.poll() is None:
                    p.kill()
                    p.wait(5)
