"""Rate grants in the generated Java runtime, against real ttctl processes on 127.0.0.1: several
transfers share one link through `ttctl link relay --profile m100` at 10 % loss.

- The Java sender (tests/java/transfer/TabletDriver.java) and two `ttctl send-file` processes
  upload equal files at once to `ttctl recv-file`, which grants each an equal share of its
  inbound capacity in every TT_FILE_STATUS (rate_grant): every file arrives verified, the Java
  upload takes about as long as the Python ones, and the relay's SDK buffer hardly ever
  overflows (a Java sender pacing to the full link rate instead overflows it hundreds of times).
- Three `ttctl send-file` processes push files at once to the Java inbox
  (tests/java/session/SessionDriver.java, FileTransfers.setInboundCapacity): it grants them
  equal shares, so that they finish together and the buffer hardly overflows.
- The arithmetic (shares, the sharing window, a sender's pace) is the Python reference's,
  number for number (tests/java/grants/GrantCheck.java).

The relay and every end are given the same --rate (the m100 profile's loss, buffer and latency
at a faster rate, so that the test takes seconds, not minutes).
"""

from __future__ import annotations

import hashlib
import json
import random
import re
import shutil
import signal
import subprocess
from pathlib import Path
from typing import Any

import pytest

from conformance_lib import build_java
from conftest import ROOT
from e2e_lib import LOCAL, Proc, Start, free_port, receiver, relay
from test_java_session import DRIVERS as SESSION_DRIVERS
from test_java_session import _ttctl, stop, tablet_inbox
from test_java_transfer import DRIVERS as TABLET_DRIVERS
from test_java_transfer import Driver

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

GRANT_CHECK = ROOT / "tests" / "java" / "grants" / "GrantCheck.java"
RATE = 4000  # B/s: the relay's, and every end's pace and inbound capacity
SIZE = 24 * 1024  # each file: 3 of them share the link for about 25 s
# Of the packets offered to the relay, at most this share may find its 2-packet buffer full.
# Three senders sharing 95 % of the link at equal pace still collide now and then (the phases of
# their frames drift): 0 to 6 % measured on a busy machine, with a Python or the Java
# receiver; a sender without a grant beside two with one: 23 %; three without grants: 62 %.
OVERFLOW = 0.1


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    cls, _ = build_java(tmp_path_factory.mktemp("java_grants"),
                        [*SESSION_DRIVERS, *sorted(TABLET_DRIVERS.glob("*.java")), GRANT_CHECK])
    return cls


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def files(tmp: Path, *names: str) -> list[Path]:
    out = []
    for i, n in enumerate(names):
        p = tmp / n
        p.write_bytes(random.Random(200 + i).randbytes(SIZE))
        out.append(p)
    return out


def send_file(path: Path, port: int, *extra: str) -> subprocess.Popen[str]:
    return subprocess.Popen([*_ttctl(), "send-file", str(path), "--to", f"udpout:{LOCAL}:{port}", "--rate",
                             str(RATE), "--timeout", "30", "--json", *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def finish(p: subprocess.Popen[str], timeout: float = 150) -> dict[str, Any]:
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        p.kill()
        out, err = p.communicate()
        raise AssertionError(f"send-file hung:\n{err[-3000:]}") from None
    assert "Traceback" not in err, err
    report: dict[str, Any] = json.loads(out) if out.strip() else {}
    assert p.returncode == 0 and report.get("ok"), err[-3000:]
    return report


def uplink(rly: Proc) -> dict[str, int]:
    """The relay's last stats line (on SIGTERM), its uplink part: packets in, out, lost, overflowed."""
    rly.signal(signal.SIGTERM)
    rly.wait(15)
    lines = [ln for ln in rly.stderr.splitlines() if ln.startswith("relay ") and " s: up " in ln]
    assert lines, rly.stderr
    up = lines[-1].split(" s: up ", 1)[1].split(" | ")[0]
    got = {"in": int(up.split(" in,")[0]), "out": int(re.search(r"(\d+) out", up)[1]),  # type: ignore[index]
           "lost": int(re.search(r"(\d+) lost", up)[1])}  # type: ignore[index]
    m = re.search(r"overflow (\d+)", up)
    got["overflow"] = int(m[1]) if m else 0
    return got


def test_the_java_sender_paces_to_its_grant(classes: Path, tmp_path: Path, start: Start) -> None:
    """Java and two `ttctl send-file` upload 24 KiB each at once through the relay (m100 at
    4000 B/s, 10 % loss) to `ttctl recv-file --rate 4000`, which grants each 1266 B/s: all three
    files arrive verified, the Java upload's time is within 1.5x of each Python one's, and the
    relay's buffer overflowed for at most a tenth of the packets offered to it (6 of 1043). Without the Java
    sender following its grant, it sends at the link's rate on top of the other two: the buffer
    overflowed for 303 of 1343 packets, and the Java upload took 12.6 s, the others 26.5 s."""
    a, b = free_port(), free_port()
    receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--rate", str(RATE))
    rly = relay(start, a, b, "--profile", "m100", "--rate", str(RATE), "--loss", "0.1", "--seed", "41",
                "--stats-interval", "0")
    java_file, py1, py2 = files(tmp_path, "java.bin", "python1.bin", "python2.bin")
    d = Driver(classes, tmp_path, "java", link="udp", port=a, rate=RATE, timeout=30, send=java_file.name)
    senders = [send_file(py1, a), send_file(py2, a)]
    try:
        r = d.finish(150)
        py = [finish(p) for p in senders]
    finally:
        for p in senders:
            if p.poll() is None:
                p.kill()
    up = uplink(rly)
    assert r["send_ok"], r["_text"][-3000:]
    for f in (java_file, py1, py2):
        assert sha(tmp_path / "inbox" / f.name) == sha(f)
    assert r["app_thread_errors"] == 0 and r["uncaught"] == 0 and r["scheduler_errors"] == 0
    grant = int(RATE * 0.95 / 3)
    report = {"java_seconds": round(r["send_seconds"], 2), "python_seconds": [p["seconds"] for p in py],
              "java_data_Bps": round(r["send_sent"] / r["send_seconds"]), "grant_Bps": grant,
              "uplink": up}
    print("MEASURED", json.dumps(report))
    for p in py:
        assert r["send_seconds"] <= 1.5 * p["seconds"] and p["seconds"] <= 1.5 * r["send_seconds"], report
    assert up["overflow"] <= OVERFLOW * up["in"], report
    # the file bytes it put in data frames (repeats included) over its whole upload: about its
    # share (less the frames' headers; a lone transfer at the very start and end goes at the
    # link's rate, hence the room), not the link's rate (3200 B/s of file bytes)
    assert r["send_sent"] / r["send_seconds"] <= 1.5 * grant, report


def test_the_java_receiver_grants_equal_shares(classes: Path, tmp_path: Path, start: Start) -> None:
    """Three `ttctl send-file` push 24 KiB each at once through the relay (m100 at 4000 B/s,
    10 % loss) into the Java inbox, whose inbound capacity is 4000 B/s: all arrive verified,
    the slowest takes at most 1.5x the fastest's time, and the relay's buffer overflowed for at
    most a tenth of the packets offered to it (15 to 39 of about 1100 in four runs, 74 in a
    fifth on a busy machine). With no grants (inbound capacity 0) the three, each
    at the full link rate, offered it 2800 packets and 1749 of them overflowed it."""
    (tmp_path / "outbox").mkdir()
    a, b = free_port(), free_port()
    rly = relay(start, a, b, "--profile", "m100", "--rate", str(RATE), "--loss", "0.1", "--seed", "43",
                "--stats-interval", "0")
    j = tablet_inbox(classes, tmp_path, "tablet", b, rate=RATE, inbound=RATE, timeout=30, secs=150)
    pushed = files(tmp_path, "push1.bin", "push2.bin", "push3.bin")
    drone = ("--sysid", "1", "--compid", "240", "--target-sysid", "255", "--target-compid", "190")
    senders = [send_file(f, a, *drone) for f in pushed]
    try:
        reports = [finish(p) for p in senders]
    finally:
        for p in senders:
            if p.poll() is None:
                p.kill()
    r = stop(j, tmp_path)
    up = uplink(rly)
    for f in pushed:
        assert sha(tmp_path / "inbox" / f.name) == sha(f)
    results = [json.loads(x) if isinstance(x, str) else x for x in r["results"]]
    assert sorted(x["name"] for x in results if x["ok"]) == [f.name for f in pushed], results
    secs = [p["seconds"] for p in reports]
    report = {"seconds": secs, "efficiency": [p["efficiency"] for p in reports], "uplink": up}
    print("MEASURED", json.dumps(report))
    assert max(secs) <= 1.5 * min(secs), report
    assert up["overflow"] <= OVERFLOW * up["in"], report


def test_the_java_arithmetic_is_pythons(classes: Path) -> None:
    """Sharing's numbers in the Java runtime are ttctl's Python proto/sharing.py's, on the same
    inputs (tests/java/grants/GrantCheck.java): each transfer's share of a capacity among n
    (0 alone or with no capacity, never 0 otherwise, at most 65535), how long a quiet transfer
    stays in the sharing set under a grant, and when a sender's frames may leave under its grant
    (no credit saved up, none kept when the grant goes)."""
    from ttctl.proto.sharing import ACTIVE_WINDOW, GrantPacer, share

    proc = subprocess.run(["java", "-cp", str(classes), "ttctl.ttapi.transfer.GrantCheck"], capture_output=True,
                          text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    got = json.loads(proc.stdout)
    assert len(got["share"]) == 110 and any(g == 65535 for _, _, g in got["share"])
    for capacity, n, g in got["share"]:
        assert g == share(capacity, n), (capacity, n, g)
    for g, w in got["window"]:
        assert w == pytest.approx(max(ACTIVE_WINDOW, 4.0 * 100 / g) if g else ACTIVE_WINDOW, abs=1e-9), (g, w)
    frames = [(0, 0.0, 100), (1266, 0.0, 100), (1266, 0.01, 100), (1266, 0.08, 100), (1266, 0.5, 267),
              (1266, 0.6, 100), (1900, 0.7, 100), (0, 0.71, 100), (0, 0.72, 100), (633, 0.73, 267), (633, 5.0, 100)]
    pacer = GrantPacer()
    want = []
    for grant, now, n in frames:
        pacer.update(grant)
        ready = pacer.ready(now)
        if ready:
            pacer.sent(now, n)
        want.append((ready, pacer.ready_at()))
    assert [r for r, _ in want] == [r for r, _ in got["pace"]], (want, got["pace"])
    for (_, a), (_, b) in zip(want, got["pace"], strict=True):
        assert (a is None and b is None) or a == pytest.approx(b, abs=1e-9), (want, got["pace"])
    assert [r for r, _ in want].count(False) >= 2  # the grant held some frames back
