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
    drivers = [ROOT / "tests" / "java" / "gcs" / f"{n}.java" for n in ("GcsCheck", "UplinkScript", "QualityScript")]
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
