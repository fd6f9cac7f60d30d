"""Ground stations that speak MAVLink 1 (pymavlink's default: magic 0xFE) through the Java
runtime's GcsBridge (issue 26): their frames are carried as MAVLink 2 (the same msgid and
payload, the CRC recomputed with CRC_EXTRA) and they are answered in MAVLink 1 when the answer
fits (msgid < 256, the payload cut to MAVLink 1's fields); what does not is counted and named in
one onProblem line. The MAVLink 1 codec is pymavlink's own (pymavlink.dialects.v10, used
directly whatever MAVLINK20 other tests set), and the Java codec is held to ttctl's Python one
(wire/v1.py) byte for byte.

- sans-IO: tests/java/gcs/V1Check.java against ttctl.wire.v1 on pymavlink's frames, mixed with
  MAVLink 2 and garbage, a bad CRC, an id the dialect lacks;
- a bridge on a recording link (tests/java/gcs/V1BridgeCheck.java) and a MAVLink 1 station;
- end to end: pymavlink in MAVLink 1 <-> BridgeDriver (Session + GcsBridge) <-> `ttctl link relay
  --profile m100` <-> `ttctl emulate onboard`: a heartbeat, an arm command acknowledged in
  MAVLink 1, a parameter read.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import threading
import time
from pathlib import Path

import pytest
from pymavlink.dialects.v10 import common as v1

from conformance_lib import build_java
from conftest import ROOT
from e2e_lib import LOCAL, Start, free_port, relay
from machine import scaled
from ttctl.bench import shipped
from ttctl.wire.v1 import Upgrader, downgrade
from v1_station import V1Station

pytestmark = pytest.mark.skipif(not (shutil.which("javac") and shutil.which("java")),
                                reason="needs a JDK (javac, java)")

GCS = ROOT / "tests" / "java" / "gcs"


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    drivers = [GCS / "V1Check.java", GCS / "V1BridgeCheck.java", GCS / "BridgeDriver.java"]
    cls, _ = build_java(tmp_path_factory.mktemp("gcs_v1"), drivers)
    return cls


def _unknown_v1_id() -> int:
    b = shipped.bindings()
    return next(i for i in range(256) if b.registry.get(i) is None)


def test_the_java_mavlink1_codec_is_the_python_one(classes: Path) -> None:
    b = shipped.bindings()
    mav = v1.MAVLink(None, srcSystem=255, srcComponent=190)
    frames = [bytes(mav.command_long_encode(1, 1, 400, 0, 1, 0, 0, 0, 0, 0, 0).pack(mav)),
              bytes(mav.heartbeat_encode(6, 8, 0, 0, 0).pack(mav)),
              bytes(mav.mission_request_list_encode(1, 1).pack(mav)),
              bytes(mav.param_request_read_encode(1, 1, b"MPC_XY_VEL_MAX", -1).pack(mav))]
    bad = bytearray(frames[1])
    bad[-1] ^= 0xFF
    unknown = bytes((0xFE, 1, 0, 255, 190, _unknown_v1_id(), 7, 0, 0))
    v2 = bytes(b.encoder(255, 190).encode(b.message("PING")(time_usec=5, seq=1, target_system=1, target_component=1)))
    datagrams = [frames[0], frames[1], b"".join(frames), frames[0] + b"\x00\x13" + bytes(bad) + frames[1] + v2,
                 v2 + frames[2], frames[3] + unknown, unknown + frames[3], unknown, bytes(bad), frames[2][:-3],
                 frames[0] + frames[1][:5], b"\xfe", b"\x01\x02\x03\xfd\x05"]
    ack = bytes(b.encoder(1, 1).encode(b.message("COMMAND_ACK")(command=400, result=0, progress=7, result_param2=9,
                                                                  target_system=255, target_component=190)))
    hb = bytes(b.encoder(1, 1).encode(b.message("HEARTBEAT")(type=2, autopilot=12, base_mode=129, custom_mode=5,
                                                               system_status=4, mavlink_version=3)))
    big = bytes(b.encoder(1, 1).encode(b.message("FLIGHT_INFORMATION")(time_boot_ms=1)))
    downs = [ack, hb, big, v2]
    lines = [f"up {d.hex()}" for d in datagrams] + [f"down {d.hex()}" for d in downs]
    proc = subprocess.run(["java", "-cp", str(classes), "ttctl.ttapi.runtime.V1Check"], input="\n".join(lines) + "\n",
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    answers = proc.stdout.splitlines()
    assert len(answers) == len(lines), proc.stdout + proc.stderr
    for d, a in zip(datagrams, answers[:len(datagrams)], strict=True):
        u = Upgrader(b.registry)
        py = u.feed(d, datagram=True)
        got = a.split()
        assert got[0] == "UP" and bytes.fromhex(got[1] if got[1] != "-" else "") == py, (d.hex(), a, py.hex())
        assert int(got[2]) == u.v1_frames and int(got[3]) == u.v1_bad_crc and int(got[5]) == u.v1_unknown, (d.hex(), a)
    for d, a in zip(downs, answers[len(datagrams):], strict=True):
        py_down = downgrade(d, b.registry)
        assert a == "DOWN " + (py_down.hex() if py_down is not None else "none"), (d.hex(), a)
    # and pymavlink reads the answer as MAVLink 1's COMMAND_ACK (command and result: no extensions)
    old = bytes.fromhex(answers[len(datagrams)].split()[1])
    m = v1.MAVLink(None).parse_char(old)
    assert m.get_type() == "COMMAND_ACK" and (m.command, m.result) == (400, 0) and len(old) == 8 + 3


def test_a_bridge_answers_a_mavlink1_station_in_kind_and_names_what_it_cannot(classes: Path) -> None:
    mav = v1.MAVLink(None, srcSystem=246, srcComponent=190)
    hb = bytes(mav.heartbeat_encode(6, 8, 0, 0, 0).pack(mav))
    uid = _unknown_v1_id()
    unknown = bytes((0xFE, 1, 0, 246, 190, uid, 7, 0, 0))
    proc = subprocess.run(["java", "-cp", str(classes), "V1BridgeCheck", hb.hex(), unknown.hex()], capture_output=True,
                          text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    out = proc.stdout.splitlines()
    uplink = [bytes.fromhex(ln.split()[1]) for ln in out if ln.startswith("UPLINK ")]
    station = [bytes.fromhex(ln.split()[1]) for ln in out if ln.startswith("STATION ")]
    problems = [ln[8:] for ln in out if ln.startswith("PROBLEM ")]
    # up: the MAVLink 1 HEARTBEAT went on the link as MAVLink 2, the same message
    b = shipped.bindings()
    [up] = b.parser().feed(b"".join(uplink))
    assert up.NAME == "HEARTBEAT" and (up.get_srcSystem(), up.get_srcComponent(), up.type) == (246, 190, 6)
    # down: all MAVLink 1 once the station spoke it; the ack and RADIO_STATUS read by pymavlink's v1 codec
    assert station and all(d[0] == 0xFE for d in station), [d.hex() for d in station]
    got = [m.get_type() for d in station for m in (v1.MAVLink(None).parse_buffer(d) or [])]
    assert "COMMAND_ACK" in got and "RADIO_STATUS" in got, got
    # what MAVLink 1 cannot carry: one line each, in words
    assert any(p.startswith("not sending FLIGHT_INFORMATION (id 264) to the MAVLink 1 ground station at 127.0.0.1:")
               and "MAVLink 1 carries message ids up to 255" in p for p in problems), problems
    assert any(p.startswith(f"not carrying MAVLink 1 message id {uid} from the ground station at 127.0.0.1:")
               and "the dialect on the link has no such message" in p for p in problems), problems
    assert len(problems) == 2, problems
    done = dict(kv.split("=") for kv in out[-1].split()[1:])
    assert done["v1up"] == "1" and int(done["v1down"]) >= 2 and done["v1dropped"] == "2", done


def test_pymavlink_in_mavlink1_flies_through_the_java_bridge(classes: Path, tmp_path: Path, start: Start) -> None:
    a, b = free_port(), free_port()
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{b}", "--no-entry-points",
                 "--profile", "m100")
    node.wait_for("onboard 1:")
    relay(start, a, b, "--profile", "m100", "--stats-interval", "0")
    g = free_port()
    st = V1Station(g)
    err = open(tmp_path / "driver.err", "w")  # noqa: SIM115 - closed below
    drv = subprocess.Popen(["java", "-cp", str(classes), "BridgeDriver", str(a), str(g), str(free_port()), "480"],
                           stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=err, text=True)
    beater = threading.Thread(target=st.beat, daemon=True)
    try:
        assert drv.stdout is not None and drv.stdout.readline().startswith("ready")
        end = time.monotonic() + scaled(30)
        while st.peer is None and time.monotonic() < end:  # the bridge's first (MAVLink 2) frames say where it is
            try:
                st.peer = st.sock.recvfrom(4096)[1]
            except TimeoutError:
                continue
        assert st.peer is not None, "nothing from the bridge"
        beater.start()
        hb = st.recv("HEARTBEAT", lambda x: x.get_srcSystem() == 1 and x.get_srcComponent() == 1, 20)
        assert hb.autopilot == v1.MAV_AUTOPILOT_PX4
        ack = None
        for confirmation in range(8):  # as ground stations retry
            st.send(st.mav.command_long_encode(1, 1, v1.MAV_CMD_COMPONENT_ARM_DISARM, confirmation, 1, 0, 0, 0, 0, 0,
                                               0))
            try:
                ack = st.recv("COMMAND_ACK", lambda x: x.command == v1.MAV_CMD_COMPONENT_ARM_DISARM, 3.0)
                break
            except AssertionError:
                continue
        assert ack is not None and ack.result == v1.MAV_RESULT_ACCEPTED
        assert len(ack.get_msgbuf()) == 8 + 3  # MAVLink 1's COMMAND_ACK: no extensions
        st.recv("HEARTBEAT", lambda x: x.get_srcComponent() == 1 and x.base_mode & 128, 15)  # armed, says so
        value = None
        for _ in range(5):
            st.send(st.mav.param_request_read_encode(1, 1, b"", 0))
            try:
                value = st.recv("PARAM_VALUE", timeout=3.0)
                break
            except AssertionError:
                continue
        assert value is not None and value.param_index == 0
    finally:
        st.stop.set()
    assert st.v2_frames == 0  # never sent what it cannot read once it spoke
    drv.stdin.write("v1\n")  # type: ignore[union-attr]
    drv.stdin.flush()  # type: ignore[union-attr]
    line = ""
    while not line.startswith("V1 "):
        line = drv.stdout.readline()  # type: ignore[union-attr]
        assert line, "the driver ended"
    counts = dict(re.findall(r"(\w+)=(\d+)", line))
    assert int(counts["up"]) >= 3 and int(counts["down"]) >= 10, line
    drv.stdin.close()  # type: ignore[union-attr]
    drv.wait(20)
    err.close()
    assert "Exception" not in (tmp_path / "driver.err").read_text()
