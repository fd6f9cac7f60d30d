"""Deflate (TT_FILE_FLAGS_DEFLATE) in the generated Java transfer runtime, against real ttctl
processes on 127.0.0.1: the Java inbox (tests/java/session/SessionDriver.java) takes a text file
`ttctl send-file` deflates, through `ttctl link relay --profile m100 --loss 0.1`, inflates it and
checks its SHA-256 before it takes its name; a forged stream (a small Python process driving the
sans-IO sender with a metadata blob of its choosing) that inflates to more than it declares, to
less, or not at all, is refused in the Python receiver's words and leaves nothing under the
name."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
import zlib
from pathlib import Path

import pytest

from conformance_lib import build_java
from conftest import ROOT
from e2e_lib import LOCAL, Start, free_port, receiver, relay
from test_java_session import DRIVERS, _ttctl, drone_send, sha, stop, tablet_inbox
from test_java_transfer import DRIVERS as TABLET_DRIVERS
from test_java_transfer import Driver
from ttctl.bench.textfiles import flight_log_csv, mission_yaml

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """SessionDriver (the inbox) and TabletDriver (uploads, fetches), from a freshly generated tree."""
    cls, _ = build_java(tmp_path_factory.mktemp("java_deflate"), [*DRIVERS, *sorted(TABLET_DRIVERS.glob("*.java"))])
    return cls

FORGE = r'''
import hashlib, json, socket, sys, time
from pathlib import Path
import ttapi
from ttctl.wire.bindings import Bindings
from ttctl.proto.deflate import deflate_meta
from ttctl.proto.endpoint import Endpoint
from ttctl.proto.storage import BytesSource
from ttctl.proto.transfer import TransferConfig, meta_check

port, stream_path, original_path, declared = int(sys.argv[1]), sys.argv[2], sys.argv[3], int(sys.argv[4])
name = sys.argv[5].encode()
stream = Path(stream_path).read_bytes()
original = Path(original_path).read_bytes()
cfg = TransferConfig()
cfg.give_up_after = 20.0
ep = Endpoint(Bindings(ttapi), 1, 240, rate_Bps=20000, config=cfg)
src = BytesSource(stream, "x.txt")
src.sha256 = hashlib.sha256(original).digest()
s = ep.send_file("x.txt", (255, 190), source=src, compress=False)
s._flags |= 4  # TT_FILE_FLAGS_DEFLATE, with the metadata a deflated offer carries
s.flags = s._flags
s.meta = deflate_meta(src.sha256, declared, name)
s.check = meta_check(s.meta)
s.deflated = None  # no fallback: a hostile sender does not give up
sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
sock.bind(("127.0.0.1", 0))
sock.settimeout(0.005)
t0 = time.monotonic()
while not s.done and time.monotonic() - t0 < 40:
    now = time.monotonic() - t0
    while (p := ep.poll(now)) is not None:
        sock.sendto(p, ("127.0.0.1", port))
    try:
        data, _ = sock.recvfrom(65536)
        ep.receive(time.monotonic() - t0, data, "java")
    except socket.timeout:
        pass
r = s.result
print(json.dumps({"done": s.done, "code": r.code if r else None, "message": r.message if r else None,
                  "sent": s.stats.bytes_sent}), flush=True)
'''


def forge(tmp: Path, port: int, stream: bytes, original: bytes, declared: int, name: str = "x.txt") -> dict:
    (tmp / "stream.z").write_bytes(stream)
    (tmp / "original.bin").write_bytes(original)
    proc = subprocess.run([sys.executable, "-c", FORGE, str(port), str(tmp / "stream.z"), str(tmp / "original.bin"),
                           str(declared), name], capture_output=True, text=True, timeout=90,
                          env={**os.environ, "PYTHONPATH": str(ROOT / "generated" / "python")})
    assert proc.returncode == 0, proc.stderr[-3000:]
    out: dict = json.loads(proc.stdout.strip().splitlines()[-1])
    return out


def finals(inbox: Path) -> list[str]:
    return sorted(p.name for p in inbox.iterdir() if p.is_file()) if inbox.exists() else []


def test_a_deflated_upload_through_the_lossy_relay_lands_inflated_and_verified(classes: Path, tmp_path: Path,
                                                                              start: Start) -> None:
    """send-file deflates a CSV flight log (the default) to the Java inbox through the m100
    relay at 10 % loss: the inbox takes the stream, inflates it, checks the SHA-256 and renames
    the file into place: byte for byte the log, nothing left in .ttctl-partial."""
    (tmp_path / "outbox").mkdir()
    a, b = free_port(), free_port()
    relay(start, a, b, "--profile", "m100", "--rate", "8000", "--loss", "0.1", "--seed", "21", "--stats-interval", "0")
    log = tmp_path / "log.csv"
    log.write_bytes(flight_log_csv(seconds=30))
    size = len(log.read_bytes())
    j = tablet_inbox(classes, tmp_path, "tablet", b)
    proc, r = drone_send(str(log), "--to", f"udpout:{LOCAL}:{a}", "--rate", "8000", "--timeout", "30")
    assert proc.returncode == 0 and r["ok"], proc.stdout + proc.stderr
    assert r["deflated_bytes"] and r["deflated_bytes"] < size / 3 and r["deflate_fallback"] is None, r
    res = stop(j, tmp_path)
    assert sha(tmp_path / "inbox" / "log.csv") == sha(log)
    (done,) = [x for x in res["results"] if x["name"] == "log.csv"]
    assert done["ok"] and done["size"] == size and done["deflated"] == r["deflated_bytes"], done
    assert f"deflated to {r['deflated_bytes']} B on the link" in done["message"], done
    assert finals(tmp_path / "inbox") == ["log.csv"]
    assert not list((tmp_path / "inbox" / ".ttctl-partial").glob("*"))


def test_forged_streams_are_refused_in_words_and_leave_nothing(classes: Path, tmp_path: Path, start: Start) -> None:
    """Straight to the Java inbox's socket: a bomb (1 MiB of zeros declared as 4096 bytes) is
    stopped at the declared size; a stream of less than declared, and a corrupt one, are refused
    with the inflater's words; each is FAILED_CHECKSUM as the Python receiver says it, nothing
    under the name, no partial kept (no resume can use it). A deflate offer whose metadata ends
    at the size (no name) is REFUSED_NAME at the offer, before any data."""
    (tmp_path / "outbox").mkdir()
    port = free_port()
    j = tablet_inbox(classes, tmp_path, "tablet", port)
    big = b"\0" * (1 << 20)
    r = forge(tmp_path, port, zlib.compress(big, 9), big[:4096], 4096)
    assert r["code"] == "FAILED_CHECKSUM" and "the stream inflates to more than the 4096 bytes offered" in \
        r["message"], r
    text = mission_yaml()
    r = forge(tmp_path, port, zlib.compress(text[:-100], 6), text, len(text))
    assert r["code"] == "FAILED_CHECKSUM" and \
        f"the stream inflates to {len(text) - 100} bytes, not the {len(text)} offered" in r["message"], r
    corrupt = bytearray(zlib.compress(text, 6))
    corrupt[2] ^= 0xFF  # the first block's header: the inflater says what is wrong
    try:
        zlib.decompress(bytes(corrupt))
        raise AssertionError("the corruption went unnoticed")
    except zlib.error as e:
        words = str(e).split(": ", 1)[-1]  # zlib's own words, as Python's receiver quotes them
    r = forge(tmp_path, port, bytes(corrupt), text, len(text))
    assert r["code"] == "FAILED_CHECKSUM" and f"the stream does not inflate ({words})" in r["message"], r
    r = forge(tmp_path, port, zlib.compress(text, 6), text, len(text), name="")  # the size, then no name
    assert r["code"] == "REFUSED_NAME" and "the deflate offer carries no name" in r["message"] and r["sent"] == 0, r
    res = stop(j, tmp_path)
    assert finals(tmp_path / "inbox") == []
    assert not list((tmp_path / "inbox" / ".ttctl-partial").glob("*.part"))
    assert not list((tmp_path / "inbox" / ".ttctl-partial").glob("*.out"))
    assert not any(x["ok"] for x in res["results"]), res["results"]
    assert {x["code"] for x in res["results"]} == {"FAILED_CHECKSUM", "REFUSED_NAME"}, res["results"]



def test_a_java_fetch_of_text_from_recv_file_serve_comes_deflated(classes: Path, tmp_path: Path,
                                                                  start: Start) -> None:
    """The server (recv-file --serve) offers a CSV log deflated; the Java requester takes the
    stream, inflates it and checks it: the file as served, fewer bytes on the link."""
    (tmp_path / "serve").mkdir()
    (tmp_path / "serve" / "log.csv").write_bytes(flight_log_csv(seconds=60))
    size = (tmp_path / "serve" / "log.csv").stat().st_size
    port = free_port()
    rx = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--rate", "50000", "--serve", str(tmp_path / "serve"))
    r = Driver(classes, tmp_path, "java", link="udp", port=port, rate=50000, timeout=30, fetch="log.csv",
               dir="got").finish(120)
    assert r["fetch_ok"], r["_text"][-3000:]
    assert sha(tmp_path / "got" / "log.csv") == sha(tmp_path / "serve" / "log.csv") == r["fetch_sha256"]
    assert r["fetch_bytes"] == size and 0 < r["fetch_deflated"] < size / 3, r
    rx.wait_for("served log.csv", where="stdout")
    assert not list((tmp_path / "got" / ".ttctl-partial").glob("*.part"))


NO_INFLATE = r'''
import json, socket, sys, time
from pathlib import Path
import ttapi
from ttctl.wire.bindings import Bindings
from ttctl.proto.endpoint import Endpoint
from ttctl.proto.storage import ReceiveDir

sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
sock.bind(("127.0.0.1", 0))
sock.settimeout(0.005)
print(sock.getsockname()[1], flush=True)
ep = Endpoint(Bindings(ttapi), 1, 240, rate_Bps=20000, receive_dir=ReceiveDir(Path(sys.argv[1])), inflate=False)
peer = None
t0 = time.monotonic()
while time.monotonic() - t0 < float(sys.argv[2]) and not Path(sys.argv[1] + ".stop").exists():
    now = time.monotonic() - t0
    while peer is not None and (p := ep.poll(now)) is not None:
        sock.sendto(p, peer)
    try:
        data, peer = sock.recvfrom(65536)
        ep.receive(time.monotonic() - t0, data, peer)
    except socket.timeout:
        pass
'''


def test_the_java_sender_deflates_text_and_sends_the_rest_as_it_is(classes: Path, tmp_path: Path,
                                                                   start: Start) -> None:
    """The Java sender (FileTransfers.send) through the m100 relay at 10 % loss to `ttctl
    recv-file`: a CSV log goes deflated (recv-file says so; the file verified byte for byte),
    random bytes go as they are (the sample does not shrink)."""
    a, b = free_port(), free_port()
    rx = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--rate", "8000")
    relay(start, a, b, "--profile", "m100", "--rate", "8000", "--loss", "0.1", "--seed", "22", "--stats-interval", "0")
    (tmp_path / "log.csv").write_bytes(flight_log_csv(seconds=30))
    size = (tmp_path / "log.csv").stat().st_size
    r = Driver(classes, tmp_path, "java", link="udp", port=a, rate=8000, timeout=30, send="log.csv").finish(120)
    assert r["send_ok"] and r["send_bytes"] == size and 0 < r["send_deflated"] < size / 3, r["_text"][-3000:]
    assert sha(tmp_path / "inbox" / "log.csv") == sha(tmp_path / "log.csv")
    rx.wait_for(f"accepted log.csv ({size} bytes) from 255/190, deflated to {r['send_deflated']} B on the link",
                where="stdout")
    (tmp_path / "noise.bin").write_bytes(os.urandom(6000))
    r = Driver(classes, tmp_path, "java2", link="udp", port=a, rate=8000, timeout=30, send="noise.bin").finish(120)
    assert r["send_ok"] and r["send_bytes"] == 6000 and r["send_deflated"] == -1, r["_text"][-3000:]
    assert sha(tmp_path / "inbox" / "noise.bin") == sha(tmp_path / "noise.bin")


def test_the_java_sender_falls_back_where_the_receiver_does_not_inflate(classes: Path, tmp_path: Path) -> None:
    """A receiver that does not inflate (Python's, inflate=False, as a process) refuses the
    deflated offer in words; the Java sender offers the file as it is under a new id, it
    arrives verified, and the result says why it went as it is."""
    (tmp_path / "mission.yaml").write_bytes(mission_yaml())
    inbox = tmp_path / "inbox"
    p = subprocess.Popen([sys.executable, "-c", NO_INFLATE, str(inbox), "60"], stdout=subprocess.PIPE, text=True,
                         env={**os.environ, "PYTHONPATH": str(ROOT / "generated" / "python")})
    try:
        assert p.stdout is not None
        port = int(p.stdout.readline())
        r = Driver(classes, tmp_path, "java", link="udp", port=port, rate=20000, timeout=20,
                   send="mission.yaml").finish(60)
    finally:
        Path(str(inbox) + ".stop").write_text("")
        p.wait(10)
    assert r["send_ok"] and r["send_deflated"] == -1, r["_text"][-3000:]
    assert "(sent as it is: offer flags 0x04 not understood here: this receiver does not decompress)" in \
        r["send_message"], r["send_message"]
    assert sha(inbox / "mission.yaml") == sha(tmp_path / "mission.yaml")


def test_the_java_inbox_resumes_the_stream_ttctl_recv_file_left(classes: Path, tmp_path: Path,
                                                                start: Start) -> None:
    """A deflated upload resumes across receivers: `ttctl recv-file` takes the first part of
    the zlib stream and is killed; the Java inbox, on the same port and folder, resumes from
    the partial stream and record it left (KEY-zSIZE), inflates and verifies the file, and the
    one send-file completes."""
    (tmp_path / "outbox").mkdir()
    port = free_port()
    log = tmp_path / "big.csv"
    log.write_bytes(flight_log_csv(seconds=300))
    rx = start("recv", "recv-file", "--listen", f"udpin:{LOCAL}:{port}", "--dir", str(tmp_path / "inbox"),
               "--rate", "4000", "--sysid", "255", "--compid", "190")
    rx.wait_for("receiving into")
    sender = subprocess.Popen([*_ttctl(), "send-file", str(log), "--to", f"udpout:{LOCAL}:{port}", "--rate", "4000",
                               "--timeout", "30", "--json", "--sysid", "1", "--compid", "240", "--target-sysid", "255",
                               "--target-compid", "190"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        rx.wait_for("accepted big.csv", where="stdout")
        time.sleep(3.0)
        rx.kill()
        records = list((tmp_path / "inbox" / ".ttctl-partial").glob("*-z*.json"))
        assert records and json.loads(records[0].read_text())["original"] == log.stat().st_size
        j = tablet_inbox(classes, tmp_path, "tablet", port)
        out, err = sender.communicate(timeout=90)
    finally:
        if sender.poll() is None:
            sender.kill()
    report = json.loads(out)
    assert sender.returncode == 0 and report["ok"] and report["deflated_bytes"], err
    r = stop(j, tmp_path)
    (res,) = [x for x in r["results"] if x["name"] == "big.csv"]
    assert res["ok"] and 0 < res["resumed"] < res["deflated"] == report["deflated_bytes"], res
    assert res["moved"] == res["deflated"] - res["resumed"] and res["size"] == log.stat().st_size, res
    assert sha(tmp_path / "inbox" / "big.csv") == sha(log)
    assert not list((tmp_path / "inbox" / ".ttctl-partial").glob("*"))


def test_ttctl_recv_file_resumes_the_stream_the_java_inbox_left(classes: Path, tmp_path: Path,
                                                                start: Start) -> None:
    """The other way: the Java inbox takes the first part of the zlib stream and its JVM is
    killed (SIGKILL); `ttctl recv-file` on the same port and folder reads the partial stream
    and record the Java end wrote ("original": the file's size) and resumes it."""
    (tmp_path / "outbox").mkdir()
    port = free_port()
    log = tmp_path / "big.csv"
    log.write_bytes(flight_log_csv(seconds=300))
    j = tablet_inbox(classes, tmp_path, "tablet", port, rate=4000)
    sender = subprocess.Popen([*_ttctl(), "send-file", str(log), "--to", f"udpout:{LOCAL}:{port}", "--rate", "4000",
                               "--timeout", "30", "--json", "--sysid", "1", "--compid", "240", "--target-sysid", "255",
                               "--target-compid", "190"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        j.wait_for("incoming incoming big.csv", timeout=30)
        time.sleep(3.0)
        j.kill()
        records = list((tmp_path / "inbox" / ".ttctl-partial").glob("*-z*.json"))
        assert records and json.loads(records[0].read_text())["original"] == log.stat().st_size
        rx = start("recv", "recv-file", "--listen", f"udpin:{LOCAL}:{port}", "--dir", str(tmp_path / "inbox"),
                   "--rate", "4000", "--sysid", "255", "--compid", "190")
        rx.wait_for("receiving into")
        out, err = sender.communicate(timeout=90)
    finally:
        if sender.poll() is None:
            sender.kill()
    report = json.loads(out)
    assert sender.returncode == 0 and report["ok"] and report["deflated_bytes"], err
    rx.wait_for("accepted big.csv", where="stdout")
    (line,) = [ln for ln in rx.stdout.splitlines() if ln.startswith("accepted big.csv")]
    assert f"deflated to {report['deflated_bytes']} B on the link, resuming with" in line, line
    held = int(line.split("resuming with ")[1].split()[0])
    assert 0 < held < report["deflated_bytes"], line
    assert sha(tmp_path / "inbox" / "big.csv") == sha(log)


def test_the_drone_fetches_text_the_java_end_serves_deflated(classes: Path, tmp_path: Path, start: Start) -> None:
    """`ttctl send-file NAME --from` the Java end's served folder through the m100 relay at
    10 % loss: the Java server offers the CSV log deflated, the Python requester inflates and
    verifies it; random bytes served the same way go as they are."""
    (tmp_path / "outbox").mkdir()
    served = tmp_path / "outbox" / "log.csv"
    served.write_bytes(flight_log_csv(seconds=30))
    (tmp_path / "outbox" / "noise.bin").write_bytes(os.urandom(4000))
    a, b = free_port(), free_port()
    relay(start, a, b, "--profile", "m100", "--rate", "8000", "--loss", "0.1", "--seed", "23", "--stats-interval", "0")
    j = tablet_inbox(classes, tmp_path, "tablet", b)
    proc, rep = drone_send("log.csv", "--from", f"udpout:{LOCAL}:{a}", "--dir", str(tmp_path / "got"), "--rate", "8000",
                           "--timeout", "30")
    assert proc.returncode == 0 and rep["ok"], proc.stdout + proc.stderr
    assert rep["deflated_bytes"] and rep["deflated_bytes"] < served.stat().st_size / 3, rep
    assert sha(tmp_path / "got" / "log.csv") == sha(served)
    proc, rep = drone_send("noise.bin", "--from", f"udpout:{LOCAL}:{a}", "--dir", str(tmp_path / "got"), "--rate",
                           "8000", "--timeout", "30")
    assert proc.returncode == 0 and rep["ok"] and not rep["deflated_bytes"], proc.stdout + proc.stderr
    assert sha(tmp_path / "got" / "noise.bin") == sha(tmp_path / "outbox" / "noise.bin")
    r = stop(j, tmp_path)
    assert any(x["name"] == "log.csv" and x["ok"] and x["served"] for x in r["results"]), r


@pytest.mark.parametrize("first", ["java", "python"])
def test_a_killed_sender_s_deflated_upload_is_resumed_by_the_java_sender(classes: Path, tmp_path: Path,
                                                                         start: Start, first: str) -> None:
    """The first sender (the Java runtime, or `ttctl send-file`) is killed (SIGKILL) a fifth
    of the way into a deflated upload to `ttctl recv-file`; the Java sender sending the same
    file makes the same stream (zlib level 6, whole file: java.util.zip and Python's zlib write
    the same bytes), so the receiver's partial stream resumes: only the rest moves, and the
    file lands verified."""
    port = free_port()
    rx = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--rate", "4000")
    (tmp_path / "big.csv").write_bytes(flight_log_csv(seconds=300))
    if first == "java":
        d = Driver(classes, tmp_path, "java", link="udp", port=port, rate=4000, timeout=30, send="big.csv")
        d.wait_for("EVENT progress send")  # printed every 8 KiB
        d.p.kill()
        d.p.wait(10)
        d._out.close()
    else:
        p = subprocess.Popen([*_ttctl(), "send-file", str(tmp_path / "big.csv"), "--to", f"udpout:{LOCAL}:{port}",
                              "--rate", "4000", "--timeout", "30", "--sysid", "255", "--compid", "190"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            rx.wait_for("accepted big.csv", where="stdout")
            time.sleep(3.0)
        finally:
            p.kill()
            p.wait(10)
    r = Driver(classes, tmp_path, "java2", link="udp", port=port, rate=4000, timeout=30, send="big.csv").finish(120)
    assert r["send_ok"] and r["send_deflated"] > 0 and 0 < r["send_resumed"] < r["send_deflated"], r["_text"][-3000:]
    assert r["send_moved"] == r["send_deflated"] - r["send_resumed"], r
    assert sha(tmp_path / "inbox" / "big.csv") == sha(tmp_path / "big.csv")
    rx.wait_for("resuming with", where="stdout")


def test_what_arrived_as_it_is_is_not_orphaned_by_a_deflated_offer(classes: Path, tmp_path: Path,
                                                                   start: Start) -> None:
    """Part of the log reached the Java inbox as it is (`send-file --no-compress`, killed); the
    same file offered deflated would orphan it: the inbox refuses that in the Python receiver's
    words, the sender sends the file as it is and resumes what is there."""
    (tmp_path / "outbox").mkdir()
    port = free_port()
    log = tmp_path / "big.csv"
    log.write_bytes(flight_log_csv(seconds=100))
    j = tablet_inbox(classes, tmp_path, "tablet", port, rate=4000)
    first = subprocess.Popen([*_ttctl(), "send-file", str(log), "--to", f"udpout:{LOCAL}:{port}", "--rate", "4000",
                              "--no-compress", "--timeout", "30", "--json", "--sysid", "1", "--compid", "240",
                              "--target-sysid", "255", "--target-compid", "190"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        j.wait_for("progress big.csv 8", timeout=30)
    finally:
        first.kill()
        first.wait(10)
    proc, r = drone_send(str(log), "--to", f"udpout:{LOCAL}:{port}", "--rate", "4000", "--timeout", "30")
    assert proc.returncode == 0 and r["ok"] and r["deflated_bytes"] is None, proc.stdout + proc.stderr
    assert r["deflate_fallback"] and r["deflate_fallback"].endswith(
        "bytes of it as it is are here: send it uncompressed to resume"), r
    held = int(r["deflate_fallback"].split()[0])
    assert held >= 8192 and r["resumed_bytes"] >= held, r
    stop(j, tmp_path)
    assert sha(tmp_path / "inbox" / "big.csv") == sha(log)
