"""Deflate at the generated C++ onboard end (templates/cpp/deflate.hpp.j2): real onboard_node
processes (tests/cpp_node_lib.py) against ttctl's Python ends.

- receiving: `ttctl send-file` of text (it deflates by default) to the node, through the m100
  relay at 10 % loss, arrives as the file, the stream counted on the link; killed mid-transfer
  and restarted, the node (or recv-file on its folder) resumes the stream from its partial file;
- hostile streams sent frame by frame to the node under the sanitizers (a bomb declaring a small
  size, corrupt bytes, a stream that inflates to less, a stream over the quota, a deflate offer
  without a name): each refused with the words ttctl's Python receiver uses, nothing under the
  final name, nothing kept;
- sending: the node's uploads (Node::send_file) to `ttctl recv-file` through the m100 relay go
  deflated when the file compresses (its stream counted by both ends), as they are when it
  does not (random bytes); a sending node killed and started again resumes (the same stream);
  a fetch from the node's serve folder comes deflated;
- built with TTCTL_NO_ZLIB, the node refuses deflated offers in words (REFUSED_UNSUPPORTED):
  `ttctl send-file` and a deflating C++ node then send the file as it is.
"""

from __future__ import annotations

import hashlib
import json
import random
import subprocess
import time
import zlib
from pathlib import Path
from typing import Any

import pytest

import ttapi
from cpp_node_lib import PROGRAM, WARN, Raw, generate, needs_gxx, sha, write
from e2e_lib import LOCAL, Start, free_port, receiver, relay, send
from machine import scaled
from ttctl.bench.textfiles import flight_log_csv, mission_yaml

pytestmark = needs_gxx

R = ttapi.TtFileResult
DEFLATE = int(ttapi.TtFileFlags.TT_FILE_FLAGS_DEFLATE)


def finals(folder: Path) -> list[str]:
    """Files under their final names (not the partial folder)."""
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*")
                  if p.is_file() and ".ttctl-partial" not in p.parts)


def leftovers(folder: Path) -> list[str]:
    part = folder / ".ttctl-partial"
    return sorted(p.name for p in part.iterdir()) if part.exists() else []


# -- receiving what ttctl send-file deflates ------------------------------------------------------

def test_text_goes_deflated_to_the_node_through_the_m100_relay(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                              start: Start, cpp_nodes: Any) -> None:
    log = tmp_path / "flight.csv"
    log.write_bytes(flight_log_csv(seconds=60))
    inbox = tmp_path / "inbox"
    b = free_port()
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:{b}", "--inbox",
                     str(inbox), "--rate", "8000")
    a = free_port()
    relay(start, a, b, "--profile", "m100", "--rate", "8000", "--loss", "0.1", "--seed", "5", "--stats-interval", "0")
    proc, r = send(str(log), "--to", f"udpout:{LOCAL}:{a}", "--rate", "8000", "--timeout", "30", timeout=120)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    size = log.stat().st_size
    assert r["deflate_fallback"] is None and r["deflated_bytes"] is not None and r["deflated_bytes"] < size / 3, r
    assert sha(inbox / "flight.csv") == sha(log)
    assert finals(inbox) == ["flight.csv"] and leftovers(inbox) == []
    done = node.wait_event("complete", name="flight.csv")
    assert done["bytes"] == size, done  # the file's size, not the stream's
    stats = node.stop()
    assert stats["files_received"] == 1 and stats["files_refused"] == 0, stats


@pytest.mark.parametrize("then", ["cpp", "python"])
def test_the_node_killed_mid_deflated_upload_resumes_the_stream(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                              start: Start, cpp_nodes: Any, then: str) -> None:
    """The node is SIGKILLed once part of the stream is in its partial file; restarted (or
    `ttctl recv-file` started on the same folder: the partial and its record are the same
    format), it resumes from there (the record names the file's size as `original`), and the
    file that takes the name is the file."""
    log = tmp_path / "flight.csv"
    log.write_bytes(flight_log_csv(seconds=120))
    inbox = tmp_path / "inbox"
    b = free_port()
    args = ("--listen", f"udpin:{LOCAL}:{b}", "--inbox", str(inbox), "--rate", "4000")
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", *args)
    sender = start("send", "send-file", str(log), "--to", f"udpout:{LOCAL}:{b}", "--rate", "4000", "--timeout", "60",
                   "--json")
    had = stream_held(inbox, 8000)
    node.kill()
    if then == "cpp":
        node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node2", *args)
    else:
        py = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--rate", "4000", "--json")
    assert sender.wait(90) == 0, sender.stderr
    r = json.loads(sender.stdout)
    assert r["ok"] and r["deflated_bytes"] is not None and r["deflate_fallback"] is None, r
    assert sha(inbox / "flight.csv") == sha(log)
    if then == "cpp":
        accepted = node.wait_event("accepted", name="flight.csv")
        node.stop()
    else:
        accepted = next(json.loads(line) for line in py.stdout.splitlines() if '"accepted"' in line)
    assert accepted["resumed_bytes"] >= had, accepted
    assert finals(inbox) == ["flight.csv"] and leftovers(inbox) == []


def stream_held(inbox: Path, least: int, timeout: float = 30.0) -> int:
    """Bytes of a zlib stream (a partial whose key ends in -z<size>) the record says arrived,
    once at least `least`."""
    timeout = scaled(timeout)  # longer on a busy machine
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        for rec in (inbox / ".ttctl-partial").glob("*-z*.json"):
            try:
                state = json.loads(rec.read_text())
            except (OSError, ValueError):
                continue
            assert isinstance(state["original"], int), state
            held = sum(b - a for a, b in state["ranges"])
            if held >= least:
                return held
        time.sleep(0.02)
    raise AssertionError(f"no partial stream of {least} bytes")


# -- sending: the node's uploads ------------------------------------------------------------------

@pytest.mark.parametrize("kind", ["text", "random"])
def test_the_node_uploads_deflated_what_compresses(cpp_node_bins: dict[str, Path], tmp_path: Path, start: Start,
                                                   cpp_nodes: Any, kind: str) -> None:
    """Node::send_file to `ttctl recv-file` through the m100 relay at 10 % loss: a CSV log goes
    as its zlib stream (under a third of the file on the link) and arrives as the file; random
    bytes go as they are."""
    if kind == "text":
        src = tmp_path / "flight.csv"
        src.write_bytes(flight_log_csv(seconds=60))
    else:
        src = write(tmp_path / "noise.bin", 20_000, 31)
    size = src.stat().st_size
    b = free_port()
    rx = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--rate", "8000", "--json")
    a = free_port()
    relay(start, a, b, "--profile", "m100", "--rate", "8000", "--loss", "0.1", "--seed", "9", "--stats-interval", "0")
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--to", f"udpout:{LOCAL}:{a}", "--sysid", "2", "--rate",
                     "8000", "--send", str(src), "--send-to", "1/240")
    sent = node.wait_event("sent", 60)
    assert sent["ok"] and sent["code"] == "COMPLETE", sent
    assert sent["message"] == f"{src.name}: {size} bytes delivered and verified", sent
    assert sent["deflate_fallback"] is None, sent
    rx.wait_for('"event": "complete"', 10, where="stdout")
    assert sha(tmp_path / "inbox" / src.name) == sha(src)
    if kind == "text":
        assert 0 < sent["deflated_bytes"] < size / 3, sent
        assert sent["bytes_sent"] < size / 2, sent  # what moved is the stream
        assert f'"deflated_bytes": {sent["deflated_bytes"]}' in rx.stdout, rx.stdout
    else:
        assert sent["deflated_bytes"] == 0 and sent["bytes_sent"] >= size, sent
    node.stop()


def test_the_node_killed_mid_deflated_upload_resumes_when_it_sends_again(cpp_node_bins: dict[str, Path],
                                                                        tmp_path: Path, start: Start,
                                                                        cpp_nodes: Any) -> None:
    """The sending node SIGKILLed half way through a deflated upload to `ttctl recv-file`, then
    started again with the same file: it deflates it to the same stream, so recv-file resumes
    its partial stream and only the rest is sent."""
    src = tmp_path / "flight.csv"
    src.write_bytes(flight_log_csv(seconds=120))
    b = free_port()
    rx = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--rate", "4000", "--json")
    args = ("--to", f"udpout:{LOCAL}:{b}", "--sysid", "2", "--rate", "4000", "--send", str(src), "--send-to", "1/240")
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", *args)
    had = stream_held(tmp_path / "inbox", 8000)
    node.kill()
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node2", *args)
    sent = node.wait_event("sent", 60)
    assert sent["ok"] and sent["deflated_bytes"] > 0, sent
    assert sent["bytes_sent"] <= sent["deflated_bytes"] - had + 4000, sent
    rx.wait_for('"event": "complete"', 10, where="stdout")
    assert sha(tmp_path / "inbox" / "flight.csv") == sha(src)
    accepted = [json.loads(line) for line in rx.stdout.splitlines() if '"accepted"' in line]
    assert len(accepted) == 2 and accepted[1]["resumed_bytes"] >= had, accepted
    node.stop()


def test_a_fetch_from_the_node_comes_deflated(cpp_node_bins: dict[str, Path], tmp_path: Path, start: Start,
                                              cpp_nodes: Any) -> None:
    """`ttctl send-file --from` the node's serve folder through the m100 relay: the node serves
    the CSV log as its zlib stream, and the file that arrives is the file."""
    serve = tmp_path / "serve"
    serve.mkdir()
    (serve / "flight.csv").write_bytes(flight_log_csv(seconds=60))
    size = (serve / "flight.csv").stat().st_size
    b = free_port()
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:{b}", "--serve", str(serve),
                     "--rate", "8000")
    a = free_port()
    relay(start, a, b, "--profile", "m100", "--rate", "8000", "--loss", "0.1", "--seed", "6", "--stats-interval", "0")
    got = tmp_path / "got"
    got.mkdir()
    proc, r = send("flight.csv", "--from", f"udpout:{LOCAL}:{a}", "--dir", str(got), "--rate", "8000", "--timeout",
                   "30", timeout=120)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert r["deflated_bytes"] is not None and r["deflated_bytes"] < size / 3, r
    assert sha(got / "flight.csv") == sha(serve / "flight.csv")
    served = node.wait_event("served", name="flight.csv")
    assert served["bytes"] == size, served
    node.stop()


# -- hostile streams, frame by frame --------------------------------------------------------------

class Hostile:
    """Offers a zlib stream to the node with metadata of its choosing, sends every byte, and
    gathers the node's answers."""

    def __init__(self, port: int) -> None:
        self.raw = Raw(port)
        self.tid = 7000

    def offer(self, stream: bytes, original: bytes, declared: int, name: bytes = b"x.txt",
              flags: int = DEFLATE) -> tuple[int, str]:
        """(final result, reason) of offering `stream` as the deflated file `original` declared
        at `declared` bytes."""
        self.tid += 1
        tid = self.tid
        meta = hashlib.sha256(original).digest() + declared.to_bytes(4, "little") + name
        self.raw.frames(*[ttapi.TtFileOffer(target_system=1, target_component=240, transfer_id=tid, size=len(stream),
                                            flags=flags, meta_length=len(meta), meta_offset=off,
                                            meta=meta[off:off + 71]) for off in range(0, len(meta), 71)])
        got = self._until(tid, lambda m: True)
        first = next(m for m in got if isinstance(m, ttapi.TtFileStatus) and m.transfer_id == tid)
        if first.result == R.TT_FILE_RESULT_IN_PROGRESS:
            for off in range(0, len(stream), 80):
                self.raw.frames(ttapi.TtFileData(transfer_id=tid, offset=off, data=stream[off:off + 80]))
            got = self._until(tid, lambda m: m.result != R.TT_FILE_RESULT_IN_PROGRESS)
        final = [m for m in got if isinstance(m, ttapi.TtFileStatus) and m.transfer_id == tid][-1]
        reasons = [m.text for m in got if isinstance(m, ttapi.TtFileReason) and m.transfer_id == tid]
        return final.result, reasons[-1] if reasons else ""

    def _until(self, tid: int, done: Any) -> list[Any]:
        return self.raw.collect(10.0, until=lambda ms: any(
            isinstance(m, ttapi.TtFileStatus) and m.transfer_id == tid and done(m) for m in ms))


def test_hostile_streams_are_stopped_and_refused_in_words(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                         cpp_nodes: Any) -> None:
    """Under ASan/UBSan: each is refused with the Python receiver's words (proto/deflate.py),
    nothing under the final name and nothing kept (no resume can use a stream that is not the
    file), and the node then takes a good stream."""
    inbox = tmp_path / "inbox"
    node = cpp_nodes(cpp_node_bins["asan"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox),
                     "--max-file", "100000")
    h = Hostile(node.port)
    try:
        big = b"\0" * (1 << 20)  # a 1 MiB bomb declared as 4096 bytes: stopped at the 4097th
        assert h.offer(zlib.compress(big, 9), big[:4096], 4096) == (
            R.TT_FILE_RESULT_FAILED_CHECKSUM, "the stream inflates to more than the 4096 bytes offered")
        assert finals(inbox) == [] and leftovers(inbox) == []
        text = mission_yaml()
        corrupt = bytearray(zlib.compress(text, 6))
        corrupt[len(corrupt) // 2] ^= 0xFF
        code, why = h.offer(bytes(corrupt), text, len(text))
        assert code == R.TT_FILE_RESULT_FAILED_CHECKSUM and (why.startswith("the stream") or "SHA-256" in why), why
        less = f"the stream inflates to {len(text) - 100} bytes, not the {len(text)} offered"
        assert h.offer(zlib.compress(text[:-100], 6), text, len(text)) == (R.TT_FILE_RESULT_FAILED_CHECKSUM, less)
        short = zlib.compress(text, 6)
        assert h.offer(short[:-10], text, len(text))[0] == R.TT_FILE_RESULT_FAILED_CHECKSUM
        assert h.offer(b"not zlib at all" * 20, text, len(text)) == (
            R.TT_FILE_RESULT_FAILED_CHECKSUM, "the stream does not inflate (incorrect header check)")
        assert h.offer(short + b"tail", text, len(text)) == (
            R.TT_FILE_RESULT_FAILED_CHECKSUM, "the stream has bytes after its end")
        assert finals(inbox) == [] and leftovers(inbox) == []
        # refused at the offer, before any data: a stream over the per-file quota, no name
        assert h.offer(random.Random(1).randbytes(150_000), b"tiny", 4) == (
            R.TT_FILE_RESULT_REFUSED_QUOTA, "a 150000-byte stream exceeds the per-file quota of 100000 bytes")
        assert h.offer(zlib.compress(big, 9), big, len(big))[0] == R.TT_FILE_RESULT_REFUSED_QUOTA
        assert h.offer(short, text, len(text), name=b"") == (
            R.TT_FILE_RESULT_REFUSED_NAME, "the deflate offer carries no name")
        # a flag this node does not know, beside DEFLATE: refused naming it
        assert h.offer(short, text, len(text), name=b"m.yaml", flags=DEFLATE | 0x40) == (
            R.TT_FILE_RESULT_REFUSED_UNSUPPORTED, "offer flags 0x40 not understood here")
        # and a good stream still goes in
        assert h.offer(short, text, len(text), name=b"m.yaml") == (R.TT_FILE_RESULT_COMPLETE, "")
        assert (inbox / "m.yaml").read_bytes() == text
        assert finals(inbox) == ["m.yaml"] and leftovers(inbox) == []
    finally:
        h.raw.close()
    node.stop()


# -- without zlib ---------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def nozlib_node(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """onboard_node built with -DTTCTL_NO_ZLIB and without -lz: the runtime needs no zlib."""
    tmp = tmp_path_factory.mktemp("nozlib")
    exe = tmp / "onboard_node_nozlib"
    proc = subprocess.run(["g++", *WARN, "-O0", "-DTTCTL_NO_ZLIB", *generate(tmp), str(PROGRAM), "-o", str(exe)],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-5000:]
    return exe


REFUSAL = "offer flags 0x04 not understood here: this receiver does not decompress"


def test_without_zlib_the_node_refuses_deflate_and_the_sender_falls_back(nozlib_node: Path, tmp_path: Path,
                                                                        cpp_nodes: Any) -> None:
    text = tmp_path / "mission.yaml"
    text.write_bytes(mission_yaml())
    inbox = tmp_path / "inbox"
    node = cpp_nodes(nozlib_node, tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox))
    proc, r = send(str(text), "--to", f"udpout:{LOCAL}:{node.port}", "--rate", "8000", timeout=60)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert r["deflate_fallback"] == REFUSAL and r["deflated_bytes"] is None, r
    assert sha(inbox / "mission.yaml") == sha(text)
    refused = node.events("refused")
    assert len(refused) == 1 and refused[0]["reason"] == REFUSAL, refused
    assert finals(inbox) == ["mission.yaml"]
    node.stop()


def test_a_deflating_node_falls_back_to_the_file_at_a_node_without_zlib(cpp_node_bins: dict[str, Path],
                                                                        nozlib_node: Path, tmp_path: Path,
                                                                        cpp_nodes: Any) -> None:
    """C++ to C++: the receiver built with TTCTL_NO_ZLIB refuses the stream in words; the
    sender offers the file as it is under a new id and says why."""
    src = tmp_path / "mission.yaml"
    src.write_bytes(mission_yaml())
    inbox = tmp_path / "inbox"
    rx = cpp_nodes(nozlib_node, tmp_path, "rx", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox))
    tx = cpp_nodes(cpp_node_bins["plain"], tmp_path, "tx", "--to", f"udpout:{LOCAL}:{rx.port}", "--sysid", "2",
                   "--send", str(src), "--send-to", "1/240")
    sent = tx.wait_event("sent", 30)
    assert sent["ok"] and sent["deflate_fallback"] == REFUSAL and sent["deflated_bytes"] == 0, sent
    assert sha(inbox / "mission.yaml") == sha(src)
    assert [e["reason"] for e in rx.events("refused")] == [REFUSAL]
    tx.stop()
    rx.stop()
