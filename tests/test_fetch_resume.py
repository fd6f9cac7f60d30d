"""A fetch (`send-file --from`) whose server restarts mid-file resumes in the same run (issue 28),
and `resumed_bytes` says what the receiving side already had, for uploads and fetches.

Real processes on 127.0.0.1: `ttctl recv-file --serve` or the generated C++ onboard node
(tests/cpp_node_lib.py) as the server, SIGKILLed at seeded random offsets of the file and
started again on the same port; `ttctl send-file --from` carries on in the same run, asks
again from where its verified data ends, and ends with the server's SHA-256 and exit 0. A
server that comes back with a different file under the name is never spliced: the fetch starts
that file again from nothing and says so.
"""

from __future__ import annotations

import json
import random
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from conftest import run_ttctl
from cpp_node_lib import needs_gxx, sha, write
from e2e_lib import LOCAL, Proc, Start, free_port, one_line, receiver, send
from machine import scaled

SIZE = 96_000
RATE = "16000"  # B/s, the server's pace: a whole file in about 6 s
TIMEOUT = 30  # send-file's --timeout: the old code waited all of it out after a restart


def partial_bytes(folder: Path) -> int:
    """What the partial files' records in `folder` say was received."""
    total = 0
    for rec in (folder / ".ttctl-partial").glob("*.json"):
        try:
            state = json.loads(rec.read_text())
        except ValueError:
            continue
        total += sum(b - a for a, b in state["ranges"])
    return total


def wait_partial(folder: Path, at_least: int, proc: Proc | None = None, timeout: float = 30.0) -> int:
    timeout = scaled(timeout)  # longer on a busy machine
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        n = partial_bytes(folder)
        if n >= at_least:
            return n
        if proc is not None and proc.p.poll() is not None:
            raise AssertionError(f"{proc.name} ended early ({proc.p.returncode}):\n{proc.stdout}\n{proc.stderr}")
        time.sleep(0.02)
    raise AssertionError(f"the partial file never held {at_least} bytes ({partial_bytes(folder)})")


def offsets(seed: int, n: int) -> list[int]:
    """`n` kill points, increasing, between 15 % and 85 % of the file, one in each n-th of that."""
    rng = random.Random(seed)
    step = 0.7 / n
    return [int(SIZE * rng.uniform(0.15 + i * step, 0.15 + (i + 1) * step)) for i in range(n)]


def kill_points(seed: int, n: int, folder: Path, f: Proc) -> Iterator[int]:
    """Wait for each kill point in turn (each at least 3000 bytes past the previous kill, so
    that every restarted server serves some of the file before it is killed in its turn)."""
    had = 0
    for at in offsets(seed, n):
        had = wait_partial(folder, min(max(at, had + 3000), SIZE - 10_000), f)
        yield had


def fetch(start: Start, tmp: Path, port: int, name: str = "log.bin") -> Proc:
    got = tmp / "got"
    got.mkdir(exist_ok=True)
    return start("fetch", "send-file", name, "--from", f"udpout:{LOCAL}:{port}", "--dir", str(got), "--rate", RATE,
                 "--timeout", str(TIMEOUT), "--json")


def finished(proc: Proc, began: float, bound: float) -> dict[str, Any]:
    code = proc.wait(bound + 5)
    took = time.monotonic() - began
    assert code == 0, proc.stderr
    assert took < bound, f"took {took:.1f} s:\n{proc.stderr}"
    report: dict[str, Any] = json.loads(proc.stdout)
    assert report["ok"], report
    return report


def python_server(start: Start, tmp: Path, spec: str, serve: Path, name: str, kind: str = "recv-file") -> Proc:
    """Python's serving end: `ttctl recv-file --serve`, or `ttctl emulate onboard --serve`."""
    if kind == "recv-file":
        return receiver(start, tmp, spec, "--serve", str(serve), "--rate", RATE, name=name)
    p = start(name, "emulate", "onboard", "--listen", spec, "--no-gcs", "--no-entry-points", "--serve", str(serve),
              "--rate", RATE)
    p.wait_for("onboard 1:")
    return p


@pytest.mark.parametrize("kind", ["recv-file", "emulate-onboard"])
def test_a_fetch_resumes_in_the_same_run_when_its_python_server_restarts(tmp_path: Path, start: Start,
                                                                         kind: str) -> None:
    """recv-file --serve (or emulate onboard --serve) killed and started again 2-3 times at seeded
    random offsets: the fetch completes in the same run, well within --timeout of the last
    restart, with the SHA-256 of the served file; each restart is reported, and nothing was there
    before the run."""
    seed = random.randrange(1 << 16)
    n = 2 + seed % 2
    serve = tmp_path / "serve"
    src = write(serve / "log.bin", SIZE, seed)
    port = free_port()
    spec = f"udpin:{LOCAL}:{port}"
    server = python_server(start, tmp_path, spec, serve, "server0", kind)
    began = time.monotonic()
    f = fetch(start, tmp_path, port)
    rng = random.Random(seed)
    for i, _ in enumerate(kill_points(seed, n, tmp_path / "got", f)):
        server.kill()
        time.sleep(rng.uniform(0.2, 1.0))
        server = python_server(start, tmp_path, spec, serve, f"server{i + 1}", kind)
    # each restart costs a few seconds at most; the old code waited out --timeout after the first
    r = finished(f, began, TIMEOUT - 5)
    assert sha(tmp_path / "got" / "log.bin") == sha(src), f"seed {seed}"
    assert r["sha256"] == sha(src)
    assert r["resumed_bytes"] == 0, r
    assert r["server_restarts"] == n, (r, f.stderr, f"seed {seed}")
    assert f.stderr.count("resuming at") == n, f.stderr


@needs_gxx
def test_a_fetch_resumes_in_the_same_run_when_its_cpp_server_restarts(cpp_node_bins: dict[str, Path],
                                                                      tmp_path: Path, start: Start,
                                                                      cpp_nodes: Any) -> None:
    """The same against the generated C++ onboard node serving the file, killed twice."""
    seed = random.randrange(1 << 16)
    serve = tmp_path / "serve"
    src = write(serve / "log.bin", SIZE, seed)
    port = free_port()
    spec = f"udpin:{LOCAL}:{port}"

    def node(i: int) -> Any:
        return cpp_nodes(cpp_node_bins["plain"], tmp_path, f"node{i}", "--listen", spec, "--serve", str(serve),
                         "--rate", RATE)

    n = node(0)
    began = time.monotonic()
    f = fetch(start, tmp_path, port)
    rng = random.Random(seed)
    for i, _ in enumerate(kill_points(seed, 2, tmp_path / "got", f)):
        n.kill()
        time.sleep(rng.uniform(0.2, 1.0))
        n = node(i + 1)
    r = finished(f, began, TIMEOUT - 5)
    assert sha(tmp_path / "got" / "log.bin") == sha(src), f"seed {seed}"
    assert r["server_restarts"] == 2 and r["resumed_bytes"] == 0, (r, f.stderr)
    assert n.events("served")
    n.stop()


def test_a_server_back_with_another_file_is_not_spliced(tmp_path: Path, start: Start) -> None:
    """The server restarts serving a different log.bin (the same size, other bytes): the fetch
    does not splice the two; it fetches the new file from nothing, says so, and ends with the
    new file's SHA-256."""
    serve = tmp_path / "serve"
    write(serve / "log.bin", SIZE, 1)
    port = free_port()
    spec = f"udpin:{LOCAL}:{port}"
    server = receiver(start, tmp_path, spec, "--serve", str(serve), "--rate", RATE, name="server0")
    began = time.monotonic()
    f = fetch(start, tmp_path, port)
    wait_partial(tmp_path / "got", SIZE // 2, f)
    server.kill()
    new = write(serve / "log.bin", SIZE, 2)
    receiver(start, tmp_path, spec, "--serve", str(serve), "--rate", RATE, name="server1")
    r = finished(f, began, TIMEOUT - 5)
    assert sha(tmp_path / "got" / "log.bin") == sha(new)
    assert r["sha256"] == sha(new) and r["server_restarts"] == 1, r
    assert "a different log.bin" in f.stderr and "from the start" in f.stderr, f.stderr
    assert "resuming at" not in f.stderr, f.stderr
    assert partial_bytes(tmp_path / "got") == 0  # the old file's bytes went with it


def test_a_server_back_without_the_file_refuses_in_its_words(tmp_path: Path, start: Start) -> None:
    """The server restarts and no longer has log.bin: the fetch asks again, hears NOT_FOUND and
    ends at once (exit 1) with the server's words, not after --timeout; what arrived is kept."""
    serve = tmp_path / "serve"
    src = write(serve / "log.bin", SIZE, 3)
    port = free_port()
    spec = f"udpin:{LOCAL}:{port}"
    server = receiver(start, tmp_path, spec, "--serve", str(serve), "--rate", RATE, name="server0")
    began = time.monotonic()
    f = fetch(start, tmp_path, port)
    wait_partial(tmp_path / "got", SIZE // 3, f)
    server.kill()
    src.unlink()
    receiver(start, tmp_path, spec, "--serve", str(serve), "--rate", RATE, name="server1")
    assert f.wait(TIMEOUT) == 1, f.stderr
    assert time.monotonic() - began < TIMEOUT - 5, f.stderr
    assert one_line(f.stderr).startswith("ttctl: error: not found at 1/240: there is no log.bin in the served folder"
                                         " (what arrived is kept in "), f.stderr
    r = json.loads(f.stdout)
    assert r["code"] == "NOT_FOUND" and not r["ok"], r
    assert partial_bytes(tmp_path / "got") >= SIZE // 3


def test_resumed_bytes_of_an_upload_is_what_the_receiver_had(tmp_path: Path, start: Start) -> None:
    """An upload interrupted (sender and receiver killed), then sent again to the restarted
    receiver: resumed_bytes is exactly what the receiver's partial file held."""
    src = write(tmp_path / "up.bin", SIZE, 5)
    inbox = tmp_path / "inbox"
    port = free_port()
    spec = f"udpin:{LOCAL}:{port}"
    rx = receiver(start, tmp_path, spec, "--rate", RATE, name="rx0")
    s = start("send0", "send-file", str(src), "--to", f"udpout:{LOCAL}:{port}", "--rate", RATE, "--json")
    wait_partial(inbox, SIZE // 3, s)
    s.kill()
    rx.kill()
    had = partial_bytes(inbox)
    assert 0 < had < SIZE
    receiver(start, tmp_path, spec, "--rate", RATE, name="rx1")
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{port}", "--rate", RATE, "--timeout", "20", timeout=60)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(inbox / "up.bin") == sha(src)
    assert r["resumed_bytes"] == had, (r, had)
    assert r["restarts"] == 0


def test_resumed_bytes_of_an_upload_counts_every_region_of_a_gappy_partial(tmp_path: Path, start: Start) -> None:
    """The receiver's partial file has more gaps than one status holds (a lossy link leaves
    them): its first answer is a burst of statuses, region by region. resumed_bytes counts what
    all of them say the receiver had (it counted the first region only: a fraction of it)."""
    src = write(tmp_path / "up.bin", SIZE, 6)
    inbox = tmp_path / "inbox"
    port = free_port()
    spec = f"udpin:{LOCAL}:{port}"
    rx = receiver(start, tmp_path, spec, "--rate", RATE, name="rx0")
    s = start("send0", "send-file", str(src), "--to", f"udpout:{LOCAL}:{port}", "--rate", RATE, "--json")
    wait_partial(inbox, SIZE // 2, s)
    s.kill()
    rx.kill()
    (record,) = (inbox / ".ttctl-partial").glob("*.json")
    state = json.loads(record.read_text())
    held = [tuple(r) for r in state["ranges"]]
    assert held[0][0] == 0
    end = held[0][1]
    holes = [(k * 1200 + 100, k * 1200 + 164) for k in range(24) if k * 1200 + 164 < end]
    assert len(holes) == 24, held
    pieces, pos = [], 0
    for a, b in holes:
        pieces.append([pos, a])
        pos = b
    state["ranges"] = [*pieces, [pos, end], *[list(r) for r in held[1:]]]
    record.write_text(json.dumps(state))
    had = partial_bytes(inbox)
    receiver(start, tmp_path, spec, "--rate", RATE, name="rx1")
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{port}", "--rate", RATE, "--timeout", "20", timeout=60)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(inbox / "up.bin") == sha(src)
    assert r["resumed_bytes"] == had, (r, had)


@pytest.mark.parametrize("as_json", [True, False])
def test_resumed_bytes_of_a_fetch_is_what_was_here(tmp_path: Path, start: Start, as_json: bool) -> None:
    """A fetch interrupted (it and its server killed), then run again: resumed_bytes is exactly
    what its partial file held, and the summary line says so."""
    serve = tmp_path / "serve"
    src = write(serve / "log.bin", SIZE, 7)
    port = free_port()
    spec = f"udpin:{LOCAL}:{port}"
    server = receiver(start, tmp_path, spec, "--serve", str(serve), "--rate", RATE, name="server0")
    f = fetch(start, tmp_path, port)
    wait_partial(tmp_path / "got", SIZE // 3, f)
    f.kill()
    server.kill()
    had = partial_bytes(tmp_path / "got")
    assert 0 < had < SIZE
    receiver(start, tmp_path, spec, "--serve", str(serve), "--rate", RATE, name="server1")
    args = ("log.bin", "--from", f"udpout:{LOCAL}:{port}", "--dir", str(tmp_path / "got"), "--rate", RATE,
            "--timeout", "20")
    if as_json:
        proc, r = send(*args, timeout=60)
        assert proc.returncode == 0 and r["ok"], proc.stderr
        assert r["resumed_bytes"] == had and r["server_restarts"] == 0, (r, had)
    else:
        proc = run_ttctl("send-file", *args, timeout=60)
        assert proc.returncode == 0, proc.stderr
        line = one_line(proc.stdout)
        assert line.startswith("received log.bin from 1/240") and f"resumed: {had} bytes were already here" in line
        assert "restarted" not in line
    assert sha(tmp_path / "got" / "log.bin") == sha(src)


def test_a_server_that_never_comes_back_times_out_in_words(tmp_path: Path, start: Start) -> None:
    """The server is killed for good: the fetch asks again while it waits, and after --timeout
    without progress ends (exit 1) saying the server went quiet and did not answer its requests."""
    serve = tmp_path / "serve"
    write(serve / "log.bin", SIZE, 4)
    port = free_port()
    server = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--serve", str(serve), "--rate", RATE)
    got = tmp_path / "got"
    got.mkdir()
    f = start("fetch", "send-file", "log.bin", "--from", f"udpout:{LOCAL}:{port}", "--dir", str(got), "--rate", RATE,
              "--timeout", "6")
    wait_partial(got, SIZE // 3, f)
    server.kill()
    t0 = time.monotonic()
    assert f.wait(30) == 1, f.stderr
    assert 5.0 <= time.monotonic() - t0 < 20, f.stderr
    line = one_line(f.stderr)
    assert line.startswith("ttctl: error: timed out: no progress for 6 s (1/240 went quiet and did not answer "), line
    assert "requests since) (what arrived is kept in " in line, line
