"""Real ground stations, unmodified, through the tablet's bridge (issue 22): MAVSDK, MAVProxy and
pymavlink on `ttctl emulate tablet --gcs udpout:...`, which carries them over the emulated DJI
radio (`ttctl link relay --profile m100 --loss 0.1`, random loss for some, bursts for others) to
`ttctl emulate onboard --no-gcs`, all real processes on loopback. What they were told is checked
against what the vehicle did (armed, altitude, the mission read back, the file's hash)."""

from __future__ import annotations

import asyncio
import functools
import hashlib
import json
import math
import os
import re
import signal
import struct
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

os.environ.setdefault("MAVLINK20", "1")  # before pymavlink is imported: ground stations speak MAVLink 2

from e2e_lib import LOCAL, Proc, Start, data_file, free_port, run_mavproxy, until
from machine import scaled
from mavsdk_child import fly

M_PER_DEG = 111_319.5
HOME = (46.0503, 14.4686)
IDLE_SCRIPT = "- wait: 0.5\n"  # the tablet's own part when only ground stations fly


@dataclass
class Chain:
    """ground stations -> tablet (bridge) -> relay (m100, lossy) -> onboard end."""

    start: Start
    air: int  # the relay's listening port (the tablet's --to)
    dtt: int  # the onboard end's listening port (the relay's --to)
    gcs: list[int]  # the bridge's --gcs udpout ports (each ground station listens on one)
    relay_args: list[str]
    onboard: Proc
    loss: str = "0.1"
    relay: Proc | None = None
    tablet: Proc | None = None

    def start_relay(self, name: str = "relay") -> Proc:
        self.relay = self.start(name, "link", "relay", "--listen", f"udp:{LOCAL}:{self.air}", "--to",
                                f"udp:{LOCAL}:{self.dtt}", "--profile", "m100", "--loss", self.loss,
                                "--stats-interval", "0", *self.relay_args)
        self.relay.wait_for("relay: udpin")
        return self.relay

    def stop_tablet(self) -> str:
        """SIGINT to the tablet: it ends (exit 0) with its one-line summary of what it carried."""
        assert self.tablet is not None
        self.tablet.signal(signal.SIGINT)
        assert self.tablet.wait(15) == 0, self.tablet.stderr
        (line,) = [x for x in self.tablet.stderr.splitlines() if "tablet: ground stations:" in x]
        return line


def chain(start: Start, tmp: Path, stations: int = 1, model: str = "random", seed: int = 1,
          script: str = IDLE_SCRIPT, onboard: tuple[str, ...] = (), tablet: tuple[str, ...] = (),
          loss: str = "0.1") -> Chain:
    air, dtt = free_port(), free_port()
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{dtt}", "--profile",
                 "m100", "--no-entry-points", "--speed", "4", *onboard)
    node.wait_for("onboard 1:")
    c = Chain(start, air, dtt, [free_port() for _ in range(stations)],
              ["--loss-model", model, "--seed", str(seed)], node, loss)
    c.start_relay()
    (tmp / "tablet.yaml").write_text(script)
    gcs = [a for port in c.gcs for a in ("--gcs", f"udpout:{LOCAL}:{port}")]
    c.tablet = start("tablet", "emulate", "tablet", "--to", f"udpout:{LOCAL}:{air}", "--profile", "m100",
                     "--script", str(tmp / "tablet.yaml"), "--json", *gcs, *tablet)
    c.tablet.wait_for("carrying ground stations at")
    return c


class Gcs:
    """A pymavlink ground station listening where the bridge sends (udpin), as QGroundControl
    listens on 14550: a HEARTBEAT (MAV_TYPE_GCS) a second, commands retried as ground stations
    retry them, everything it receives kept in `seen`. One thread drives it."""

    def __init__(self, port: int, sysid: int = 255, compid: int = 190) -> None:
        from pymavlink import mavutil

        self.m = mavutil.mavlink
        self.conn = mavutil.mavlink_connection(f"udpin:{LOCAL}:{port}", source_system=sysid,
                                               source_component=compid, dialect="common")
        self.seen: list[tuple[float, Any]] = []
        self._beat = 0.0
        self.beating = True

    def close(self) -> None:
        self.conn.close()

    def pump(self, seconds: float, pred: Callable[[Any], bool] | None = None) -> Any:
        """Receive (and beat) for `seconds`, or until a message satisfies `pred`: that message."""
        end = time.monotonic() + seconds
        while True:
            now = time.monotonic()
            # udpin: it answers the address it heard, so it beats once the bridge sent it something
            if self.beating and now >= self._beat and self.conn.clients:
                self._beat = now + 1.0
                self.conn.mav.heartbeat_send(self.m.MAV_TYPE_GCS, self.m.MAV_AUTOPILOT_INVALID, 0, 0, 4)
            if now >= end:
                return None
            msg = self.conn.recv_match(blocking=True, timeout=min(0.1, end - now))
            if msg is None or msg.get_type() == "BAD_DATA":
                continue
            self.seen.append((time.monotonic(), msg))
            if pred is not None and pred(msg):
                return msg

    def wait(self, kind: str, cond: Callable[[Any], bool] = lambda m: True, timeout: float = 10.0) -> Any:
        timeout = scaled(timeout)  # longer on a busy machine
        msg = self.pump(timeout, lambda m: m.get_type() == kind and cond(m))
        assert msg is not None, f"no {kind} as asked in {timeout} s"
        return msg

    def vehicle(self, kind: str, cond: Callable[[Any], bool] = lambda m: True, timeout: float = 10.0) -> Any:
        """The vehicle's (1/1) next `kind` that satisfies `cond`."""
        return self.wait(kind, lambda m: m.get_srcSystem() == 1 and m.get_srcComponent() == 1 and cond(m), timeout)

    def command(self, cmd: int, *p: float, tries: int = 6, every: float = 1.5, resend: bool = False) -> int:
        """COMMAND_LONG to 1/1, resent (confirmation counting up) until its COMMAND_ACK: the result.
        `resend`: its first send is already a resend (confirmation 1), as after an ack lost."""
        args = list(p) + [0.0] * (7 - len(p))
        for i in range(int(resend), tries + int(resend)):
            self.conn.mav.command_long_send(1, 1, cmd, i, *args)
            ack = self.pump(every, lambda m: m.get_type() == "COMMAND_ACK" and m.command == cmd)
            if ack is not None:
                return int(ack.result)
        raise AssertionError(f"no COMMAND_ACK for command {cmd} after {tries} sends")

    def param(self, name: str, tries: int = 6) -> float:
        for _ in range(tries):
            self.conn.mav.param_request_read_send(1, 1, name.encode(), -1)
            msg = self.pump(1.5, lambda m: m.get_type() == "PARAM_VALUE" and m.param_id == name)
            if msg is not None:
                return float(msg.param_value)
        raise AssertionError(f"no PARAM_VALUE {name} after {tries} requests")

    def param_int(self, name: str) -> int:
        """An integer parameter: its bytes in PARAM_VALUE's float (PX4's bytewise encoding)."""
        return int(struct.unpack("<i", struct.pack("<f", self.param(name)))[0])

    def armed(self) -> bool:
        hb = self.vehicle("HEARTBEAT", timeout=4)
        return bool(hb.base_mode & self.m.MAV_MODE_FLAG_SAFETY_ARMED)

    def received(self, kind: str, src: tuple[int, int] | None = None, since: float = 0.0) -> list[Any]:
        return [m for t, m in self.seen if t >= since and m.get_type() == kind
                and (src is None or (m.get_srcSystem(), m.get_srcComponent()) == src)]


def take_off(gcs: Gcs, node: Proc, metres: float) -> None:
    """NAV_TAKEOFF from pymavlink as QGroundControl sends it (NaN yaw, lat, lon), resent until
    acknowledged: ACCEPTED even when a resend is what got through, and the vehicle climbs."""
    m = gcs.m
    result = gcs.command(m.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, math.nan, math.nan, math.nan, 295 + metres)
    assert result == m.MAV_RESULT_ACCEPTED, node.stderr
    gcs.vehicle("GLOBAL_POSITION_INT", lambda p: p.relative_alt > 0.6 * metres * 1000, timeout=20)


def is_item(seq: int, msg: Any) -> bool:
    return bool(msg.seq == seq)


def no_traceback(*procs: Proc | None) -> None:
    for p in procs:
        if p is not None:
            assert "Traceback" not in p.stderr + p.stdout, p.stderr


_until = functools.partial(until, poll=0.1)


async def persevere(go: Callable[[], Any], keep: bool = False, attempts: int = 3) -> Any:
    """A mission transfer as a user does it: tried again when MAVSDK gives up (TIMEOUT: its final
    MISSION_ACK lost, say, or its ~2.5 s retry budget run out). The seconds of the try that
    succeeded and what the failed ones said (and its value with `keep`)."""
    from mavsdk.plugins.mission import MissionError

    failed: list[str] = []
    for _ in range(attempts):
        t0 = time.monotonic()
        try:
            value = await go()
        except MissionError as e:
            failed.append(f"{str(e).split(';')[0]} after {time.monotonic() - t0:.1f} s")
            continue
        took = (time.monotonic() - t0, failed)
        return (took, value) if keep else took
    raise AssertionError(f"{attempts} mission transfers failed: {failed}")


async def again(action: Callable[[], Any], attempts: int = 3) -> Any:
    """A MAVSDK call tried again after a TIMEOUT (MAVSDK resends a command 3 times 0.5 s apart, and a
    parameter's PARAM_SET or read as often, which a burst of loss can swallow): what its user does.
    Action's parameter calls (`set_takeoff_altitude`) report that timeout as PARAMETER_ERROR. Any
    other error fails at once. Its value."""
    from mavsdk.plugins.action import ActionError
    from mavsdk.plugins.mission import MissionError
    from mavsdk.plugins.param import ParamError

    for i in range(attempts):
        try:
            return await action()
        except (ActionError, MissionError, ParamError) as e:
            lost = "TIMEOUT" in str(e) or (isinstance(e, ActionError) and "PARAMETER_ERROR" in str(e))
            if not lost or i == attempts - 1:
                raise
    return None


def test_mavsdk_default_configuration_connects_through_the_bridge(tmp_path: Path, start: Start) -> None:
    """MAVSDK's default ground-station configuration sends nothing until it has heard a vehicle's
    HEARTBEAT; the vehicle behind the tablet must therefore be heard before any ground station spoke."""
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")

    c = chain(start, tmp_path, seed=2)

    async def main(m: Any) -> float:
        t0 = time.monotonic()
        await m.add_any_connection(f"udpin://{LOCAL}:{c.gcs[0]}")
        system = await m.first_autopilot(timeout_s=10)
        assert system is not None, f"no autopilot in 10 s; the tablet carried: {c.stop_tablet()}"
        assert await system.get_system_id() == 1
        return time.monotonic() - t0

    print(f"\nMAVSDK (default configuration) connected through the bridge in {fly(main, 60):.1f} s")


# -- 1. MAVSDK ------------------------------------------------------------------------------------
@pytest.mark.parametrize("model", ["random", "burst"])
def test_mavsdk_flies_a_mission_through_the_bridge(tmp_path: Path, start: Start, model: str) -> None:
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")
    from mavsdk.asyncio.plugins.action import ActionAsync
    from mavsdk.asyncio.plugins.mission import MissionAsync
    from mavsdk.asyncio.plugins.param import ParamAsync
    from mavsdk.asyncio.plugins.telemetry import TelemetryAsync
    from mavsdk.plugins.mission import MissionItem, MissionPlan
    from mavsdk.plugins.telemetry import FlightMode

    c = chain(start, tmp_path, model=model, seed=3)

    async def main(m: Any) -> tuple[dict[str, float], dict[str, list[str]]]:
        times: dict[str, float] = {}
        tries: dict[str, list[str]] = {}
        t0 = time.monotonic()
        await m.add_any_connection(f"udpin://{LOCAL}:{c.gcs[0]}")
        system = await m.first_autopilot(timeout_s=10)
        times["connect"] = time.monotonic() - t0
        assert system is not None and await system.get_system_id() == 1
        tel, act, par, mis = TelemetryAsync(system), ActionAsync(system), ParamAsync(system), MissionAsync(system)
        home = await _until(tel.home, lambda h: abs(h.latitude_deg - HOME[0]) < 1e-6, 15)
        pos = await _until(tel.position, lambda p: abs(p.latitude_deg - home.latitude_deg) < 1e-6, 15)
        assert pos.relative_altitude_m < 0.1
        assert not await tel.armed()
        assert await tel.flight_mode() == FlightMode.HOLD
        await _until(tel.health, lambda h: h.is_armable and h.is_global_position_ok, 15)
        assert await again(lambda: par.get_param_float("MPC_XY_VEL_MAX")) == pytest.approx(1.5)
        await again(lambda: par.set_param_float("MPC_XY_VEL_MAX", 2.5))
        assert await again(lambda: par.get_param_float("MPC_XY_VEL_MAX")) == pytest.approx(2.5)
        assert await again(lambda: par.get_param_int("NAV_DLL_ACT")) == 2
        await again(act.arm)
        await _until(tel.armed, bool, 5)
        await again(lambda: act.set_takeoff_altitude(4.0))
        assert await again(lambda: par.get_param_float("MIS_TAKEOFF_ALT")) == pytest.approx(4.0)
        await again(act.takeoff)
        await _until(tel.position, lambda p: p.relative_altitude_m > 3.8, 25)
        await _until(tel.in_air, bool, 5)  # EXTENDED_SYS_STATE, a stream fitted to the link: a little later
        # 20 items: a zig-zag 2 m apart (no speed: one MISSION_ITEM_INT each)
        items = [MissionItem(home.latitude_deg + (2 * (i % 2)) / M_PER_DEG, home.longitude_deg
                             + 2 * i / (M_PER_DEG * math.cos(math.radians(home.latitude_deg))), 4.0 + i % 3,
                             math.nan, True, math.nan, math.nan, MissionItem.CameraAction.NONE, math.nan,
                             math.nan, math.nan, math.nan, math.nan, MissionItem.VehicleAction.NONE)
                 for i in range(20)]
        times["upload"], tries["upload"] = await persevere(lambda: mis.upload_mission(MissionPlan(items)))
        (times["download"], tries["download"]), plan = await persevere(mis.download_mission, keep=True)

        def key(i: Any) -> tuple[float, float, float]:
            return (round(i.latitude_deg, 7), round(i.longitude_deg, 7), round(i.relative_altitude_m, 2))

        assert [key(i) for i in plan.mission_items] == [key(i) for i in items]
        await again(mis.start_mission)
        await _until(tel.flight_mode, lambda f: f == FlightMode.MISSION, 10)
        await _until(mis.mission_progress, lambda p: p.current >= 3, 30)  # flying it, item by item
        await again(act.land)  # (LAND lasts about a second of wall time at --speed 4: not waited for as a mode)
        await _until(tel.in_air, lambda a: not a, 40)
        return times, tries

    times, tries = fly(main, 180)
    print(f"\nMAVSDK through the bridge ({model} loss 10 %): connect {times['connect']:.1f} s, "
          f"20-item upload {times['upload']:.1f} s (failed tries first: {tries['upload']}), "
          f"download {times['download']:.1f} s (failed tries first: {tries['download']})")
    summary = c.stop_tablet()
    assert re.search(r"ground stations: \d+ frames up .* \d+ down", summary), summary
    assert "landed" in c.onboard.stderr
    no_traceback(c.onboard, c.relay, c.tablet)


# -- 2. MAVProxy ----------------------------------------------------------------------------------
def test_mavproxy_through_the_bridge(tmp_path: Path, start: Start) -> None:
    """MAVProxy 1.8.75 on its pipe, listening where the bridge sends (udpin), as on 14550: all the
    parameters arrive, `mode` names PX4's modes, `arm throttle` arms, `wp load` uploads a mission
    that `wp list` reads back."""
    from conftest import shipped
    from ttctl.ends.onboard.autopilot import Autopilot
    from ttctl.ends.onboard.vehicle import SimVehicle

    lat0, lon0 = HOME
    rows = ["QGC WPL 110", f"0\t1\t0\t16\t0\t0\t0\t0\t{lat0}\t{lon0}\t295\t1"]
    for i, (n, e) in enumerate(((6, 0), (6, 6), (0, 6), (0, 0)), start=1):
        lon = lon0 + e / (M_PER_DEG * math.cos(math.radians(lat0)))
        rows.append(f"{i}\t0\t3\t16\t0\t0\t0\t0\t{lat0 + n / M_PER_DEG:.7f}\t{lon:.7f}\t5\t1")
    (tmp_path / "mission.txt").write_text("\n".join(rows) + "\n")
    c = chain(start, tmp_path, model="burst", seed=5)
    # MAVProxy sends MISSION_COUNT once (the bridge sends a count the vehicle did not answer again: one
    # `wp load` is enough at 10 % loss), and MISSION_REQUEST_LIST and a command once: its user types
    # `wp list` and `arm throttle` again when nothing came back (both harmless twice)
    steps = (("", 8.0), ("mode", 0.5), ("wp load mission.txt", 6.0), ("wp list", 3.0), ("wp list", 3.0),
             ("arm throttle", 2.0), ("arm throttle", 2.0))
    out = run_mavproxy(c.gcs[0], steps, tmp_path, "--cmd=set param_ftp 0")
    count = len(Autopilot(shipped(), SimVehicle()).params.params)
    assert f"Received {count} parameters" in out, out[-3000:]
    assert re.search(r"Available modes:.*LOITER.*MISSION.*RTL.*OFFBOARD", out), out[-3000:]
    assert "Sent all 5 waypoints" in out, out[-3000:]  # (its MISSION_ACK may be lost: it is sent once)
    assert "mission of 5 items received" in c.onboard.stderr  # the vehicle's own word
    assert re.search(r"Requesting 5 waypoints", out) and "Saved 5 waypoints" in out, out[-3000:]  # wp list
    assert "ARMED" in out, out[-3000:]  # MAVProxy says so from the vehicle's HEARTBEAT
    c.stop_tablet()
    no_traceback(c.onboard, c.relay, c.tablet)


# -- 3. two ground stations at once ---------------------------------------------------------------
def test_two_ground_stations_each_get_their_own_answers(tmp_path: Path, start: Start) -> None:
    """MAVSDK (245/190) on one --gcs, a pymavlink ground station with QGroundControl's 255/190
    (the tablet's own ids: carried under another) on another: each gets the answers to its own
    commands only, both get the vehicle's HEARTBEAT and the bridge's RADIO_STATUS."""
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")
    from mavsdk.asyncio.plugins.action import ActionAsync
    from mavsdk.asyncio.plugins.mavlink_direct import MavlinkDirectAsync
    from mavsdk.asyncio.plugins.param import ParamAsync
    from mavsdk.asyncio.plugins.telemetry import TelemetryAsync

    c = chain(start, tmp_path, stations=2, model="random", seed=7)
    gcs = Gcs(c.gcs[1])
    m = gcs.m
    results: dict[str, Any] = {}

    def pymavlink_side() -> None:
        gcs.vehicle("HEARTBEAT", timeout=15)
        results["param"] = gcs.param_int("NAV_DLL_ACT")
        results["acks"] = [gcs.command(m.MAV_CMD_REQUEST_MESSAGE, m.MAVLINK_MSG_ID_AUTOPILOT_VERSION)
                           for _ in range(3)]
        gcs.pump(6.0)  # MAVSDK arms and takes off meanwhile: its acks must not come here

    side_done = tmp_path / "pymavlink-side-done"  # MAVSDK, in its own process, stays until then

    async def main(mav: Any) -> list[tuple[str, int, int, str]]:
        at_mavsdk: list[tuple[str, int, int, str]] = []
        await mav.add_any_connection(f"udpin://{LOCAL}:{c.gcs[0]}")
        system = await mav.first_autopilot(timeout_s=10)
        assert system is not None
        tel, act, par = TelemetryAsync(system), ActionAsync(system), ParamAsync(system)
        direct = MavlinkDirectAsync(system)

        async def collect(name: str) -> None:  # what reached MAVSDK's port, as it parsed it
            async for x in direct.subscribe_message(name):
                at_mavsdk.append((x.message_name, x.component_id, x.target_system_id, x.fields_json))

        watchers = [asyncio.ensure_future(collect("RADIO_STATUS"))]
        await _until(tel.health, lambda h: h.is_armable, 15)
        assert await again(lambda: par.get_param_int("NAV_DLL_ACT")) == 2
        await again(act.arm)
        await again(lambda: act.set_takeoff_altitude(3.0))
        await again(act.takeoff)
        await _until(tel.position, lambda p: p.relative_altitude_m > 2.8, 20)
        while not side_done.exists():
            await asyncio.sleep(0.1)
        for w in watchers:
            w.cancel()
        return at_mavsdk

    def side() -> None:
        try:
            pymavlink_side()
        except BaseException as e:
            results["pymavlink side"] = repr(e)
        finally:
            side_done.touch()

    pymavlink_thread = threading.Thread(target=side, daemon=True)
    pymavlink_thread.start()
    try:
        at_mavsdk = fly(main, 90)
    finally:
        side_done.touch()
        pymavlink_thread.join(30)
        gcs.close()
    assert "pymavlink side" not in results, results
    assert results["param"] == 2
    assert results["acks"] == [m.MAV_RESULT_ACCEPTED] * 3
    acks = gcs.received("COMMAND_ACK")
    # every COMMAND_ACK here is for this ground station (its own ids given back) and for its own command
    assert acks and all((a.target_system, a.target_component) == (255, 190) for a in acks), \
        [(a.command, a.target_system, a.target_component) for a in acks]
    assert {a.command for a in acks} == {m.MAV_CMD_REQUEST_MESSAGE}, [a.command for a in acks]
    assert not [a for a in acks if a.command in (m.MAV_CMD_COMPONENT_ARM_DISARM, m.MAV_CMD_NAV_TAKEOFF)]
    # answers addressed to anyone else never came here either
    other = [x for _, x in gcs.seen if getattr(x, "target_system", 0) not in (0, 255)]
    assert not other, other[:5]
    assert len(gcs.received("HEARTBEAT", (1, 1))) >= 5
    assert len(gcs.received("RADIO_STATUS", (1, 68))) >= 5
    # MAVSDK got RADIO_STATUS from the radio's component too. (Whether the pymavlink station's acks
    # reached MAVSDK's port cannot be seen from MAVSDK: it drops frames addressed to other systems
    # itself, as a bridge sending everything everywhere showed; the pymavlink side above is the check.)
    assert len([x for x in at_mavsdk if x[0] == "RADIO_STATUS" and x[1] == 68]) >= 3, at_mavsdk
    assert "taking off" in c.onboard.stderr  # MAVSDK's take-off was done by the vehicle
    c.stop_tablet()
    no_traceback(c.onboard, c.relay, c.tablet)


# -- 4. the tablet's script and a ground station at once ------------------------------------------
FLIGHT = """\
- takeoff: 5
- wait: {until: altitude >= 4.5 and state == hovering, timeout: 40}
- send: payload.bin
- goto: [4, 0, 5]
- land
- wait: {until: state == landed, timeout: 60}
"""


def test_tablet_script_flies_and_sends_a_file_while_a_ground_station_watches(tmp_path: Path, start: Start) -> None:
    payload = data_file(tmp_path, "payload.bin", size=3000, seed=22)
    c = chain(start, tmp_path, model="burst", seed=11, script=FLIGHT,
              onboard=("--inbox", str(tmp_path / "inbox")))
    assert c.tablet is not None
    gcs = Gcs(c.gcs[0])
    try:
        gcs.vehicle("HEARTBEAT", timeout=15)
        params = {"MPC_XY_VEL_MAX": gcs.param("MPC_XY_VEL_MAX"), "NAV_DLL_ACT": gcs.param_int("NAV_DLL_ACT")}
        top = 0
        end = time.monotonic() + scaled(120)
        while time.monotonic() < end and '"step": 6' not in c.tablet.stdout:
            p = gcs.pump(0.5, lambda x: x.get_type() == "GLOBAL_POSITION_INT" and x.get_srcSystem() == 1)
            top = max(top, p.relative_alt if p is not None else 0)
            assert c.tablet.p.poll() is None, c.tablet.stderr
    finally:
        gcs.close()
    steps = [json.loads(x) for x in c.tablet.stdout.splitlines() if '"event": "step"' in x]
    assert [s["step"] for s in steps] == list(range(1, 7)) and all(s["ok"] for s in steps), c.tablet.stdout
    assert hashlib.sha256((tmp_path / "inbox" / "payload.bin").read_bytes()).digest() == \
        hashlib.sha256(payload.read_bytes()).digest()
    assert params["MPC_XY_VEL_MAX"] == pytest.approx(1.5) and params["NAV_DLL_ACT"] == 2
    assert top > 4500, top  # the ground station saw the climb the script asked for (mm)
    assert gcs.received("RADIO_STATUS", (1, 68))
    summary = c.stop_tablet()
    assert re.search(r"ground stations: [1-9]\d* frames up", summary), summary
    no_traceback(c.onboard, c.relay, c.tablet)


# -- 5. the radio dies and comes back -------------------------------------------------------------
def test_relay_killed_mid_flight_the_ground_station_sees_the_link_go_and_come_back(tmp_path: Path,
                                                                                  start: Start) -> None:
    c = chain(start, tmp_path, model="random", seed=13)
    gcs = Gcs(c.gcs[0])
    m = gcs.m
    try:
        gcs.vehicle("HEARTBEAT", timeout=15)
        assert gcs.command(m.MAV_CMD_COMPONENT_ARM_DISARM, 1) == m.MAV_RESULT_ACCEPTED
        take_off(gcs, c.onboard, 10)
        gcs.vehicle("GLOBAL_POSITION_INT", lambda p: p.relative_alt > 3000, timeout=20)
        rs = gcs.wait("RADIO_STATUS", lambda r: r.get_srcComponent() == 68, timeout=3)
        assert rs.rssi > 0 and rs.remrssi == rs.rssi
        assert c.relay is not None
        c.relay.p.send_signal(signal.SIGKILL)
        c.relay.p.wait(5)
        killed = time.monotonic()
        gcs.pump(1.0)  # what was in flight
        gone = gcs.wait("RADIO_STATUS", lambda r: r.get_srcComponent() == 68 and r.rssi == 0, timeout=6)
        assert time.monotonic() - killed < 5.0
        assert gone.remrssi == 0
        mark = time.monotonic()
        gcs.pump(2.5)
        assert not gcs.received("HEARTBEAT", (1, 1), since=mark)  # the vehicle's heartbeats stopped
        assert gcs.received("RADIO_STATUS", (1, 68), since=mark)  # the radio still says so, 1 Hz
        c.start_relay("relay2")
        back = gcs.vehicle("HEARTBEAT", timeout=10)
        assert back.base_mode & m.MAV_MODE_FLAG_SAFETY_ARMED  # still flying
        gcs.wait("RADIO_STATUS", lambda r: r.get_srcComponent() == 68 and r.rssi > 0, timeout=8)
        assert gcs.command(m.MAV_CMD_NAV_LAND, 0, 0, 0, math.nan, math.nan, math.nan, math.nan) == \
            m.MAV_RESULT_ACCEPTED
        gcs.vehicle("GLOBAL_POSITION_INT", lambda p: p.relative_alt < 2500, timeout=20)  # the land was done
    finally:
        gcs.close()
    c.stop_tablet()
    no_traceback(c.onboard, c.tablet)


def test_a_retried_takeoff_whose_ack_was_lost_is_accepted(tmp_path: Path, start: Start) -> None:
    """A ground station whose COMMAND_ACK for NAV_TAKEOFF was lost sends it again (confirmation 1):
    the vehicle, taking off, must say ACCEPTED again (mavlink.io: commands idempotent where possible,
    TAKEOFF when already flying acknowledged ACCEPTED), not DENIED for what it is doing."""
    c = chain(start, tmp_path, model="random", seed=19)
    gcs = Gcs(c.gcs[0])
    m = gcs.m
    nan = math.nan
    try:
        gcs.vehicle("HEARTBEAT", timeout=15)
        assert gcs.command(m.MAV_CMD_COMPONENT_ARM_DISARM, 1) == m.MAV_RESULT_ACCEPTED
        assert gcs.command(m.MAV_CMD_COMPONENT_ARM_DISARM, 1) == m.MAV_RESULT_ACCEPTED  # ARM is idempotent
        assert gcs.command(m.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, nan, nan, nan, 295 + 8) == m.MAV_RESULT_ACCEPTED
        gcs.vehicle("GLOBAL_POSITION_INT", lambda p: p.relative_alt > 1000, timeout=10)  # climbing
        retry = gcs.command(m.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, nan, nan, nan, 295 + 8, resend=True)  # the same, again
    finally:
        gcs.close()
    assert retry == m.MAV_RESULT_ACCEPTED, c.onboard.stderr


def test_a_new_upload_of_the_same_length_after_an_abandoned_one_is_carried(tmp_path: Path, start: Start) -> None:
    """A ground station gives up an upload part-way (MAVSDK after its TIMEOUT, a final MISSION_ACK lost,
    a MAVProxy user typing wp load again) and uploads another plan with as many items: it must be
    asked for the new items and the vehicle must end up with the new plan, never the old items.
    No loss on the relay: what happens is the bridge's doing."""
    c = chain(start, tmp_path, loss="0", seed=23)
    gcs = Gcs(c.gcs[0])
    m = gcs.m
    lat0, lon0 = (round(x * 1e7) for x in HOME)

    def plan(north_m: float) -> list[Any]:
        return [m.MAVLink_mission_item_int_message(1, 1, seq, m.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT,
                                                   m.MAV_CMD_NAV_WAYPOINT, 0, 1, 0, 0, 0, math.nan,
                                                   lat0 + round((north_m + seq) / M_PER_DEG * 1e7), lon0, 5.0, 0)
                for seq in range(3)]

    def request(timeout: float) -> Any:
        return gcs.pump(timeout, lambda x: x.get_type() in ("MISSION_REQUEST_INT", "MISSION_REQUEST", "MISSION_ACK"))

    old, new = plan(10.0), plan(40.0)
    try:
        gcs.vehicle("HEARTBEAT", timeout=15)
        gcs.conn.mav.mission_count_send(1, 1, 3, 0)
        for seq in (0, 1):  # the first two items of the old plan, then the station gives up
            asked = request(5.0)
            assert asked is not None and asked.get_type() != "MISSION_ACK" and asked.seq == seq, asked
            gcs.conn.mav.send(old[seq])
        gcs.pump(1.5)
        verdict, asked_for = None, []
        gcs.conn.mav.mission_count_send(1, 1, 3, 0)  # the new plan, as many items
        end = time.monotonic() + 8  # (about 2 s when carried)
        while verdict is None and time.monotonic() < end:
            x = request(1.5)
            if x is None:
                gcs.conn.mav.mission_count_send(1, 1, 3, 0)  # no request yet: the count again, as stations do
            elif x.get_type() == "MISSION_ACK":
                verdict = x.type
            else:
                asked_for.append(x.seq)
                gcs.conn.mav.send(new[x.seq])
        held = []
        gcs.conn.mav.mission_request_list_send(1, 1, 0)
        count = gcs.wait("MISSION_COUNT", timeout=5).count
        for seq in range(count):
            gcs.conn.mav.mission_request_int_send(1, 1, seq, 0)
            held.append(gcs.wait("MISSION_ITEM_INT", functools.partial(is_item, seq), timeout=5).x)
    finally:
        gcs.close()
    assert verdict == m.MAV_MISSION_ACCEPTED, (verdict, asked_for, c.onboard.stderr)
    assert sorted(set(asked_for)) == [0, 1, 2], asked_for  # the station was asked for its new items
    assert held == [i.x for i in new], (held, [i.x for i in old], [i.x for i in new])


# -- 6. a signed DTT link -------------------------------------------------------------------------
def test_signed_link_carries_an_unsigned_ground_station_and_refuses_a_stranger(tmp_path: Path,
                                                                              start: Start) -> None:
    from pymavlink import mavutil

    key = tmp_path / "link.key"
    key.write_text("correct horse battery staple\n")
    c = chain(start, tmp_path, model="random", seed=17, onboard=("--key", str(key)), tablet=("--key", str(key)))
    gcs = Gcs(c.gcs[0])
    m = gcs.m
    stranger = mavutil.mavlink_connection(f"udpout:{LOCAL}:{c.air}", source_system=250, source_component=190,
                                          dialect="common")

    def stranger_sends(*cmd: Any) -> None:
        for i in range(5):
            stranger.mav.heartbeat_send(m.MAV_TYPE_GCS, m.MAV_AUTOPILOT_INVALID, 0, 0, 4)
            stranger.mav.command_long_send(1, 1, *cmd[:1], i, *cmd[1:])
            gcs.pump(0.4)

    try:
        gcs.vehicle("HEARTBEAT", timeout=15)
        stranger_sends(m.MAV_CMD_COMPONENT_ARM_DISARM, 1, 0, 0, 0, 0, 0, 0)
        gcs.pump(1.0)
        assert not gcs.armed()  # the stranger's arm did nothing
        assert gcs.param("MPC_XY_VEL_MAX") == pytest.approx(1.5)
        assert gcs.command(m.MAV_CMD_COMPONENT_ARM_DISARM, 1) == m.MAV_RESULT_ACCEPTED
        gcs.pump(1.0)
        assert gcs.armed()
        stranger_sends(m.MAV_CMD_COMPONENT_ARM_DISARM, 0, 21196, 0, 0, 0, 0, 0)  # forced disarm
        gcs.pump(1.0)
        assert gcs.armed()  # still: the stranger commands nothing
    finally:
        gcs.close()
        stranger.close()
    assert "unsigned" in c.onboard.stderr, c.onboard.stderr  # the onboard end said whom it ignored
    # the link is signed, the ground station's side is not: the bridge passes the vehicle's frames unsigned
    assert gcs.seen and not [x for _, x in gcs.seen if x._signed], "signed frames reached the ground station"
    c.stop_tablet()
    no_traceback(c.onboard, c.relay, c.tablet)
