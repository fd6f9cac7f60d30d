"""PX4's flight modes on `ttctl emulate onboard`, flown by real ground stations as processes on
loopback: MAVSDK's offboard and manual-control plugins, MAVProxy's mode names, DO_SET_MODE and
integer parameters, and ground-station time that stays the wall clock whatever --speed is."""

from __future__ import annotations

import asyncio
import functools
import math
import re
import threading
import time
from pathlib import Path
from typing import Any

import pytest

from e2e_lib import LOCAL, Start, free_port, mavproxy_exe, run_mavproxy, until
from machine import scaled
from mavsdk_child import fly

EARTH_RADIUS = 6_378_137.0


def onboard(start: Start, port: int, speed: str = "1") -> Any:
    node = start("onboard", "emulate", "onboard", "--gcs", f"udpout:{LOCAL}:{port}", "--listen", f"udpin:{LOCAL}:0",
                 "--no-entry-points", "--speed", speed)
    node.wait_for("onboard 1:")
    return node


_until = functools.partial(until, poll=0.1)


def test_mavsdk_offboard_and_manual_control_fly_what_they_command(tmp_path: Path, start: Start) -> None:
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")
    from mavsdk.asyncio.plugins.action import ActionAsync
    from mavsdk.asyncio.plugins.manual_control import ManualControlAsync
    from mavsdk.asyncio.plugins.offboard import OffboardAsync
    from mavsdk.asyncio.plugins.telemetry import TelemetryAsync
    from mavsdk.plugins.offboard import OffboardError, VelocityNedYaw
    from mavsdk.plugins.telemetry import FlightMode

    port = free_port()
    node = onboard(start, port, speed="2")

    async def main(m: Any) -> None:
        await m.add_any_connection(f"udpin://{LOCAL}:{port}")
        system = await m.first_autopilot(timeout_s=15)
        assert system is not None
        tel, act = TelemetryAsync(system), ActionAsync(system)
        off, man = OffboardAsync(system), ManualControlAsync(system)
        await _until(tel.health, lambda h: h.is_armable, 10)
        assert await tel.flight_mode() == FlightMode.HOLD
        await act.arm()
        await act.set_takeoff_altitude(3.0)
        await act.takeoff()
        await _until(tel.position, lambda p: p.relative_altitude_m > 2.8, 15)
        await _until(tel.flight_mode, lambda f: f == FlightMode.HOLD, 5)  # the climb done
        with pytest.raises(OffboardError):
            await off.start()  # no set-point yet: MAVSDK itself refuses
        await off.set_velocity_ned(VelocityNedYaw(0.0, 0.0, 0.0, 90.0))
        await off.start()
        assert await off.is_active()
        await _until(tel.flight_mode, lambda f: f == FlightMode.OFFBOARD, 3)
        await _until(tel.heading, lambda h: abs(h.heading_deg - 90) < 2, 5)
        before = await tel.position_velocity_ned()
        await off.set_velocity_ned(VelocityNedYaw(0.0, 1.0, 0.0, 90.0))
        await asyncio.sleep(2.5)  # 5 s of the vehicle's clock at --speed 2
        await off.set_velocity_ned(VelocityNedYaw(0.0, 0.0, 0.0, 90.0))
        await asyncio.sleep(1.5)
        after = await tel.position_velocity_ned()
        moved_e = after.position.east_m - before.position.east_m
        moved_n = after.position.north_m - before.position.north_m
        assert moved_e == pytest.approx(5.0, rel=0.1) and abs(moved_n) < 0.3, (moved_n, moved_e)
        assert abs(after.position.down_m - before.position.down_m) < 0.2
        await off.stop()
        await _until(tel.flight_mode, lambda f: f == FlightMode.HOLD, 3)
        # position control by the sticks: forward (the vehicle faces east) for 2 s
        stop = asyncio.Event()
        sticks = [0.0, 0.0, 0.5, 0.0]

        async def feed() -> None:
            while not stop.is_set():
                await man.set_manual_control_input(*sticks)
                await asyncio.sleep(0.05)

        feeder = asyncio.ensure_future(feed())
        try:
            await asyncio.sleep(0.3)
            await man.start_position_control()
            await _until(tel.flight_mode, lambda f: f == FlightMode.POSCTL, 3)
            here = await tel.position_velocity_ned()
            sticks[0] = 1.0
            await asyncio.sleep(1.5)
            sticks[0] = 0.0
            await asyncio.sleep(1.5)
            there = await tel.position_velocity_ned()
            assert there.position.east_m - here.position.east_m > 3.0
            assert abs(there.position.north_m - here.position.north_m) < 0.3
            assert abs(there.velocity.east_m_s) < 0.1  # centred sticks: holding
        finally:
            stop.set()
            await feeder
        await _until(tel.flight_mode, lambda f: f == FlightMode.RETURN_TO_LAUNCH, 3)  # NAV_RCL_ACT 2
        await act.land()
        await _until(tel.in_air, lambda a: not a, 30)

    fly(main, 120)
    assert "Traceback" not in node.stderr
    assert "manual control lost: return" in node.stderr


def test_mavproxy_names_the_modes_sets_them_and_integer_parameters(tmp_path: Path, start: Start) -> None:
    """MAVProxy 1.8.75, unmodified, as a process driven through its prompt. Its `mode NAME` (and
    `rtl`) fail before sending anything for any PX4 vehicle (pymavlink's set_mode_px4 is given the
    mode table's tuple); `long DO_SET_MODE 1 MAIN SUB` is what works, as with PX4 itself."""
    mavproxy_exe()
    port = free_port()
    node = onboard(start, port, speed="2")
    steps = (("", 5.0), ("mode", 0.5), ("param set NAV_DLL_ACT 3", 1.0), ("param show NAV_DLL_ACT", 0.5),
             ("param set NAV_DLL_ACT 9", 1.0), ("arm throttle", 1.5),
             ("takeoff 4", 5.0), ("long DO_SET_MODE 1 5 0", 1.0), ("long DO_SET_MODE 1 6 0", 1.0),
             ("long DO_SET_MODE 1 4 5", 3.0))
    out = run_mavproxy(port, steps, tmp_path, "--cmd=set param_ftp 0")
    from conftest import shipped
    from ttctl.ends.onboard.autopilot import Autopilot
    from ttctl.ends.onboard.vehicle import SimVehicle

    assert f"Received {len(Autopilot(shipped(), SimVehicle()).params.params)} parameters" in out, out[-2000:]
    assert re.search(r"Available modes:.*LOITER.*MISSION.*RTL.*OFFBOARD", out)
    assert "LOITER>" in out and "Mode TAKEOFF" in out and "Mode RTL" in out, out[-2000:]
    assert re.search(r"NAV_DLL_ACT\s+3\b", out), out[-3000:]  # an INT32 read back as the integer set
    assert "NAV_DLL_ACT = 9 refused: outside 0..3" in out
    assert re.search(r"DO_SET_MODE: DENIED", out) and "ACRO: not a mode flown here" in out
    assert re.search(r"DO_SET_MODE: TEMPORARILY_REJECTED", out) and "OFFBOARD: no set-point stream" in out
    assert re.search(r"DO_SET_MODE: ACCEPTED", out)
    assert "returning" in node.stderr


def test_ground_station_time_is_the_wall_clock_at_any_speed(tmp_path: Path, start: Start) -> None:
    from pymavlink import mavutil

    m = mavutil.mavlink
    port = free_port()
    conn = mavutil.mavlink_connection(f"udpin:{LOCAL}:{port}", source_system=255, source_component=190,
                                      dialect="common")
    node = onboard(start, port, speed="8")
    try:
        assert conn.recv_match(type="HEARTBEAT", blocking=True, timeout=10) is not None
        seen: dict[str, list[tuple[float, Any]]] = {"HEARTBEAT": [], "ATTITUDE": []}
        end = time.monotonic() + 4.0
        while time.monotonic() < end:
            msg = conn.recv_match(type=list(seen), blocking=True, timeout=0.5)
            if msg is not None and msg.get_srcComponent() == 1:
                seen[msg.get_type()].append((time.monotonic(), msg))
        assert 3 <= len(seen["HEARTBEAT"]) <= 5  # 1 Hz
        assert 13 <= len(seen["ATTITUDE"]) <= 19  # 4 Hz
        (t0, a0), (t1, a1) = seen["ATTITUDE"][0], seen["ATTITUDE"][-1]
        assert (a1.time_boot_ms - a0.time_boot_ms) / 1000 == pytest.approx(t1 - t0, abs=0.3)
        assert not math.isnan(a1.yaw)
        # sticks at 10 Hz of the wall clock are a live stream (COM_RC_LOSS_T 0.5 s), at any --speed
        conn.mav.command_long_send(1, 1, m.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, 0, math.nan, math.nan, math.nan, 300)
        conn.mav.command_long_send(1, 1, m.MAV_CMD_COMPONENT_ARM_DISARM, 0, 1, 0, 0, 0, 0, 0, 0)
        conn.recv_match(type="GLOBAL_POSITION_INT", condition="GLOBAL_POSITION_INT.relative_alt>4800",
                        blocking=True, timeout=10)
        stop = threading.Event()

        def sticks() -> None:
            while not stop.is_set():
                conn.mav.manual_control_send(1, 0, 0, 500, 0, 0)
                time.sleep(0.1)

        feeder = threading.Thread(target=sticks)
        feeder.start()
        try:
            time.sleep(0.5)
            conn.mav.command_long_send(1, 1, m.MAV_CMD_DO_SET_MODE, 0, 1, 3, 0, 0, 0, 0, 0)
            time.sleep(2.5)
            while conn.recv_match(blocking=False) is not None:
                pass
            hb = conn.recv_match(type="HEARTBEAT", condition="HEARTBEAT.get_srcComponent()==1", blocking=True,
                                 timeout=3)
            assert mavutil.interpret_px4_mode(hb.base_mode, hb.custom_mode) == "POSCTL"
            assert "manual control" in node.stderr and "manual control lost" not in node.stderr
        finally:
            stop.set()
            feeder.join()
        lost = time.monotonic()
        node.wait_for("manual control lost: return")
        assert time.monotonic() - lost < 2.0  # and their end is noticed: NAV_RCL_ACT returns
    finally:
        conn.close()


def test_qgroundcontrol_px4_guided_actions(tmp_path: Path, start: Start) -> None:
    """What QGroundControl's PX4 plugin sends for its guided actions (PX4FirmwarePlugin.cc), from
    pymavlink: take-off (NAV_TAKEOFF to an AMSL altitude while disarmed, then arm), go to
    (DO_REPOSITION as COMMAND_INT, AMSL), pause (DO_REPOSITION, all NaN), change heading
    (DO_REPOSITION's yaw in radians), return (DO_SET_MODE AUTO.RTL), and a mode from its list
    this vehicle does not fly."""
    from pymavlink import mavutil

    m = mavutil.mavlink
    nan = math.nan
    port = free_port()
    conn = mavutil.mavlink_connection(f"udpin:{LOCAL}:{port}", source_system=255, source_component=190,
                                      dialect="common")
    node = onboard(start, port, speed="4")

    said: list[str] = []

    def command(cmd: int, *p: float) -> int:
        conn.mav.command_long_send(1, 1, cmd, 0, *(list(p) + [0.0] * (7 - len(p))))
        end = time.monotonic() + 3
        while time.monotonic() < end:
            msg = conn.recv_match(type=["COMMAND_ACK", "STATUSTEXT"], blocking=True, timeout=0.5)
            if msg is not None and msg.get_type() == "STATUSTEXT":
                said.append(msg.text)
            elif msg is not None and msg.command == cmd:
                return int(msg.result)
        raise AssertionError(f"no COMMAND_ACK for {cmd}")

    def mode() -> str:
        hb = conn.recv_match(type="HEARTBEAT", condition="HEARTBEAT.get_srcComponent()==1", blocking=True, timeout=3)
        return str(mavutil.interpret_px4_mode(hb.base_mode, hb.custom_mode))

    def until(kind: str, condition: str, timeout: float = 15) -> Any:
        timeout = scaled(timeout)  # longer on a busy machine
        msg = conn.recv_match(type=kind, condition=condition, blocking=True, timeout=timeout)
        assert msg is not None, (kind, condition, node.stderr[-500:])
        return msg

    try:
        home = until("HOME_POSITION", "True")
        home_amsl = home.altitude / 1000
        assert command(m.MAV_CMD_NAV_TAKEOFF, -1, 0, 0, nan, nan, nan, home_amsl + 5) == m.MAV_RESULT_ACCEPTED
        assert mode() == "TAKEOFF"
        assert command(m.MAV_CMD_COMPONENT_ARM_DISARM, 1) == m.MAV_RESULT_ACCEPTED
        until("GLOBAL_POSITION_INT", "GLOBAL_POSITION_INT.relative_alt>4850")
        lat = home.latitude + round(math.degrees(10 / EARTH_RADIUS) * 1e7)
        conn.mav.command_int_send(1, 1, m.MAV_FRAME_GLOBAL, m.MAV_CMD_DO_REPOSITION, 0, 0, -1,
                                  m.MAV_DO_REPOSITION_FLAGS_CHANGE_MODE, 0, nan, lat, home.longitude, home_amsl + 5)
        assert until("COMMAND_ACK", f"COMMAND_ACK.command=={m.MAV_CMD_DO_REPOSITION}").result == m.MAV_RESULT_ACCEPTED
        assert mode() == "LOITER"
        until("LOCAL_POSITION_NED", "LOCAL_POSITION_NED.x>9.8")
        assert command(m.MAV_CMD_DO_REPOSITION, -1, 1, 0, nan, nan, nan, nan) == m.MAV_RESULT_ACCEPTED  # pause
        assert command(m.MAV_CMD_DO_REPOSITION, -1, 1, 0, math.pi / 2, nan, nan, nan) == m.MAV_RESULT_ACCEPTED
        until("VFR_HUD", "abs(VFR_HUD.heading-90)<=2")
        assert command(m.MAV_CMD_DO_SET_MODE, 1, 7, 0) == m.MAV_RESULT_DENIED  # STABILIZED, from QGC's list
        assert "refused: STABILIZED: not a mode flown here" in said
        assert command(m.MAV_CMD_DO_SET_MODE, 1, 4, 5) == m.MAV_RESULT_ACCEPTED
        assert mode() == "RTL"
        until("HEARTBEAT", "HEARTBEAT.get_srcComponent()==1 and not HEARTBEAT.base_mode & 128", timeout=30)
        pos = until("LOCAL_POSITION_NED", "True")
        assert math.hypot(pos.x, pos.y) < 0.3 and abs(pos.z) < 0.1
    finally:
        conn.close()
    assert "Traceback" not in node.stderr
