"""The user's own dialect between ground stations and the vehicle (issue 28), as real processes on
loopback: `ttctl gen --lang xml` exports robolab.xml as one file (pymavlink's mavgen is the oracle
for every message's CRC_EXTRA); MAVSDK's MavlinkDirect loads it and, beside a pymavlink station
with mavgen's module of it, drives the README's motors plugin on `emulate onboard` directly and
through `emulate tablet --gcs` -> `link relay --profile m100 --loss 0.1`, each station getting
its own answers. The stations are docs/ground-stations.md's code blocks, run as written. Bad
input (a flood, an id the dialect lacks, a plugin that raises) is counted, said once, and never
starves the vehicle's HEARTBEAT or commands."""

from __future__ import annotations

import importlib.util
import itertools
import os
import re
import shutil
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

os.environ.setdefault("MAVLINK20", "1")

from conftest import ROOT, assert_no_traceback, run_ttctl
from e2e_lib import LOCAL, Start, free_port
from mavsdk_child import fly
from test_gcs_bridge_peers import chain, no_traceback

DOC = ROOT / "docs" / "ground-stations.md"
OWN = ROOT / "dialects" / "examples"
REQUESTS = 20


@pytest.fixture(scope="session")
def bindings_cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("ttctl-cache")


@pytest.fixture
def own(tmp_path: Path, bindings_cache: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """tmp_path with robolab.xml, motors.py, the exported XML (gen/xml/robolab.xml) and mavgen's
    module of it (robolab_pm.py), as docs/ground-stations.md has them."""
    monkeypatch.setenv("TTCTL_CACHE_DIR", str(bindings_cache))
    monkeypatch.delenv("TTCTL_DIALECT", raising=False)
    shutil.copy(OWN / "robolab.xml", tmp_path)
    shutil.copy(OWN / "motors.py", tmp_path)
    gen = run_ttctl("gen", "robolab.xml", "--lang", "xml", "-o", "gen", cwd=tmp_path)
    assert gen.returncode == 0, gen.stderr
    assert gen.stdout.strip() in DOC.read_text(), gen.stdout  # the doc shows what it says
    mavgen(tmp_path / "gen" / "xml" / "robolab.xml", tmp_path / "robolab_pm.py")
    return tmp_path


def mavgen(xml: Path, out: Path) -> None:
    proc = subprocess.run([sys.executable, "-m", "pymavlink.tools.mavgen", "--lang", "Python3", "--wire-protocol",
                           "2.0", "-o", str(out), str(xml)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def load_module(path: Path, name: str) -> ModuleType:
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def doc_block(marker: str) -> str:
    """The doc's python code block that contains `marker`."""
    blocks = re.findall(r"```python\n(.*?)```", DOC.read_text(), re.S)
    (found,) = [b for b in blocks if marker in b]
    return found


def doc_pymavlink(folder: Path) -> Any:
    """The doc's pymavlink station (`main`), importing mavgen's module from `folder`."""
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))
    sys.modules.pop("robolab_pm", None)
    ns: dict[str, Any] = {"__name__": "motors_pymavlink"}
    exec(compile(doc_block("import robolab_pm"), "motors_pymavlink.py", "exec"), ns)
    return ns["main"]


def doc_mavsdk_scenario(url: str, xml: Path, count: int) -> Any:
    """A fly() body running the doc's MAVSDK script's `main` with the child's Mavsdk."""
    source = doc_block("MavlinkDirectAsync")

    async def body(mav: Any) -> dict[int, float]:
        ns: dict[str, Any] = {"__name__": "motors_mavsdk"}
        exec(compile(source, "motors_mavsdk.py", "exec"), ns)
        answers: dict[int, float] = await ns["main"](url=url, xml=str(xml), count=count, mav=mav)
        return answers

    return body


def both_stations(own: Path, mavsdk_port: int, pm_port: int, pm_ids: tuple[int, int]) -> tuple[Any, Any]:
    """MAVSDK (245/190) and the pymavlink station at once, REQUESTS each: their answers."""
    got: dict[str, Any] = {}
    main = doc_pymavlink(own)

    def pymavlink_side() -> None:
        try:
            got["pm"] = main(port=pm_port, count=REQUESTS, sysid=pm_ids[0], compid=pm_ids[1])
        except BaseException as e:
            got["pm"] = repr(e)

    t = threading.Thread(target=pymavlink_side, daemon=True)
    t.start()
    at_mavsdk = fly(doc_mavsdk_scenario(f"udpin://{LOCAL}:{mavsdk_port}", own / "gen" / "xml" / "robolab.xml",
                                        REQUESTS), 75)
    t.join(60)
    assert not t.is_alive(), "the pymavlink station did not finish"
    return at_mavsdk, got["pm"]


def check_answers(answers: Any, who: str) -> None:
    assert isinstance(answers, tuple), f"{who}: {answers}"
    mine, others = answers
    assert sorted(mine) == list(range(REQUESTS)), f"{who} got answers to {sorted(mine)}"
    assert all(rpm == 30 * 12.5 for rpm in mine.values()), mine
    assert others == [], f"{who} got answers meant for other stations: {others[:5]}"


# -- 1. the export ---------------------------------------------------------------------------------
def test_the_exported_xml_is_one_file_with_every_message_once_and_mavgens_crcs(own: Path) -> None:
    from pymavlink.generator import mavparse

    from ttctl.dialect import load_dialect

    flat = own / "gen" / "xml" / "robolab.xml"
    text = flat.read_text()
    assert "<include>" not in text
    loaded = load_dialect(str(own / "robolab.xml"))
    assert loaded.dialect is not None
    files = [f.path for f in loaded.dialect.files]
    assert len(files) >= 4, files  # robolab, ttapi, common, standard, minimal
    # mavgen reads each original file alone (its own messages) and the exported one
    original: dict[int, tuple[str, int]] = {}
    entries: dict[str, dict[str, int]] = {}  # enums merged across the files, as mavgen merges them
    for path in files:
        parsed = mavparse.MAVXML(path, mavparse.PROTOCOL_2_0)
        for m in parsed.message:
            assert m.id not in original, (m.name, path)
            original[m.id] = (m.name, m.crc_extra)
        for e in parsed.enum:
            entries.setdefault(e.name, {}).update({x.name: x.value for x in e.entry if not x.end_marker})
    exported = mavparse.MAVXML(str(flat), mavparse.PROTOCOL_2_0)
    ids = [m.id for m in exported.message]
    assert len(ids) == len(set(ids))  # every message once
    assert {m.id: (m.name, m.crc_extra) for m in exported.message} == original
    assert original[51000][0] == "KR_MOTOR_CONTROL" and original[0][0] == "HEARTBEAT"
    # the enums' entries, auto-numbered or not, keep their values
    assert {e.name: {x.name: x.value for x in e.entry if not x.end_marker} for e in exported.enum} == entries
    assert entries["KR_VEHICLE_DIR"] == {"KR_VEHICLE_DIR_STOP": 0, "KR_VEHICLE_DIR_FORWARD": 1,
                                         "KR_VEHICLE_DIR_BACKWARD": 2}
    # --lang xml beside a language, and --check of it
    both = run_ttctl("gen", "robolab.xml", "--lang", "python,xml", "-o", "gen", cwd=own)
    assert both.returncode == 0 and "[python, xml;" in both.stdout, both.stdout + both.stderr
    check = run_ttctl("gen", "robolab.xml", "--lang", "xml", "-o", "gen", "--check", cwd=own)
    assert check.returncode == 0, check.stdout
    flat.write_text(text.replace("KR_MOTOR_STATUS", "KR_MOTOR_STATE"))
    check = run_ttctl("gen", "robolab.xml", "--lang", "xml", "-o", "gen", "--check", cwd=own)
    assert check.returncode == 1 and "gen/xml/robolab.xml: out of date" in check.stdout, check.stdout


def test_the_export_refuses_in_one_line_and_writes_nothing(own: Path) -> None:
    broken = own / "broken.xml"
    broken.write_text((own / "robolab.xml").read_text().replace('id="51001"', 'id="51000"'))
    proc = run_ttctl("gen", "broken.xml", "--lang", "xml", "-o", "out", cwd=own)
    assert_no_traceback(proc)
    assert proc.returncode == 1 and "nothing generated" in proc.stderr, proc.stderr
    assert not (own / "out").exists()
    proc = run_ttctl("gen", "robolab.xml", "--lang", "xml,cobol", "-o", "out", cwd=own)
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    assert "unknown language cobol" in proc.stderr and "xml" in proc.stderr
    assert not (own / "out").exists()


# -- 2. stations and the vehicle -------------------------------------------------------------------
def test_mavsdk_and_pymavlink_each_get_their_own_answers_directly(own: Path, start: Start) -> None:
    """Both on `emulate onboard --gcs` links of their own: MAVSDK (MavlinkDirect with the exported
    XML) and the pymavlink station with QGroundControl's ids; REQUESTS each, all answered, none
    to the other."""
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")
    p_mavsdk, p_pm = free_port(), free_port()
    node = start("onboard", "emulate", "onboard", "--dialect", "robolab.xml", "--plugin", "motors.py",
                 "--no-entry-points", "--listen", f"udpin:{LOCAL}:{free_port()}",
                 "--gcs", f"udpout:{LOCAL}:{p_mavsdk}", "--gcs", f"udpout:{LOCAL}:{p_pm}")
    node.wait_for("plugins Motors", timeout=60)
    at_mavsdk, at_pm = both_stations(own, p_mavsdk, p_pm, (255, 190))
    assert sorted(at_mavsdk) == list(range(REQUESTS)), at_mavsdk
    check_answers(at_pm, "the pymavlink station")
    no_traceback(node)


def test_mavsdk_and_pymavlink_each_get_their_own_answers_through_the_tablet(own: Path, start: Start) -> None:
    """The same stations on the tablet's bridge, over `link relay --profile m100 --loss 0.1`: the
    plugin's answers come back down the DTT link and the bridge gives each station its own (the
    pymavlink one, at the tablet's own ids 255/190, carried under another and given its own back)."""
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")
    c = chain(start, own, stations=2, onboard=("--dialect", "robolab.xml", "--plugin", "motors.py"),
              tablet=("--dialect", "robolab.xml"))
    at_mavsdk, at_pm = both_stations(own, c.gcs[0], c.gcs[1], (255, 190))
    assert sorted(at_mavsdk) == list(range(REQUESTS)), at_mavsdk
    check_answers(at_pm, "the pymavlink station")
    handled = re.findall(r"motors: seq (\d+)", c.onboard.stderr)
    assert {int(s) for s in handled} == set(range(REQUESTS))  # (retries may run it twice)
    c.stop_tablet()
    no_traceback(c.onboard, c.relay, c.tablet)


# -- 3. bad input ----------------------------------------------------------------------------------
RAISER = '''
from robolab import messages as m

from ttctl.ends.plugins import Context, Plugin, handles


class Raiser(Plugin):
    @handles(m.KrMotorControl)
    def on_control(self, msg: m.KrMotorControl, ctx: Context) -> None:
        raise RuntimeError("the robot's driver is unplugged")
'''


class RawStation:
    """A pymavlink station (mavgen's module of the exported XML) on a bare socket, as fast as it can."""

    def __init__(self, folder: Path, port: int, sysid: int = 250, compid: int = 190) -> None:
        self.mod = load_module(folder / "robolab_pm.py", "robolab_pm_raw")
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind((LOCAL, port))
        self.sock.settimeout(0.05)
        self.link = self.mod.MAVLink(None, srcSystem=sysid, srcComponent=compid)
        self.link.robust_parsing = True
        self.vehicle: Any = None
        self.seen: list[tuple[float, Any]] = []

    def send(self, msg: Any) -> None:
        self.sock.sendto(msg.pack(self.link), self.vehicle)
        self.link.seq = (self.link.seq + 1) % 256

    def pump(self, seconds: float) -> None:
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            try:
                data, addr = self.sock.recvfrom(65535)
            except TimeoutError:
                continue
            self.vehicle = addr
            self.seen.extend((time.monotonic(), m) for m in self.link.parse_buffer(data) or [])

    def kinds(self, kind: str, since: float = 0.0) -> list[Any]:
        return [m for t, m in self.seen if t >= since and m.get_type() == kind]


def unknown_frame(msgid: int, sysid: int, compid: int, seq: int) -> bytes:
    """A well-formed MAVLink 2 frame of a message no dialect here has (its CRC over any extra)."""
    from pymavlink.generator.mavcrc import x25crc

    payload = bytes(range(8))
    head = bytes([0xFD, len(payload), 0, 0, seq, sysid, compid, msgid & 0xFF, (msgid >> 8) & 0xFF, msgid >> 16])
    crc = x25crc(head[1:] + payload)
    crc.accumulate(bytes([77]))
    return head + payload + crc.crc.to_bytes(2, "little")


def test_a_flood_an_unknown_id_and_a_raising_plugin_are_counted_said_once_and_starve_nothing(
        own: Path, start: Start) -> None:
    (own / "raiser.py").write_text(RAISER)
    port = free_port()
    node = start("onboard", "emulate", "onboard", "--dialect", "robolab.xml", "--plugin", "motors.py",
                 "--plugin", "raiser.py", "--no-entry-points", "--listen", f"udpin:{LOCAL}:{free_port()}",
                 "--gcs", f"udpout:{LOCAL}:{port}")
    node.wait_for("plugins Motors, Raiser", timeout=60)
    st = RawStation(own, port)
    try:
        while st.vehicle is None:
            st.pump(0.2)
        m = st.mod
        # the flood: user messages as fast as one socket sends them, for 3 s, the vehicle's frames read meanwhile
        flood_start = time.monotonic()
        sent = 0
        while time.monotonic() - flood_start < 3.0:
            for _ in range(200):
                st.send(m.MAVLink_kr_motor_control_message(1, sent & 0xFFFF, m.KR_VEHICLE_DIR_FORWARD, 10))
                sent += 1
            st.pump(0.001)
        # a command in the flood's wake: acked at once
        asked = time.monotonic()
        for i in range(3):
            st.send(m.MAVLink_command_long_message(1, 1, m.MAV_CMD_REQUEST_MESSAGE, i,
                                                   m.MAVLINK_MSG_ID_AUTOPILOT_VERSION, 0, 0, 0, 0, 0, 0))
            st.pump(1.0)
            if st.kinds("COMMAND_ACK", asked):
                break
        for i in range(10):
            st.sock.sendto(unknown_frame(52000, 250, 190, i), st.vehicle)
        st.pump(1.0)
        heartbeats = [t for t, x in st.seen if x.get_type() == "HEARTBEAT" and x.get_srcComponent() == 1
                      and flood_start <= t]
        acks = st.kinds("COMMAND_ACK", asked)
        answers = st.kinds("KR_MOTOR_STATUS", flood_start)
    finally:
        st.sock.close()
    assert sent > 2000, sent
    assert acks and acks[0].result == m.MAV_RESULT_ACCEPTED
    assert len(heartbeats) >= 3, len(heartbeats)  # a second apart, through the flood and after
    assert max(b - a for a, b in itertools.pairwise(heartbeats)) < 2.5
    assert 100 <= len(answers) < sent / 2, (len(answers), sent)  # delivered up to the rate, the rest shed
    node.signal(2)
    assert node.wait(15) == 0, node.stderr
    err = node.stderr
    assert err.count("faster than 100 a second") == 1, err
    assert err.count("message id 52000 is not in the dialect this end speaks (robolab)") == 1, err
    assert err.count("plugin Raiser.on_control failed on KR_MOTOR_CONTROL: RuntimeError: the robot's driver") == 1
    summary = re.search(r"ground stations' own messages: (\d+) delivered to plugins, (\d+) answers, (\d+) shed "
                        r"\(over 100/s\), (\d+) not in the dialect, (\d+) handler failures", err)
    assert summary is not None, err
    delivered, replies, shed, unknown, failed = map(int, summary.groups())
    assert delivered + shed <= sent and shed > 0 and unknown >= 10 and failed == delivered, summary.group(0)
    assert replies == delivered  # motors answered every one delivered, beside the raiser
    assert "Traceback" not in err


TELL = '''
from robolab import messages as m

from ttctl.ends.plugins import Context, Plugin, handles


class Tell(Plugin):
    @handles(m.KrMotorControl)
    def on_control(self, msg: m.KrMotorControl, ctx: Context) -> None:
        if msg.seq == 7:  # to station 250 alone, then to every station
            ctx.send_gcs(m.KrMotorStatus(seq=1007, note="to 250"), to=250)
            ctx.send_gcs(m.KrMotorStatus(target_system=0, seq=2007, note="to all"))
        elif msg.seq == 8:
            ctx.send_gcs(m.KrMotorStatus(seq=1008), to=(99, 1))  # no such station: ValueError, counted
'''


def test_a_plugin_publishes_to_one_station_or_to_every_one(own: Path, start: Start) -> None:
    """`ctx.send_gcs(msg, to=sysid)` reaches that station only (on its own link, addressed to it),
    `ctx.send_gcs(msg)` every station; a station nobody heard is a ValueError the node survives; a
    message for another vehicle (target_system 2) does not reach the plugin."""
    (own / "tell.py").write_text(TELL)
    p250, p251 = free_port(), free_port()
    node = start("onboard", "emulate", "onboard", "--dialect", "robolab.xml", "--plugin", "tell.py",
                 "--no-entry-points", "--listen", f"udpin:{LOCAL}:{free_port()}",
                 "--gcs", f"udpout:{LOCAL}:{p250}", "--gcs", f"udpout:{LOCAL}:{p251}")
    node.wait_for("plugins Tell", timeout=60)
    a, b = RawStation(own, p250, 250, 190), RawStation(own, p251, 251, 190)
    try:
        for st in (a, b):
            while st.vehicle is None:
                st.pump(0.2)
        m = a.mod
        a.send(m.MAVLink_heartbeat_message(m.MAV_TYPE_GCS, m.MAV_AUTOPILOT_INVALID, 0, 0, 4, 3))  # heard: 250
        a.pump(0.2)
        b.send(m.MAVLink_kr_motor_control_message(2, 7, m.KR_VEHICLE_DIR_FORWARD, 20))  # vehicle 2's: not ours
        b.send(m.MAVLink_kr_motor_control_message(1, 7, m.KR_VEHICLE_DIR_FORWARD, 20))
        b.send(m.MAVLink_kr_motor_control_message(1, 8, m.KR_VEHICLE_DIR_FORWARD, 20))
        for _ in range(10):
            a.pump(0.1)
            b.pump(0.1)
    finally:
        a.sock.close()
        b.sock.close()
    at_a = sorted((x.seq, x.target_system) for x in a.kinds("KR_MOTOR_STATUS"))
    at_b = sorted((x.seq, x.target_system) for x in b.kinds("KR_MOTOR_STATUS"))
    assert at_a == [(1007, 250), (2007, 0)], at_a
    assert at_b == [(2007, 0)], at_b
    node.signal(2)
    assert node.wait(15) == 0
    assert node.stderr.count("plugin Tell.on_control failed on KR_MOTOR_CONTROL: ValueError: no ground station "
                             "99/1 was heard here") == 1, node.stderr
    assert "Traceback" not in node.stderr


def test_the_bridge_queues_a_stations_own_messages_behind_its_commands() -> None:
    """The tablet's uplink (sans-IO): a station flooding its own messages keeps 16 of them at
    most, and its COMMAND_LONG and HEARTBEAT leave first."""
    from ttctl.bridge.uplink import MAX_USER, GcsUplink

    def frame(msgid: int, payload: bytes) -> bytes:
        return bytes([0xFD, len(payload), 0, 0, 0, 250, 190, msgid & 0xFF, msgid >> 8 & 0xFF, msgid >> 16]) \
            + payload + b"\0\0"

    up = GcsUplink(None)
    for i in range(1000):
        up.put(0.0, "KR_MOTOR_CONTROL", frame(51000, i.to_bytes(4, "little")))
    up.put(0.0, "COMMAND_LONG", frame(76, b"cmd"))
    up.put(0.0, "HEARTBEAT", frame(0, b"hb"))
    assert len(up) == MAX_USER + 2 and up.stats.user_overflow == 1000 - MAX_USER
    out = [up.pull(0.0, 100) for _ in range(len(up))]
    assert out[0] == frame(76, b"cmd") and out[1] == frame(0, b"hb")
    assert out[2:] == [frame(51000, i.to_bytes(4, "little")) for i in range(1000 - MAX_USER, 1000)]


def test_the_doc_shows_the_plugin_answering_with_reply() -> None:
    """motors.py answers with ctx.reply, as the doc says (so that a station's request is answered
    to that station, a tablet's to the tablet)."""
    assert "ctx.reply(m.KrMotorStatus(" in (OWN / "motors.py").read_text()
    assert "ctx.reply(m.KrMotorStatus(" in doc_block("on_kr_motor_control")



def test_a_message_the_tablet_lacks_is_carried_by_its_header_as_mavlink_router_does(own: Path, start: Start) -> None:
    """A tablet that speaks only ttapi between a station and a robolab vehicle: the station's
    KR_MOTOR_CONTROL (an id the tablet cannot check) is carried up by its header and reaches the
    plugin, said once; from a station at the tablet's own ids (which the bridge must rewrite, and
    the CRC covers) it is not, said once; no crash anywhere."""
    c = chain(start, own, stations=2, onboard=("--dialect", "robolab.xml", "--plugin", "motors.py"))
    a, b = RawStation(own, c.gcs[0], 250, 190), RawStation(own, c.gcs[1], 255, 190)
    try:
        for st in (a, b):
            while st.vehicle is None:
                st.pump(0.2)
        m = a.mod
        for seq in range(6):
            a.send(m.MAVLink_kr_motor_control_message(1, seq, m.KR_VEHICLE_DIR_FORWARD, 20))
            b.send(m.MAVLink_kr_motor_control_message(1, 100 + seq, m.KR_VEHICLE_DIR_FORWARD, 20))
            a.pump(0.3)
            b.pump(0.1)
        c.onboard.wait_for("motors: seq ", timeout=10)
    finally:
        a.sock.close()
        b.sock.close()
    handled = {int(s) for s in re.findall(r"motors: seq (\d+)", c.onboard.stderr)}
    assert handled and handled <= set(range(6)), handled  # (10 % loss: most of them) and none of 255/190's
    line = c.stop_tablet()
    err = c.tablet.stderr if c.tablet is not None else ""
    assert err.count("carrying message id 51000 from a ground station by its header") == 1, err
    assert err.count("not carrying message id 51000 from a ground station: the tablet's dialect (ttapi) lacks it "
                     "and the station uses the tablet's own ids 255/190") == 1, err
    assert re.search(r"ids the dialect lacks: \d+ carried by header, 6 not", line), line
    no_traceback(c.onboard, c.relay, c.tablet)


def test_a_station_flooding_its_own_messages_through_the_tablet_starves_no_command(own: Path, start: Start) -> None:
    """Through tablet -> m100 relay -> onboard: a station sends KR_MOTOR_CONTROL as fast as it can
    for 6 s; meanwhile its COMMAND_LONGs are acked and the vehicle's HEARTBEAT keeps coming, and
    some of its own messages are still answered."""
    c = chain(start, own, onboard=("--dialect", "robolab.xml", "--plugin", "motors.py"),
              tablet=("--dialect", "robolab.xml"))
    st = RawStation(own, c.gcs[0], 250, 190)
    acks: list[float] = []
    try:
        while st.vehicle is None:
            st.pump(0.2)
        m = st.mod
        begin = time.monotonic()
        sent = 0
        asked_at = 0.0
        while time.monotonic() - begin < 6.0:
            for _ in range(50):
                st.send(m.MAVLink_kr_motor_control_message(1, sent & 0xFFFF, m.KR_VEHICLE_DIR_FORWARD, 10))
                sent += 1
            now = time.monotonic()
            if now - asked_at > 1.0:  # a command a second, as a station polls
                st.send(m.MAVLink_command_long_message(1, 1, m.MAV_CMD_REQUEST_MESSAGE, 0,
                                                       m.MAVLINK_MSG_ID_AUTOPILOT_VERSION, 0, 0, 0, 0, 0, 0))
                asked_at = now
            st.pump(0.01)
        st.pump(2.0)
        acks = [t for t, x in st.seen if x.get_type() == "COMMAND_ACK"]
        heartbeats = [t for t, x in st.seen if x.get_type() == "HEARTBEAT" and x.get_srcComponent() == 1
                      and t >= begin]
        answers = st.kinds("KR_MOTOR_STATUS", begin)
    finally:
        st.sock.close()
    assert sent > 5000, sent
    # 6 asked, not retried, over a 10 % lossy link both ways (without the uplink's own queue for the
    # station's messages, none came back); a HEARTBEAT a second, some lost to the link
    assert len(acks) >= 2, len(acks)
    assert len(heartbeats) >= 5 and max(b - a for a, b in itertools.pairwise(heartbeats)) < 4.5, heartbeats
    assert answers, "none of the station's own messages was answered"
    line = c.stop_tablet()
    assert re.search(r"\d+ of their own messages dropped for room", line), line
    no_traceback(c.onboard, c.relay, c.tablet)
