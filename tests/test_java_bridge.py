"""The ground-station bridge of the generated Java runtime (runtime.GcsBridge, issue 22): its rules
without a vehicle (tests/java/gcs/GcsCheck.java: the sans-IO uplink queue and budget, the link
quality, a bridge on a recording link with a UDP socket as the ground station), the frames it
makes decoded by pymavlink as the oracle."""

from __future__ import annotations

import math
import os
import random
import shutil
import subprocess
from pathlib import Path
from typing import Any

import pytest

from conformance_lib import build_java
from conftest import ROOT, shipped

pytestmark = pytest.mark.skipif(not (shutil.which("javac") and shutil.which("java")),
                                reason="needs a JDK (javac, java)")


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    drivers = [ROOT / "tests" / "java" / "gcs" / f"{n}.java"
               for n in ("GcsCheck", "UplinkScript", "QualityScript", "ProtocolScript")]
    cls, _ = build_java(tmp_path_factory.mktemp("gcs_check"), drivers)
    return cls


def _mav() -> object:
    os.environ["MAVLINK20"] = "1"
    from pymavlink.dialects.v20 import common
    return common.MAVLink(None)


def test_bridge_rules_without_a_vehicle(classes: Path) -> None:
    """Retries of a waiting frame dropped, NEWEST slots replaced in place, PROTOCOL first, 64 + 64
    frames at most, the budget at 300 B/s over 10 virtual seconds; the table of ground stations
    (each 255/190 under its own free id, answers routed by target, forgotten after 30 s silent,
    at most 16 heard); the clashing 255/190 ground
    station carried as 254/190 and its answer given back to 255; a command for system 7 and
    garbage not carried; RADIO_STATUS within a second and a half; a port in use refused; on a
    signed link the scheduler signs the ground stations' frames; a send the socket refuses is told
    once, in words; bad settings are refused with words."""
    proc = subprocess.run(["java", "-cp", str(classes), "GcsCheck"], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    frames = {ln.split()[1]: bytes.fromhex(ln.split()[2]) for ln in proc.stdout.splitlines()
              if ln.startswith("FRAME ")}
    result = dict(kv.split("=") for kv in proc.stdout.splitlines()[-1].split()[1:])
    assert 3000 <= int(result["budget_bytes"]) <= 3200 and result["busy"] == "refused", result
    assert result["signed"] == "3", result
    assert result["ftp_resend"] == "ok", result  # GcsResend follows a station's retried MAVLink FTP request
    [problem] = [ln for ln in proc.stdout.splitlines() if ln.startswith("PROBLEM ")]
    assert problem.startswith("PROBLEM sending to the ground station at 192.0.2.1:14550 failed: "), problem
    mav = _mav()
    moved = mav.parse_char(frames["resourced"])  # the CRC recomputed: pymavlink accepts it
    assert moved.get_type() == "COMMAND_LONG" and moved.get_srcSystem() == 254 and moved.get_srcComponent() == 190
    assert moved.target_system == 7 and moved.get_seq() == 9
    back = _mav().parse_char(frames["retargeted"])
    assert back.get_type() == "COMMAND_ACK" and back.target_system == 255 and back.target_component == 190
    radio = _mav().parse_char(frames["radio"])
    assert radio.get_type() == "RADIO_STATUS" and (radio.get_srcSystem(), radio.get_srcComponent()) == (1, 68)
    assert (radio.rssi, radio.remrssi, radio.txbuf, radio.rxerrors, radio.fixed) == (229, 229, 87, 70000 % 65536, 3)
    assert (radio.noise, radio.remnoise) == (0, 0)
    zero = _mav().parse_char(frames["radio_zero"])
    assert (zero.rssi, zero.txbuf, zero.rxerrors) == (0, 0, 0)
    live = _mav().parse_char(frames["radio_live"])
    assert live.get_type() == "RADIO_STATUS" and live.rssi == 254 and live.txbuf == 100


def _script(seed: int) -> tuple[list[str], list[tuple[str, int, Any]]]:
    """A ground station's traffic and the scheduler's pulls, 20 s of it: HEARTBEATs, 50 Hz
    MANUAL_CONTROL from two sources, commands repeated as retries, parameter requests in loops,
    bursts of 80 distinct mission items (past the bound), pulls at random times."""
    b = shipped()
    rnd = random.Random(seed)
    ops: list[tuple[str, int, Any]] = []
    t = 0
    seq = 0
    while t < 20_000_000:
        t += rnd.randint(1, 40_000)
        seq = (seq + 1) & 0xFF
        r = rnd.random()
        src = rnd.choice([(255, 190), (245, 190)])
        if r < 0.35:
            msg: Any = b.ManualControl(target=1, x=rnd.randint(-1000, 1000), y=0, z=500, r=0, buttons=0)
        elif r < 0.40:
            msg = b.Heartbeat(type=6, autopilot=8, base_mode=0, custom_mode=0, system_status=0)
        elif r < 0.55:
            msg = b.CommandLong(target_system=1, target_component=1, command=rnd.choice([400, 22, 512]), confirmation=0,
                                param1=rnd.choice([0.0, 1.0]), param2=0, param3=0, param4=0, param5=0, param6=0,
                                param7=0)
        elif r < 0.70:
            msg = b.ParamRequestList(target_system=1, target_component=1)
        elif r < 0.72:
            for i in range(80):
                item = b.MissionItemInt(target_system=1, target_component=1, seq=i, frame=6, command=16, current=0,
                                        autocontinue=1, param1=0, param2=0, param3=0, param4=0, x=i, y=0, z=10,
                                        mission_type=0)
                ops.append(("put", t, (item.NAME, bytes(item.pack(seq, *src)))))
            continue
        else:
            ops.append(("pull", t, None))
            continue
        ops.append(("put", t, (msg.NAME, bytes(msg.pack(seq, *src)))))
    lines = [f"put {t} {f.hex()}" if op == "put" else f"pull {t}" for op, t, (_, f) in
             ((op, t, x if x is not None else ("", b"")) for op, t, x in ops)]
    return lines, ops


def test_the_java_uplink_decides_as_the_python_bridge(classes: Path) -> None:
    """The same 20 s of a ground station's frames and the scheduler's pulls, played to the Java
    GcsUplink (tests/java/gcs/UplinkScript.java) and to the Python bridge's (ttctl/bridge/uplink.py)
    at 250 B/s, bursts of one 100-byte packet: every verdict, every frame pulled and every
    "ready at" the same, step for step, past the bounds and the budget."""
    from ttctl.bridge.uplink import GcsUplink

    lines, ops = _script(7)
    proc = subprocess.run(["java", "-cp", str(classes), "UplinkScript"], input="budget 250 100\n" + "\n".join(lines)
                          + "\n", capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    java = proc.stdout.splitlines()
    q = GcsUplink(250.0, burst=100)
    python = []
    for op, t, x in ops:
        now = t / 1e6
        if op == "put":
            name, f = x
            python.append(q.put(now, name, f))
        else:
            got = q.pull(now, 100)
            if got is not None:
                python.append(got.hex())
            else:
                at = q.deadline(now)
                python.append(f"- {-1 if at is None else math.ceil(at * 1e6)}")
    python.append(f"overflow {q.stats.overflow} duplicates {q.stats.duplicates} replaced {q.stats.replaced}")
    assert len(java) == len(python)
    differ = []
    for i, (j, p) in enumerate(zip(java, python, strict=True)):
        # "ready at" in microseconds, rounded from nanoseconds and from floats
        if j.startswith("- ") and p.startswith("- ") and abs(int(j[2:]) - int(p[2:])) <= 2:
            continue
        if j != p:
            differ.append((i, lines[i] if i < len(lines) else "", j, p))
    assert not differ, differ[:5]
    tally = {v: python.count(v) for v in ("queued", "replaced", "duplicate")}
    pulled = sum(1 for v in python if v[:2] == "fd")
    assert tally["duplicate"] > 20 and tally["replaced"] > 100 and pulled > 100 and q.stats.overflow > 0, \
        (tally, pulled)


def test_the_java_link_quality_is_the_python_bridges(classes: Path) -> None:
    """The vehicle's frames over 60 s of a lossy link (random loss, bursts, frames overtaken by a
    later one, repeats, two components, a 5 s silence), played to the Java GcsQuality
    (tests/java/gcs/QualityScript.java) and the Python bridge's Routes: the same rssi at every
    RADIO_STATUS, the same frames counted lost; the same txbuf for every queue size."""
    from ttctl.bridge.routes import Routes
    from ttctl.ends.tablet.gcs_bridge import TXBUF_BYTES

    rnd = random.Random(11)
    lines: list[str] = []
    routes = Routes(1)
    want: list[str] = []
    seqs = {1: 0, 68: 0}
    t = 0
    next_radio = 1_000_000
    held: tuple[int, int] | None = None
    while t < 60_000_000:
        t += rnd.randint(2_000, 30_000)
        if 30_000_000 <= t < 35_000_000:  # the radio lost for 5 s
            t = 35_000_000
        while next_radio <= t:
            lines.append(f"rssi {next_radio}")
            want.append(str(routes.quality(next_radio / 1e6)))
            next_radio += 1_000_000
        comp = rnd.choice([1, 1, 1, 68])
        seqs[comp] = (seqs[comp] + 1) & 0xFF
        r = rnd.random()
        if r < (0.3 if 10_000_000 <= t < 15_000_000 else 0.08):
            continue  # lost
        events = [(comp, seqs[comp])]
        if r > 0.97 and held is None:
            held = events.pop()  # overtaken by the next one
        elif held is not None and comp == held[0]:
            events.append(held)
            held = None
        if r < 0.1:
            events.append(events[-1] if events else (comp, seqs[comp]))  # a repeat
        for c, sq in events:
            lines.append(f"frame {t} {c} {sq}")
            routes.vehicle_frame(t / 1e6, c, sq)
    for n in range(0, 5000, 7):
        lines.append(f"txbuf {n}")
        want.append(str(max(0, min(100, round(100 * (1 - n / TXBUF_BYTES))))))
    want.append(f"lost {routes.lost} received {routes.received}")
    proc = subprocess.run(["java", "-cp", str(classes), "QualityScript"], input="\n".join(lines) + "\n",
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    got = proc.stdout.splitlines()
    assert len(got) == len(want)
    differ = [(i, g, w) for i, (g, w) in enumerate(zip(got, want, strict=True)) if g != w]
    assert not differ, differ[:5]
    rssis = [int(w) for w in want[:59]]
    assert 0 in rssis and max(rssis) > 220 and min(x for x in rssis if x) < 200, rssis  # lossy, silent, good


def _describe(f: bytes) -> str:
    """ProtocolScript.describe: id:sys/comp:field (and :target:type for an item request)."""
    def u8(o: int) -> int:
        return f[10 + o] if o < f[1] else 0

    def u16(o: int) -> int:
        return u8(o) | u8(o + 1) << 8

    mid = f[7] | f[8] << 8
    s = f"{mid}:{f[5]}/{f[6]}:{u16(28) if mid in (73, 39) else u16(0)}"
    return s + (f":{u8(2)}/{u8(3)}:{u8(4)}" if mid in (51, 40) else "")


@pytest.mark.parametrize("seed", [29, 2, 3])
def test_the_java_mission_and_parameter_protocols_decide_as_the_python_bridges(classes: Path, seed: int) -> None:
    """90 virtual seconds of two ground stations uploading, downloading and listing parameters
    with a vehicle behind a link that loses 10 % each way, played to the Python bridge's protocols
    (bridge/missions.py, downloads.py, params.py and its uplink, in the bridge's order; the script
    made as it plays, the stations and the vehicle answering what reached them) and then to the
    Java runtime's (tests/java/gcs/ProtocolScript.java): every frame passed on or kept, sent to a
    station, offered to the uplink or pulled from it the same, step for step."""
    from ttctl.bridge.downloads import DownloadRelay
    from ttctl.bridge.missions import MissionRelay
    from ttctl.bridge.params import ParamLists
    from ttctl.bridge.uplink import GcsUplink

    os.environ["MAVLINK20"] = "1"
    from pymavlink.dialects.v20 import common

    rnd = random.Random(seed)
    mavs: dict[tuple[int, int], Any] = {}

    def pack(src: tuple[int, int], msg: Any) -> bytes:
        m = mavs.setdefault(src, common.MAVLink(None, srcSystem=src[0], srcComponent=src[1]))
        return bytes(msg.pack(m))

    parser = common.MAVLink(None)
    parser.robust_parsing = True

    def decode(f: bytes) -> Any:
        msg = parser.decode(bytearray(f))
        msg.NAME = msg.get_type()  # (as ttctl's own bindings name it)
        return msg

    def request(who: tuple[int, int], seq: int, kind: int) -> Any:
        msg = common.MAVLink_mission_request_int_message(who[0], who[1], seq, kind)
        msg.NAME = msg.get_type()
        return msg

    q = GcsUplink(250.0, burst=100)
    missions = MissionRelay(request, waiting=q.waiting)
    downloads = DownloadRelay(lambda who, seq, t: pack(who, common.MAVLink_mission_request_int_message(1, 1, seq, t)),
                              waiting=q.waiting)
    params = ParamLists()
    stations = {(255, 190): {"plan": 0}, (245, 190): {"plan": 0}}
    vplan: dict[int, int] = {0: 0}  # the vehicle's plan: count per mission type
    vup: dict[tuple[int, int], list[int]] = {}  # the vehicle's upload from a station: [count, next]
    lines: list[str] = []
    python: list[str] = []
    to_vehicle: list[tuple[float, bytes]] = []  # (arrives, frame)
    to_station: list[tuple[float, tuple[int, int], Any]] = []

    def veh_send(now: float, msg: Any) -> None:
        now = round(now, 6)
        if rnd.random() < 0.9:
            f = pack((1, 1), msg)
            lines.append(f"veh {round(now * 1e6)} {f.hex()}")
            python.append(vehicle_frame(now, f))

    def vehicle_frame(now: float, f: bytes) -> str:
        msg = decode(f)
        st: list[str] = []
        first: list[str] = []
        up: list[str] = []
        fwd = True
        tgt = getattr(msg, "target_system", 0)
        who = (tgt, msg.target_component) if tgt else None
        if msg.NAME == "PARAM_VALUE":
            params.value(now, msg.param_index, msg.param_count)
        elif msg.NAME.startswith("MISSION_"):
            fwd, again, reqs = missions.from_vehicle(now, msg, who)
            passed, lost, ahead = downloads.from_vehicle(now, msg, who)
            for x in reversed(again):
                q.put(now, "MISSION_ITEM_INT", x, first=True)
            for x in reversed(lost):
                q.put(now, "MISSION_REQUEST_INT", x, first=True)
            first += [_describe(x) for x in again + lost]
            for x in ahead:
                q.put(now, "MISSION_REQUEST_INT", x)
                up.append(_describe(x))
            st += [_describe(pack((1, 1), r)) for r in reqs]
            for r in reqs:
                to_station.append((now + 0.01, who, r))
            fwd = fwd and passed
        if fwd and who in stations:
            to_station.append((now + 0.01, who, msg))
        return f"{int(fwd)} st[{','.join(st)}] first[{','.join(first)}] up[{','.join(up)}]"

    def gcs_frame(now: float, who: tuple[int, int], msg: Any) -> None:
        f = pack(who, msg)
        lines.append(f"gcs {round(now * 1e6)} {who[0] * 256 + who[1]} {f.hex()}")
        msg = decode(f)
        st: list[str] = []
        up: list[bytes] = []
        wanted: list[bytes] = []
        fwd = True
        if msg.NAME.startswith("MISSION_"):
            fwd, answers, wanted, ahead = downloads.from_gcs(now, msg, who)
            st += [_describe(bytes(a.get_msgbuf())) for a in answers]
            for a in answers:
                to_station.append((now + 0.01, who, a))
            for x in reversed(wanted):
                q.put(now, "MISSION_REQUEST_INT", x, first=True)
            up += ahead
        if fwd:
            if msg.NAME == "PARAM_REQUEST_LIST":
                params.request(now, who)
            up.append(f)
        for x in up:
            q.put(now, decode(x).NAME, x)
        if fwd:
            reqs = missions.from_gcs(now, msg, who, f)
            st += [_describe(pack((1, 1), r)) for r in reqs]
            for r in reqs:
                to_station.append((now + 0.01, who, r))
        python.append(f"{int(fwd)} st[{','.join(st)}] first[{','.join(_describe(x) for x in wanted)}] "
                      f"up[{','.join(_describe(x) for x in up)}]")

    def vehicle_gets(now: float, f: bytes) -> None:
        msg = decode(f)
        src = (f[5], f[6])
        n = msg.NAME
        if n == "MISSION_COUNT":
            vup[src] = [msg.count, 0, msg.mission_type]
            veh_send(now, common.MAVLink_mission_request_int_message(src[0], src[1], 0, msg.mission_type))
        elif n == "MISSION_ITEM_INT" and src in vup:
            u = vup[src]
            if msg.seq == u[1]:
                u[1] += 1
            if u[1] >= u[0]:
                vplan[u[2]] = u[0]
                del vup[src]
                veh_send(now, common.MAVLink_mission_ack_message(src[0], src[1], 0, u[2]))
            elif msg.seq >= u[1] - 1:
                veh_send(now, common.MAVLink_mission_request_int_message(src[0], src[1], u[1], u[2]))
        elif n == "MISSION_REQUEST_LIST":
            veh_send(now, common.MAVLink_mission_count_message(src[0], src[1], vplan.get(msg.mission_type, 0),
                                                                msg.mission_type))
        elif n == "MISSION_REQUEST_INT":
            if msg.seq < vplan.get(msg.mission_type, 0):
                veh_send(now, common.MAVLink_mission_item_int_message(
                    src[0], src[1], msg.seq, 6, 16, 0, 1, 0, 0, 0, 0, 460503000 + msg.seq, 144686000, 5.0,
                    msg.mission_type))
        elif n == "PARAM_REQUEST_LIST":
            for i in range(21):
                veh_send(now + i * 0.02, common.MAVLink_param_value_message(b"P%d" % i, float(i), 9, 21, i))
        elif n == "PARAM_REQUEST_READ":
            i = msg.param_index
            veh_send(now, common.MAVLink_param_value_message(b"P%d" % i, float(i), 9, 21, i))

    def station_gets(now: float, who: tuple[int, int], msg: Any) -> None:
        n = msg.NAME
        if n == "MISSION_REQUEST_INT" and msg.target_system == who[0] and stations[who].get("count"):
            stations[who]["asked"] = now
            if msg.seq < stations[who]["count"] and rnd.random() < 0.95:
                gcs_frame(now, who, common.MAVLink_mission_item_int_message(
                    1, 1, msg.seq, 6, 16, 0, 1, 0, 0, 0, 0, 460503000 + msg.seq, 144686000, 5.0, msg.mission_type))
        elif n == "MISSION_ACK":
            stations[who]["count"] = 0
        elif n == "MISSION_COUNT" and msg.count:
            for s in range(msg.count):  # a download: asked for item by item, as it comes
                stations[who].setdefault("want", []).append(s)

    t = 0.0
    next_tick = next_pull = 0.0
    while t < 90.0:
        t = round(t + rnd.uniform(0.002, 0.03), 6)  # (the script's microseconds)
        while next_pull <= t:  # the scheduler pulls; what it takes reaches the vehicle 50 ms later, or is lost
            lines.append(f"pull {round(next_pull * 1e6)}")
            got = q.pull(next_pull, 100)
            python.append(f"pull {_describe(got) if got is not None else '-'}")
            if got is not None and rnd.random() < 0.9:
                to_vehicle.append((next_pull + 0.05, got))
            next_pull = round(next_pull + 0.05 + rnd.randint(1, 3000) / 1e6, 6)
        while next_tick <= t:
            lines.append(f"tick {round(next_tick * 1e6)}")
            again = missions.tick(next_tick)
            for x in reversed(again):  # (ahead of what waits, in their order)
                q.put(next_tick, decode(x).NAME, x, first=True)
            asks = missions.ahead_requests(next_tick)
            st = [_describe(pack((1, 1), r)) for _, r in asks]
            for w, r in asks:  # (the next items, asked of their stations)
                to_station.append((next_tick + 0.01, w, r))
            reads = [pack(who, common.MAVLink_param_request_read_message(1, 1, b"", i))
                     for who, i in params.tick(next_tick)]
            for x in reads:
                q.put(next_tick, decode(x).NAME, x)
            python.append(f" st[{','.join(st)}] first[{','.join(_describe(x) for x in again)}] "
                          f"up[{','.join(_describe(x) for x in reads)}]")
            next_tick = round(next_tick + 0.1 + rnd.randint(1, 3000) / 1e6, 6)  # (never exactly a bound apart)
        for arrives, f in sorted(x for x in to_vehicle if x[0] <= t):
            to_vehicle.remove((arrives, f))
            vehicle_gets(t, f)
        for item in [x for x in to_station if x[0] <= t]:
            to_station.remove(item)
            station_gets(t, item[1], item[2])
        who = rnd.choice(list(stations))
        s = stations[who]
        r = rnd.random()
        if r < 0.004 and not s.get("count"):
            s["count"] = rnd.randint(1, 25)
            gcs_frame(t, who, common.MAVLink_mission_count_message(1, 1, s["count"], rnd.choice([0, 0, 2])))
        elif r < 0.006:
            gcs_frame(t, who, common.MAVLink_mission_request_list_message(1, 1, rnd.choice([0, 0, 2])))
        elif r < 0.008:
            gcs_frame(t, who, common.MAVLink_param_request_list_message(1, 1))
        elif r < 0.06 and s.get("want"):
            gcs_frame(t, who, common.MAVLink_mission_request_int_message(1, 1, s["want"].pop(0), 0))
        elif r < 0.062 and s.get("count") and t - s.get("asked", 0.0) > 1.5:  # its retry, when not asked
            gcs_frame(t, who, common.MAVLink_mission_count_message(1, 1, s["count"], 0))  # for an item (QGC: 1.5 s)
    python.append(f"resent {missions.resent} swallowed {missions.swallowed} answered {downloads.answered} "
                  f"read {params.read}")
    proc = subprocess.run(["java", "-cp", str(classes), "ProtocolScript"], input="budget 250 100\n" + "\n".join(lines)
                          + "\n", capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    java = proc.stdout.splitlines()
    differ = [(i, lines[i] if i < len(lines) else "", j, p)
              for i, (j, p) in enumerate(zip(java, python, strict=False)) if j != p]
    assert len(java) == len(python) and not differ, differ[:3]
    if seed == 29:  # (the script did exercise every rule: items lost and sent again, downloads, lists)
        assert missions.resent > 3 and missions.swallowed > 50 and downloads.answered > 5 and params.read > 0, \
            python[-1]
