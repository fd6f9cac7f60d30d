"""The Java tablet's ground-station bridge carries the user's dialect (issue 28), real processes:

    pymavlink stations (robolab.xml, by mavgen; 200/190, and 255/190: the tablet's own ids) <->
    [RobolabBridge: the robolab runtime's Session + GcsBridge] <-> link relay --profile m100
    --loss 0.1 <-> the vehicle: `emulate onboard --dialect robolab.xml --plugin motors.py`, or
    the C++ node built from robolab's generated skeleton, its KR_MOTOR_CONTROL handler filled in

Each station sends KR_MOTOR_CONTROL (10 seqs of its own) until its KR_MOTOR_STATUS comes: every
answer reaches the station that asked and no other (the plugin, or the C++ handler, answers
from the onboard end's component, addressed by target_system = the frame's sysid; the bridge
gives the clashing station its id back); the autopilot's HEARTBEAT, for every station, reaches
both. A frame of a message the dialect lacks is carried as
mavlink-router carries it: the Python vehicle names it."""

from __future__ import annotations

import importlib.util
import shutil
import socket
import subprocess
import sys
import time
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from conftest import DIALECTS, ROOT, pymavlink_dialects, run_ttctl
from e2e_lib import LOCAL, Start, free_port, relay
from machine import scaled

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

ROBOLAB = DIALECTS / "examples" / "robolab.xml"
MOTORS = DIALECTS / "examples" / "motors.py"
UNKNOWN_MSGID = 52123


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    base = tmp_path_factory.mktemp("java_bridge_dialect")
    gen = run_ttctl("gen", str(ROBOLAB), "--lang", "java", "-o", str(base / "gen"), timeout=300)
    assert gen.returncode == 0, gen.stderr
    sources = sorted(str(p) for p in (base / "gen" / "java").rglob("*.java"))
    sources.append(str(ROOT / "tests" / "java" / "own" / "RobolabBridge.java"))
    javac = subprocess.run(["javac", "--release", "11", "-Xlint:all", "-Werror", "-encoding", "UTF-8", "-d",
                            str(base / "classes"), *sources], capture_output=True, text=True, timeout=600)
    assert javac.returncode == 0, javac.stderr[-4000:]
    return base / "classes"


@pytest.fixture(scope="module")
def pm(tmp_path_factory: pytest.TempPathFactory) -> ModuleType:
    """pymavlink's own Python for robolab.xml (mavgen on a copy beside ttapi.xml and common.xml)."""
    stage = tmp_path_factory.mktemp("pm_robolab")
    for xml in pymavlink_dialects().glob("*.xml"):
        shutil.copy(xml, stage)
    shutil.copy(DIALECTS / "ttapi.xml", stage)
    shutil.copy(ROBOLAB, stage)
    out = stage / "pm_robolab.py"
    proc = subprocess.run([sys.executable, "-m", "pymavlink.tools.mavgen", "--lang", "Python3", "--wire-protocol",
                           "2.0", "-o", str(out), str(stage / "robolab.xml")], capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    spec = importlib.util.spec_from_file_location("pm_robolab", out)
    assert spec and spec.loader
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


HANDLER = """        KrMotorStatus st;  // the answer, to the system that asked (a ground station behind the tablet too)
        st.target_system = frame.sysid;
        st.seq = msg.seq;
        st.dir = msg.dir;
        st.speed = msg.speed;
        st.rpm = static_cast<float>(msg.speed) * 12.5F;
        st.note[0] = 'o';
        st.note[1] = 'k';
        ctx.send(st);
"""

LAPTOP = """#include <atomic>
#include <cstdio>

#include "onboard/robolab_plugin.hpp"
#include "robolab/udp_link.hpp"

int main()
{
    robolab::link::NodeConfig cfg;
    robolab::link::Node node(cfg);
    robolab::onboard::RobolabPlugin plugin;
    node.add(plugin);
    robolab::link::Words why;
    robolab::link::UdpLink udp(node);
    if (!node.start(why) || !udp.open("udpin:127.0.0.1:PORT", why)) {
        std::fprintf(stderr, "%s\\n", why.c_str());
        return 1;
    }
    std::atomic<bool> stop{false};
    udp.run(stop);
}
"""


@pytest.fixture(scope="module")
def cpp_node(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """robolab.xml's C++ tree, the skeleton's KR_MOTOR_CONTROL handler answering (the program is
    built per test: its port is in its source, as in the README's)."""
    if shutil.which("g++") is None:
        pytest.skip("needs g++")
    base = tmp_path_factory.mktemp("cpp_robolab")
    gen = run_ttctl("gen", str(ROBOLAB), "--lang", "cpp", "-o", str(base / "gen"), timeout=300)
    assert gen.returncode == 0, gen.stderr
    skeleton = base / "gen" / "cpp" / "onboard" / "robolab_plugin.hpp"
    todo = ("        // TODO: handle KR_MOTOR_CONTROL (from system frame.sysid, component frame.compid); "
            "ctx.send(...) replies\n")
    text = skeleton.read_text()
    assert todo in text
    skeleton.write_text(text.replace(todo, HANDLER))
    return base


def start_cpp(base: Path, port: int, tmp: Path) -> subprocess.Popen[bytes]:
    src = tmp / "laptop.cpp"
    src.write_text(LAPTOP.replace("PORT", str(port)))
    exe = tmp / "laptop"
    gxx = subprocess.run(["g++", "-std=c++17", "-Wall", "-Wextra", "-Werror", "-O0", "-I", str(base / "gen" / "cpp"),
                          str(src), "-o", str(exe), "-lz"], capture_output=True, text=True, timeout=600)
    assert gxx.returncode == 0, gxx.stderr[-4000:]
    return subprocess.Popen([str(exe)], cwd=tmp, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


class Station:
    """A pymavlink ground station speaking robolab, sending to the bridge's port."""

    def __init__(self, pm: ModuleType, port: int, sysid: int, compid: int = 190) -> None:
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind((LOCAL, 0))
        self.sock.setblocking(False)
        self.to = (LOCAL, port)
        sock, to = self.sock, self.to

        class Out:
            def write(self, b: bytes) -> None:
                sock.sendto(b, to)

        self.mav = pm.MAVLink(Out(), srcSystem=sysid, srcComponent=compid)
        self.statuses: dict[int, Any] = {}
        self.heartbeats: set[tuple[int, int]] = set()  # the sources of the HEARTBEATs heard

    def poll(self) -> None:
        while True:
            try:
                data = self.sock.recv(65536)
            except BlockingIOError:
                return
            for m in self.mav.parse_buffer(data) or []:
                if m.get_type() == "KR_MOTOR_STATUS":
                    self.statuses[m.seq] = m
                elif m.get_type() == "HEARTBEAT":
                    self.heartbeats.add((m.get_srcSystem(), m.get_srcComponent()))

    def ask(self, seq: int) -> None:
        self.mav.heartbeat_send(6, 8, 0, 0, 0)  # MAV_TYPE_GCS, MAV_AUTOPILOT_INVALID
        self.mav.kr_motor_control_send(1, seq, 1, 30)

    def unknown(self) -> None:
        """A frame of msgid UNKNOWN_MSGID (no dialect here has it), CRC_EXTRA 0."""
        payload = bytes([1, 2, 3, 4])
        head = bytes([len(payload), 0, 0, 7, self.mav.srcSystem, self.mav.srcComponent, UNKNOWN_MSGID & 0xFF,
                      UNKNOWN_MSGID >> 8 & 0xFF, UNKNOWN_MSGID >> 16])
        from pymavlink.generator.mavcrc import x25crc

        crc = x25crc(head + payload)
        crc.accumulate(bytes([0]))
        self.sock.sendto(b"\xfd" + head + payload + crc.crc.to_bytes(2, "little"), self.to)


@pytest.mark.parametrize("vehicle", ["python", "cpp"])
def test_java_bridge_carries_the_users_dialect_to_its_stations(classes: Path, pm: ModuleType, tmp_path: Path,
                                                                start: Start, vehicle: str,
                                                                request: pytest.FixtureRequest) -> None:
    port, front, listen = free_port(), free_port(), free_port()
    cpp: subprocess.Popen[bytes] | None = None
    if vehicle == "python":
        node = start("onboard", "emulate", "onboard", "--dialect", str(ROBOLAB), "--plugin", str(MOTORS), "--listen",
                     f"udpin:{LOCAL}:{port}", "--no-gcs", "--no-entry-points", "--profile", "m100")
        node.wait_for("onboard 1:", timeout=60)  # type: ignore[attr-defined]
    else:
        cpp = start_cpp(request.getfixturevalue("cpp_node"), port, tmp_path)
    relay(start, front, port, "--profile", "m100", "--loss", "0.1", "--seed", "3", "--dialect", str(ROBOLAB),
          "--stats-interval", "0")
    out = open(tmp_path / "bridge.out", "w")  # noqa: SIM115 - closed below
    java = subprocess.Popen(["java", "-cp", str(classes), "RobolabBridge", str(front), str(listen), "500"],
                            stdin=subprocess.PIPE, stdout=out, stderr=subprocess.STDOUT, text=True)
    try:
        end = time.monotonic() + scaled(20)
        while "ready" not in (tmp_path / "bridge.out").read_text() and time.monotonic() < end:
            time.sleep(0.05)
        a, b = Station(pm, listen, 200), Station(pm, listen, 255)  # b: the tablet's own ids (QGroundControl's)
        if vehicle == "python":
            a.unknown()
        want = {a: list(range(100, 110)), b: list(range(200, 210))}
        asked: dict[tuple[int, int], float] = {}
        end = time.monotonic() + scaled(50)
        while time.monotonic() < end and any(s not in st.statuses for st, seqs in want.items() for s in seqs):
            now = time.monotonic()
            for st, seqs in want.items():
                st.poll()
                pending = [s for s in seqs if s not in st.statuses]
                for s in pending[:2]:  # two outstanding each, resent every 1.5 s
                    if now - asked.get((id(st), s), -9.0) > 1.5:
                        asked[(id(st), s)] = now
                        st.ask(s)
            time.sleep(0.02)
        assert sorted(a.statuses) == want[a] and sorted(b.statuses) == want[b], (sorted(a.statuses),
                                                                                 sorted(b.statuses))
        assert all(m.target_system == 200 for m in a.statuses.values())
        assert all(m.target_system == 255 and m.rpm == 375.0 for m in b.statuses.values())
        if vehicle == "python":  # its autopilot's HEARTBEAT is for every station: both have it
            assert (1, 1) in a.heartbeats and (1, 1) in b.heartbeats, (a.heartbeats, b.heartbeats)
            node.wait_for(f"sends msgid {UNKNOWN_MSGID}", timeout=10)  # type: ignore[attr-defined]
            assert "200/190 at" in node.stderr and "which dialect robolab does not have" in node.stderr  # type: ignore
        assert java.stdin is not None
        java.stdin.write("stats\n")
        java.stdin.close()
        java.wait(20)
    finally:
        if java.poll() is None:
            java.kill()
            java.wait(10)
        if cpp is not None:
            cpp.kill()
            cpp.wait(10)
        out.close()
    text = (tmp_path / "bridge.out").read_text()
    assert "closed" in text and f"unknownCarried {1 if vehicle == 'python' else 0}" in text, text
