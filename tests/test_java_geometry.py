"""The Java runtime's file-data frames follow the link's packet size (issue 26, /work/notes/geometry.md
as the lead decided it): a LinkScheduler takes its packet size from the Link (Link.mtu()), and
FileTransfers size their data frames to it: TT_FILE_DATA 80/100 on an unsigned 100-byte link as
before, TT_FILE_DATA_FIT filling the packet otherwise (107 bytes at 128, 66 at 100 signed, 94 at
128 signed), TT_FILE_DATA_WIDE across packets. Java to Java over an in-memory link of those packets
with seeded loss (tests/java/geometry/GeometryCheck.java): every file arrives whole, no packet is
over the link's size, and the receiver sees the frames the geometry says. And a cross run: the
Java sender (GeometrySender.java) and `ttctl send-file` put the same data frames on 128-byte and
signed links (ttctl's Python Geometry is the reference).
"""

from __future__ import annotations

import random
import re
import shutil
import socket
import subprocess
import threading
from pathlib import Path

import pytest

from conformance_lib import build_java
from conftest import ROOT, run_ttctl, shipped
from e2e_lib import LOCAL, Start, free_port

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

# mtu:signed:mode:loss -> (narrow kind, its largest count: what a full frame carries)
CASES = {
    "100:0:narrow:0.05": ("data", 0),
    "128:0:narrow:0.05": ("fit", 107),
    "100:1:narrow:0.05": ("fit", 66),
    "128:1:narrow:0.05": ("fit", 94),
    "128:0:wide:0.05": ("wide", 0),
    # no loss: after its probe frames the sender goes wide (247/280 = 0.88 of the link against 94/128)
    "128:1:auto:0": ("auto", 94),
}


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    cls, _ = build_java(tmp_path_factory.mktemp("java_geometry"), sorted((ROOT / "tests/java/geometry").glob("*.java")))
    return cls


def test_frames_follow_the_link_packet(classes: Path, tmp_path: Path) -> None:
    proc = subprocess.run(["java", "-cp", str(classes), "GeometryCheck", str(tmp_path), *CASES],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    lines = [ln for ln in proc.stdout.splitlines() if ln.startswith("CASE ")]
    assert len(lines) == len(CASES), proc.stdout + proc.stderr
    for case, line in zip(CASES, lines, strict=True):
        got = dict(re.findall(r"(\w+)=(\S+)", line))
        kind, cap = CASES[case]
        assert got["ok"] == "true" and got["sha"] == "1", (case, line)
        assert got["oversize"] == "0", (case, line)  # no packet over the link's size
        if kind == "auto":
            assert got["data"] == "0" and int(got["fit"]) > 0 and int(got["wide"]) > 0, (case, line)
            assert int(got["fitmax"]) == cap, (case, line)
            continue
        others = {"data", "fit", "wide"} - {kind}
        assert int(got[kind]) > 0 and all(got[o] == "0" for o in others), (case, line)
        if kind == "fit":
            assert int(got["fitmax"]) == cap, (case, line)


def test_the_java_geometry_is_pythons_for_every_packet_size(classes: Path) -> None:
    """Shared vectors: for every packet size from 13 to 300 bytes, signed or not, the Java
    Geometry refuses what Python's refuses, and chooses the same narrow frame (TT_FILE_DATA or
    TT_FILE_DATA_FIT), its capacity and length, the wide frame's length, its survival under loss
    and the packet loss inferred from a wide-frame loss."""
    from ttctl.proto.transfer import Geometry

    proc = subprocess.run(["java", "-cp", str(classes), "ttctl.ttapi.transfer.GeometryVectors"], capture_output=True,
                          text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert len(lines) == 2 * (300 - 13 + 1)
    ps = [0.0, 0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.9]
    xs = [0.001, 0.05, 0.1, 0.3, 0.6, 0.95]
    for ln in lines:
        w = ln.split()
        mtu, signed = int(w[1]), w[2] == "1"
        try:
            g = Geometry(mtu, signed)
        except ValueError:
            assert w[0] == "REFUSED", ln
            continue
        assert w[0] == "G", ln
        assert (w[3] == "1", int(w[4]), int(w[5]), int(w[6])) == (g.narrow_fit, g.narrow_cap, g.narrow_frame,
                                                                 g.wide_frame), ln
        surv, loss = " ".join(w[7:]).split(" | ")
        assert [float(v) for v in surv.split()] == pytest.approx([g.survival_wide(p) for p in ps], rel=1e-12), ln
        assert [float(v) for v in loss.split()] == pytest.approx([g.packet_loss_from_wide(x) for x in xs],
                                                                 rel=1e-9, abs=1e-11), ln


# --- the Java sender's frames are Python's: a cross run on mtu 128 and signed links -------------

class Tap:
    """A UDP relay in the test (no loss): datagrams to `port` go to the receiver at `to` and its
    answers come back; every datagram up is kept."""

    def __init__(self, to: int) -> None:
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind((LOCAL, 0))
        self.sock.settimeout(0.2)
        self.port = self.sock.getsockname()[1]
        self.to = (LOCAL, to)
        self.up: list[bytes] = []
        self.sender: tuple[str, int] | None = None
        self.stop = threading.Event()
        self.t = threading.Thread(target=self.run, daemon=True)
        self.t.start()

    def run(self) -> None:
        while not self.stop.is_set():
            try:
                data, addr = self.sock.recvfrom(65536)
            except TimeoutError:
                continue
            if addr == self.to:
                if self.sender is not None:
                    self.sock.sendto(data, self.sender)
            else:
                self.sender = addr
                self.up.append(data)
                self.sock.sendto(data, self.to)

    def close(self) -> None:
        self.stop.set()
        self.t.join(2)
        self.sock.close()


def data_frames(packets: list[bytes]) -> dict[tuple[str, int], bytes]:
    """(message, offset) -> the frame's payload after the transfer id (offset, count, data), as
    first sent; the packets' sizes are checked by the caller."""
    b = shipped()
    parser = b.parser()
    out: dict[tuple[str, int], bytes] = {}
    for p in packets:
        for m in parser.feed(p):
            if m.NAME in ("TT_FILE_DATA", "TT_FILE_DATA_WIDE", "TT_FILE_DATA_FIT"):
                raw = bytes(m.pack_payload())
                out.setdefault((m.NAME, m.offset), raw[4:])
    return out


@pytest.mark.parametrize(("profile", "mtu", "signed", "narrow", "cap"), [
    ("psdk", 128, False, "TT_FILE_DATA_FIT", 107),
    ("psdk", 128, True, "TT_FILE_DATA_FIT", 94),
    ("m100", 100, True, "TT_FILE_DATA_FIT", 66),
])
def test_the_java_senders_frames_are_pythons(classes: Path, tmp_path: Path, start: Start, profile: str, mtu: int,
                                             signed: bool, narrow: str, cap: int) -> None:
    """The same file sent by the Java runtime (FileTransfers on a UdpLink of `mtu`-byte packets)
    and by `ttctl send-file --profile P` to `ttctl recv-file --profile P`, signed or not: the
    same narrow frame kind, carrying the same bytes at the same offsets (its count stated), the
    same wide frames where both sent them, no packet over the link's size, both files whole."""
    key = tmp_path / "key"
    key.write_text("ab" * 32)
    keyed = ["--key", str(key)] if signed else []
    src = tmp_path / "same.bin"
    src.write_bytes(random.Random(mtu + signed).randbytes(9000))
    runs: dict[str, dict[tuple[str, int], bytes]] = {}
    for who in ("java", "python"):
        port = free_port()
        inbox = tmp_path / f"inbox-{who}"
        recv = start(f"recv-{who}", "recv-file", "--listen", f"udpin:{LOCAL}:{port}", "--dir", str(inbox),
                     "--profile", profile, *keyed)
        recv.wait_for("receiving into")
        tap = Tap(port)
        try:
            if who == "java":
                proc = subprocess.run(["java", "-cp", str(classes), "GeometrySender", str(tap.port), str(mtu),
                                       "ab" * 32 if signed else "-", "20000", str(src)], capture_output=True,
                                      text=True, timeout=180)
                assert proc.returncode == 0 and "RESULT ok=true" in proc.stdout, proc.stdout + proc.stderr
            else:
                proc = run_ttctl("send-file", str(src), "--to", f"udpout:{LOCAL}:{tap.port}", "--profile", profile,
                                 "--rate", "20000", "--no-compress", *keyed, "--json", timeout=180)
                assert proc.returncode == 0, proc.stderr
        finally:
            tap.close()
        assert (inbox / "same.bin").read_bytes() == src.read_bytes(), who
        assert max(map(len, tap.up)) <= mtu, (who, max(map(len, tap.up)))
        runs[who] = data_frames(tap.up)
    java, py = runs["java"], runs["python"]
    kinds = {k for k, _ in java} | {k for k, _ in py}
    assert kinds <= {narrow, "TT_FILE_DATA_WIDE"}, kinds
    for run in (java, py):  # both begin with the narrow frame (the probe), the packet's worth each
        firsts = sorted(o for k, o in run if k == narrow)
        assert firsts[:3] == [0, cap, 2 * cap], firsts[:3]
    common = set(java) & set(py)
    assert sum(k == narrow for k, _ in common) >= 3, sorted(common)[:5]
    for k in common:
        assert java[k] == py[k], k  # offset, count, bytes: the same frame but for the transfer id
