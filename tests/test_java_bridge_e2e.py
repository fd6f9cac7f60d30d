"""The Java runtime's GcsBridge flying the vehicle for pymavlink ground stations, real processes
end to end (issue 22):

    pymavlink GCS (udpin, 255/190: QGC's ids) <-> [BridgeDriver: Session + GcsBridge on a UdpLink]
        <-> ttctl link relay --profile m100 --loss 0.1 <-> ttctl emulate onboard --no-gcs

The driver is tests/java/gcs/BridgeDriver.java; a second ground station (245/190, MAVSDK-like)
sends first to the bridge's listening port. pymavlink is the ground station and the oracle."""

from __future__ import annotations

import math
import os
import shutil
import socket
import subprocess
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from conformance_lib import build_java
from conftest import ROOT
from e2e_lib import LOCAL, Start, free_port, relay
from machine import busy, scaled

pytestmark = pytest.mark.skipif(not (shutil.which("javac") and shutil.which("java")),
                                reason="needs a JDK (javac, java)")

os.environ["MAVLINK20"] = "1"
from pymavlink import mavutil  # noqa: E402  (MAVLINK20 must be set first)

RELAY = ("--profile", "m100", "--loss", "0.1", "--seed", "5", "--stats-interval", "0")
RATE = 480  # B/s: the app's pace into the relay's m100 uplink (500 B/s at 10 m)
ACCEPTED = 0


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    cls, _ = build_java(tmp_path_factory.mktemp("gcs_bridge"), [ROOT / "tests" / "java" / "gcs" / "BridgeDriver.java"])
    return cls


class Gcs:
    """A pymavlink ground station: HEARTBEAT (MAV_TYPE_GCS) every second, everything it
    receives kept with its arrival time."""

    def __init__(self, device: str, sysid: int, compid: int) -> None:
        self.m: Any = mavutil.mavlink_connection(device, source_system=sysid, source_component=compid,
                                                 dialect="common")
        self.ids = (sysid, compid)
        self.seen: list[tuple[float, Any]] = []
        self.next_hb = 0.0

    def heartbeat(self) -> None:
        now = time.monotonic()
        if now >= self.next_hb:
            self.m.mav.heartbeat_send(6, 8, 0, 0, 0)  # MAV_TYPE_GCS, MAV_AUTOPILOT_INVALID
            self.next_hb = now + 1.0

    def wait(self, pred: Callable[[Any], bool], timeout: float, resend: Callable[[], None] | None = None,
             every: float = 1.5) -> Any:
        """Receives until `pred` holds for a message (returned) or `timeout` (None), calling
        `resend` every `every` s meanwhile, as a ground station retries."""
        end = time.monotonic() + timeout
        last = -math.inf
        while time.monotonic() < end:
            self.heartbeat()
            if resend is not None and time.monotonic() - last >= every:
                resend()
                last = time.monotonic()
            msg = self.m.recv_match(blocking=True, timeout=0.05)
            if msg is None or msg.get_type() == "BAD_DATA":
                continue
            self.seen.append((time.monotonic(), msg))
            if pred(msg):
                return msg
        return None

    def pump(self, seconds: float) -> None:
        self.wait(lambda m: False, seconds)

    def of(self, kind: str) -> list[tuple[float, Any]]:
        return [(t, m) for t, m in self.seen if m.get_type() == kind]

    def command(self, cmd: int, *params: float, timeout: float = 12.0) -> tuple[Any, int]:
        """COMMAND_LONG to the vehicle, retried every 1.5 s with the next confirmation, as QGC
        does: (the first COMMAND_ACK for it, or None; tries sent)."""
        p = list(params) + [0.0] * (7 - len(params))
        tries = [0]

        def send() -> None:
            self.m.mav.command_long_send(1, 1, cmd, tries[0], *p)
            tries[0] += 1

        return self.wait(lambda m: m.get_type() == "COMMAND_ACK" and m.command == cmd, timeout, send), tries[0]


class Driver:
    def __init__(self, classes: Path, tmp: Path, relay_port: int, gcs_port: int, listen_port: int,
                 *key: str) -> None:
        self.err = open(tmp / "driver.err", "w")  # noqa: SIM115
        self.p = subprocess.Popen(["java", "-cp", str(classes), "BridgeDriver", str(relay_port), str(gcs_port),
                                   str(listen_port), str(RATE), *key], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                  stderr=self.err, text=True)
        assert self.line("ready").startswith("ready")

    def line(self, prefix: str, timeout: float = 30) -> str:
        timeout = scaled(timeout)  # longer on a busy machine
        assert self.p.stdout is not None
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            ln = self.p.stdout.readline()
            if not ln:
                break
            if ln.startswith(prefix):
                return ln.strip()
            assert not ln.startswith("EVENT uncaught"), ln
        raise AssertionError(f"no {prefix!r} from the driver")

    def ask(self, cmd: str) -> None:
        assert self.p.stdin is not None
        self.p.stdin.write(cmd + "\n")
        self.p.stdin.flush()

    def stats(self) -> dict[str, int]:
        self.ask("stats")
        return {k: int(v) for k, v in (kv.split("=") for kv in self.line("STATS").split()[1:])}

    def latencies(self) -> tuple[list[float], list[float], int]:
        """(each command's time to its ack, its last try's round trip, commands failed)."""
        ln = self.line("LAT", timeout=60)
        total, rest = ln[4:].split(" TRY ", 1)
        tries, errors = rest.rsplit(" errors ", 1)

        def ms(x: str) -> list[float]:
            return [float(v) for v in x.strip("[] ").split(",") if v]

        return ms(total), ms(tries), int(errors)

    def close(self) -> str:
        out, _ = self.p.communicate(timeout=20)
        self.err.close()
        return out


def p95(xs: list[float]) -> float:
    s = sorted(xs)
    return s[min(len(s) - 1, math.ceil(0.95 * len(s)) - 1)]


def test_java_bridge_flies_for_pymavlink(classes: Path, tmp_path: Path, start: Start) -> None:
    """Through the Java bridge at 10 % loss a ground station with QGroundControl's ids sees the
    vehicle's HEARTBEAT and a RADIO_STATUS from (1, 68) about once a second, reads a parameter,
    arms and takes off (COMMAND_ACK ACCEPTED, the altitude rising), uploads a 5-item mission; a
    second ground station on the listening port gets its own answers; garbage and frames for
    system 7 change nothing; a 5-second flood of 50 Hz MANUAL_CONTROL and PARAM_REQUEST_LIST
    leaves the app's command latency within its idle p95 + 200 ms and the bridge's queue bounded;
    the radio killed for 6 s shows as RADIO_STATUS rssi 0 and no HEARTBEAT, and both return with it."""
    a, b, gcs_port, listen = free_port(), free_port(), free_port(), free_port()
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{b}", "--no-entry-points",
                 "--profile", "m100")
    node.wait_for("onboard 1:")
    radio = [relay(start, a, b, *RELAY)]

    def outage(seconds: float) -> float:
        """Kills the relay (the radio), then starts it again on the same ports; the time it died."""
        radio[-1].kill()
        died = time.monotonic()
        qgc.pump(seconds)
        radio.append(start("relay2", "link", "relay", "--listen", f"udp:{LOCAL}:{a}", "--to", f"udp:{LOCAL}:{b}",
                           *RELAY, "--seed", "6"))  # the same loss, not the same losses again
        radio[-1].wait_for("relay: udpin")
        return died

    qgc = Gcs(f"udpin:{LOCAL}:{gcs_port}", 255, 190)
    drv = Driver(classes, tmp_path, a, gcs_port, listen)
    try:
        _fly(qgc, drv, listen, outage)
    finally:
        if drv.p.poll() is None:
            out = drv.close()
            assert "closed []" in out, out  # no problem reported
        qgc.m.close()


def _fly(qgc: Gcs, drv: Driver, listen: int, outage: Callable[[float], float]) -> None:
    t0 = time.monotonic()
    hb = qgc.wait(lambda m: m.get_type() == "HEARTBEAT" and (m.get_srcSystem(), m.get_srcComponent()) == (1, 1), 20)
    assert hb is not None, [m.get_type() for _, m in qgc.seen][-20:]
    assert hb.type != 6 and hb.autopilot != 8  # the vehicle, not a ground station's echo
    heard = time.monotonic()

    # a parameter by name
    value = qgc.wait(lambda m: m.get_type() == "PARAM_VALUE" and m.param_id == "MIS_TAKEOFF_ALT", 15,
                     lambda: qgc.m.mav.param_request_read_send(1, 1, b"MIS_TAKEOFF_ALT", -1))
    assert value is not None and value.param_value == pytest.approx(2.0)

    # arm and take off
    ack, _ = qgc.command(400, 1)
    assert ack is not None and ack.result == ACCEPTED and ack.target_system == 255 and ack.target_component == 190
    took = time.monotonic()
    ack, tries = qgc.command(22, 0, 0, 0, float("nan"), float("nan"), float("nan"), float("nan"))
    # a retry (its first try's ack lost) gets the answer the first try got, not a second take-off
    assert ack is not None and ack.result == ACCEPTED, (ack, tries)
    high = qgc.wait(lambda m: m.get_type() == "GLOBAL_POSITION_INT" and m.relative_alt > 1500, 20)
    assert high is not None
    alts = [m.relative_alt for t, m in qgc.of("GLOBAL_POSITION_INT") if t >= took]
    assert alts[0] < 500 and alts[-1] > alts[0] + 1000, alts  # from the ground up

    # a 5-item mission
    items = 5
    seqs: list[int] = []

    def count() -> None:
        qgc.m.mav.mission_count_send(1, 1, items, 0)

    mission_t0 = time.monotonic()
    req = qgc.wait(lambda m: m.get_type() in ("MISSION_REQUEST_INT", "MISSION_REQUEST"), 15, count)
    done = None
    while req is not None and done is None:
        n = req.seq
        seqs.append(n)

        def item(n: int = n) -> None:
            qgc.m.mav.mission_item_int_send(1, 1, n, 6, 16, 0, 1, 0, 0, 0, math.nan,
                                            int((46.0503 + 0.0002 * n) * 1e7), int(14.4686 * 1e7), 10, 0)

        def moved(m: Any, n: int = n) -> bool:
            return (m.get_type() in ("MISSION_REQUEST_INT", "MISSION_REQUEST") and m.seq != n) \
                or m.get_type() == "MISSION_ACK"

        nxt = qgc.wait(moved, 15, item)
        if nxt is not None and nxt.get_type() == "MISSION_ACK":
            done = nxt
        req = nxt
    assert done is not None and done.type == ACCEPTED and sorted(set(seqs)) == list(range(items)), (seqs, done)
    print(f"mission of {items} items uploaded in {time.monotonic() - mission_t0:.1f} s")

    # a second ground station (245/190) that sends first, to the listening port
    mavsdk = Gcs(f"udpout:{LOCAL}:{listen}", 245, 190)
    try:
        ack2, _ = mavsdk.command(512, 148)  # MAV_CMD_REQUEST_MESSAGE AUTOPILOT_VERSION
        assert ack2 is not None and ack2.target_system == 245 and ack2.result == ACCEPTED
        mavsdk.pump(1.5)
        assert mavsdk.of("RADIO_STATUS") and mavsdk.of("HEARTBEAT")
    finally:
        mavsdk.m.close()
    qgc.pump(0.5)
    acks = [m for _, m in qgc.of("COMMAND_ACK")]
    assert acks and all(m.target_system == 255 for m in acks), acks  # 245's ack did not come here

    # strangers: garbage and frames for system 7, to both of the bridge's addresses
    before = drv.stats()
    junk = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    enc = mavutil.mavlink.MAVLink(None, srcSystem=255, srcComponent=190)
    for i in range(5):
        junk.sendto(bytes([0xFD, 9, 0, 0, i]) + os.urandom(30), (LOCAL, listen))
        junk.sendto(enc.command_long_encode(7, 1, 400, 0, 0, 0, 0, 0, 0, 0, 0).pack(enc), (LOCAL, listen))
    junk.close()
    qgc.pump(1.0)
    after = drv.stats()
    assert after["notCarried"] - before["notCarried"] == 10 and after["unknown"] - before["unknown"] == 5, after
    armed = qgc.wait(lambda m: m.get_type() == "HEARTBEAT" and m.get_srcSystem() == 1 and m.get_srcComponent() == 1,
                     5)
    assert armed is not None and armed.base_mode & 128, armed  # still armed: the disarm for 7 was not carried

    # RADIO_STATUS from (1, 68), about once a second since the start
    radio = qgc.of("RADIO_STATUS")
    span = radio[-1][0] - radio[0][0]
    assert all((m.get_srcSystem(), m.get_srcComponent()) == (1, 68) for _, m in radio)
    assert span > 5 and 0.7 * span <= len(radio) - 1 <= 1.3 * span + 1, (len(radio), span)
    # once the vehicle is heard (a second for its frames to fill the window): 10 % loss, not silence
    assert all(m.rssi == m.remrssi and 150 <= m.rssi <= 254 for t, m in radio if t > heard + 1.0), \
        [(round(t - heard, 1), m.rssi) for t, m in radio]

    # the radio lost for 6 s: RADIO_STATUS says rssi 0 within 3.5 s (+ its second) and the
    # vehicle's HEARTBEATs stop; when it returns, both come back
    died = outage(6.0)
    after_death = [(t, m) for t, m in qgc.seen if t > died]
    zero = [t - died for t, m in after_death if m.get_type() == "RADIO_STATUS" and m.rssi == 0]
    assert zero and zero[0] <= 3.5 + 1.5, [(round(t - died, 1), m.rssi) for t, m in after_death
                                           if m.get_type() == "RADIO_STATUS"]
    beats = [t - died for t, m in after_death if m.get_type() == "HEARTBEAT" and m.get_srcComponent() == 1]
    assert not beats or max(beats) < 1.0, beats  # at most what was already on its way
    back = qgc.wait(lambda m: m.get_type() == "RADIO_STATUS" and m.rssi > 0, 10)
    assert back is not None
    assert qgc.wait(lambda m: m.get_type() == "HEARTBEAT" and m.get_srcSystem() == 1 and m.get_srcComponent() == 1, 5)

    # the app's command latency, idle, then under a ground station's floods
    qgc.pump(2.0)
    drv.ask("lat 8")
    qgc.pump(8.5)
    idle_total, idle, idle_errors = drv.latencies()
    assert len(idle) >= 10 and idle_errors == 0, (idle_total, idle)
    sticks = _flood(qgc, drv, params=False)
    assert len(sticks["lat"]) >= 8, sticks
    # the round trip of the try that was answered: the radio's loss decides how many tries a
    # command takes (a few of 20 at 10 % loss both ways), the bridge's traffic how long each takes
    assert p95(sticks["try"]) <= p95(idle) + 200 * busy(), (sorted(idle), sticks)
    both = _flood(qgc, drv, params=True)
    s = both["stats"]
    assert s["peak"] <= GcsLimit and s["duplicates"] - sticks["stats"]["duplicates"] > 50, s
    assert s["replaced"] - sticks["stats"]["replaced"] > 50 and s["uncaught"] == 0 and s["problems"] == 0, s
    print(f"took {time.monotonic() - t0:.1f} s; idle p95 {p95(idle):.0f} ms ({p95(idle_total):.0f} ms with "
          f"retries); sticks {sticks}; both {both}")
    # each PARAM_REQUEST_LIST carried makes the vehicle send its whole list down; those answers wait
    # below the app's acks at the onboard end, and a list still waiting is not queued again there
    assert len(both["try"]) >= 5 and p95(both["try"]) <= p95(idle) + 200 * busy(), (sorted(idle), both)


GcsLimit = 128  # GcsUplink.PROTOCOL_LIMIT + NEWEST_LIMIT
FLOOD_S = 8


def _flood(qgc: Gcs, drv: Driver, params: bool) -> dict[str, Any]:
    """8 s of 50 Hz MANUAL_CONTROL (and PARAM_REQUEST_LIST as often, with `params`) while the
    app sends its commands (a command that takes three tries at 10 % loss takes 3.7 s of them);
    the uplink's GCS bytes stay within the default share (0.8) of the app's pace."""
    before = drv.stats()
    drv.ask(f"lat {FLOOD_S}")
    start = time.monotonic()
    end = start + FLOOD_S
    nxt = start
    while time.monotonic() < end:
        qgc.m.mav.manual_control_send(1, 0, 0, 500, 0, 0)
        if params:
            qgc.m.mav.param_request_list_send(1, 1)
        nxt += 0.02
        qgc.wait(lambda m: False, max(0.0, nxt - time.monotonic()))
    lat, tries, errors = drv.latencies()
    took = time.monotonic() - start
    after = drv.stats()
    assert errors == 0, (lat, errors, (drv.err.flush(), Path(drv.err.name).read_text()[-600:])[1])
    assert after["carriedBytes"] - before["carriedBytes"] <= 0.8 * RATE * took + 100, (before, after, took)
    values = len([1 for t, _ in qgc.of("PARAM_VALUE") if t > start])
    return {"lat": sorted(lat), "try": sorted(tries), "stats": after, "param_values": values}


def test_java_bridge_on_a_signed_link(classes: Path, tmp_path: Path, start: Start) -> None:
    """The onboard end started with --key takes only signed frames: a ground station's frames,
    unsigned at the bridge, reach the vehicle and are answered because the app's scheduler signs
    them as they leave (and the vehicle's signed answers come down to the ground station unsigned)."""
    a, b, gcs_port, listen = free_port(), free_port(), free_port(), free_port()
    key = tmp_path / "key"
    key.write_text("our secret\n")  # a passphrase: its SHA-256 is the key, as Signing.keyFromPassphrase's
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{b}", "--no-entry-points",
                 "--profile", "m100", "--key", str(key))
    node.wait_for("onboard 1:")
    relay(start, a, b, "--profile", "m100", "--stats-interval", "0")
    qgc = Gcs(f"udpin:{LOCAL}:{gcs_port}", 255, 190)
    drv = Driver(classes, tmp_path, a, gcs_port, listen, "our secret")
    try:
        hb = qgc.wait(lambda m: m.get_type() == "HEARTBEAT" and (m.get_srcSystem(), m.get_srcComponent()) == (1, 1),
                      20)
        assert hb is not None, [m.get_type() for _, m in qgc.seen][-20:]
        value = qgc.wait(lambda m: m.get_type() == "PARAM_VALUE" and m.param_id == "MPC_XY_VEL_MAX", 10,
                         lambda: qgc.m.mav.param_request_read_send(1, 1, b"MPC_XY_VEL_MAX", -1))
        assert value is not None and value.param_value == pytest.approx(1.5)
        assert all(not m.get_signed() for _, m in qgc.seen)  # unsigned at the ground station's side
        s = drv.stats()
        assert s["carried"] > 0 and s["problems"] == 0 and s["uncaught"] == 0, s
        assert "signature" not in node.stderr and "unsigned" not in node.stderr, node.stderr
    finally:
        out = drv.close()
        qgc.m.close()
    assert "closed []" in out, out
