"""Missions and safety against real ground stations (real processes on loopback): MAVSDK pauses
(the vehicle holds), continues at the same item, sets the current item and sees the mission
finish; a MAVSDK geofence is enforced with GF_ACTION's action; MAVProxy sets the current
waypoint; pymavlink probes check MISSION_ITEM_REACHED, DO_CHANGE_SPEED and DO_SET_HOME in the
vehicle's state."""

from __future__ import annotations

import asyncio
import math
import time
from pathlib import Path
from typing import Any

import pytest

from e2e_lib import LOCAL, Start, free_port, mavproxy_exe, run_mavproxy
from machine import scaled
from mavsdk_child import fly
from test_emulate_mavsdk import _until, onboard
from test_emulate_onboard import command, gcs, wait_for

__all__ = ["gcs"]  # the fixture, shared
M_PER_DEG = 111_319.49  # metres per degree of latitude (the vehicle's sphere)


def north(lat0: float, metres: float) -> float:
    return lat0 + metres / M_PER_DEG


def east(lat0: float, lon0: float, metres: float) -> float:
    return lon0 + metres / (M_PER_DEG * math.cos(math.radians(lat0)))


def test_mavsdk_pauses_continues_sets_the_current_item_and_sees_the_mission_finish(start: Start) -> None:
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")
    from mavsdk.asyncio.plugins.action import ActionAsync
    from mavsdk.asyncio.plugins.mission import MissionAsync
    from mavsdk.asyncio.plugins.telemetry import TelemetryAsync
    from mavsdk.plugins.mission import MissionItem, MissionPlan
    from mavsdk.plugins.telemetry import FlightMode

    port = free_port()
    node = onboard(start, port)

    async def main(m: Any) -> None:
        await m.add_any_connection(f"udpin://{LOCAL}:{port}")
        system = await m.first_autopilot(timeout_s=15)
        assert system is not None
        tel, act, mis = TelemetryAsync(system), ActionAsync(system), MissionAsync(system)
        home = await _until(tel.home, lambda h: abs(h.latitude_deg - 46.0503) < 1e-6, 10)
        await _until(tel.health, lambda h: h.is_armable, 10)
        lat0, lon0 = home.latitude_deg, home.longitude_deg
        route = [(0.0, 0.0), (16.0, 0.0), (16.0, 10.0), (0.0, 10.0)]
        items = [MissionItem(north(lat0, n), east(lat0, lon0, e), 5.0, math.nan, True, math.nan, math.nan,
                             MissionItem.CameraAction.NONE, math.nan, math.nan, math.nan, math.nan, math.nan,
                             MissionItem.VehicleAction.NONE) for n, e in route]
        await mis.upload_mission(MissionPlan(items))
        await act.arm()
        await mis.start_mission()
        await _until(tel.position, lambda p: (p.latitude_deg - lat0) * M_PER_DEG > 6.0, 40)
        await mis.pause_mission()  # MAVSDK: hold mode
        await _until(tel.flight_mode, lambda f: f == FlightMode.HOLD, 5)
        await asyncio.sleep(0.5)
        before = await tel.position()
        await asyncio.sleep(1.5)
        after = await tel.position()
        assert abs(after.latitude_deg - before.latitude_deg) * M_PER_DEG < 0.3  # holding, not returning
        assert await tel.flight_mode() == FlightMode.HOLD and await tel.in_air()
        assert (await mis.mission_progress()).current == 1  # still on its way to item 1
        await mis.start_mission()  # continue: on to item 1, not back to item 0
        await _until(tel.flight_mode, lambda f: f == FlightMode.MISSION, 5)
        await _until(tel.position, lambda p: (p.latitude_deg - lat0) * M_PER_DEG > 15.5, 30)
        await asyncio.wait_for(mis.set_current_mission_item(3), 10)  # skip item 2
        await _until(mis.is_mission_finished, bool, 40)
        pos = await tel.position()
        assert abs(pos.latitude_deg - lat0) * M_PER_DEG < 0.5
        assert abs((pos.longitude_deg - lon0) * M_PER_DEG * math.cos(math.radians(lat0)) - 10) < 0.5
        progress = await mis.mission_progress()
        assert (progress.current, progress.total) == (4, 4)
        await _until(tel.flight_mode, lambda f: f == FlightMode.HOLD, 5)  # PX4 holds after the last item
        await act.land()

    fly(main, 150)
    assert "Traceback" not in node.stderr
    # item 2 was never flown: the vehicle went from item 1 straight to item 3
    assert "mission complete" in node.stderr


def test_mavsdk_geofence_is_enforced_with_gf_action(start: Start) -> None:
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")
    from mavsdk.asyncio.plugins.action import ActionAsync
    from mavsdk.asyncio.plugins.geofence import GeofenceAsync
    from mavsdk.asyncio.plugins.param import ParamAsync
    from mavsdk.asyncio.plugins.telemetry import TelemetryAsync
    from mavsdk.plugins.geofence import FenceType, GeofenceData, Point, Polygon
    from mavsdk.plugins.telemetry import FlightMode

    port = free_port()
    node = onboard(start, port)

    async def main(m: Any) -> None:
        await m.add_any_connection(f"udpin://{LOCAL}:{port}")
        system = await m.first_autopilot(timeout_s=15)
        assert system is not None
        tel, act, geo, par = TelemetryAsync(system), ActionAsync(system), GeofenceAsync(system), ParamAsync(system)
        home = await _until(tel.home, lambda h: abs(h.latitude_deg - 46.0503) < 1e-6, 10)
        await _until(tel.health, lambda h: h.is_armable, 10)
        lat0, lon0 = home.latitude_deg, home.longitude_deg
        square = [Point(north(lat0, dn), east(lat0, lon0, de)) for dn, de in ((-20, -20), (20, -20), (20, 20),
                                                                              (-20, 20))]
        await geo.upload_geofence(GeofenceData([Polygon(square, FenceType.INCLUSION)], []))
        await par.set_param_int("GF_ACTION", 3)  # return
        assert await par.get_param_int("GF_ACTION") == 3
        await act.arm()
        await act.set_takeoff_altitude(4.0)
        await act.takeoff()
        await _until(tel.position, lambda p: p.relative_altitude_m > 3.8, 20)
        await act.goto_location(north(lat0, 35), lon0, home.absolute_altitude_m + 4, math.nan)
        top = 0.0
        end = time.monotonic() + scaled(40)
        while time.monotonic() < end and await tel.flight_mode() != FlightMode.RETURN_TO_LAUNCH:
            top = max(top, ((await tel.position()).latitude_deg - lat0) * M_PER_DEG)
            await asyncio.sleep(0.1)
        assert await tel.flight_mode() == FlightMode.RETURN_TO_LAUNCH
        assert 18.5 < top < 21  # turned back at the 20 m fence (its breach predicted), not past it
        await _until(tel.in_air, lambda a: not a, 90)
        back = await tel.position()
        assert abs(back.latitude_deg - lat0) * M_PER_DEG < 0.3

    fly(main, 150)
    assert "geofence breached: outside the inclusion fence: return" in node.stderr
    assert "Traceback" not in node.stderr


def test_mission_items_reached_and_commands_checked_in_state(gcs: tuple[Any, Any]) -> None:
    """pymavlink: MISSION_CURRENT counts items, MISSION_ITEM_REACHED comes for each one;
    DO_CHANGE_SPEED and DO_SET_HOME answered ACCEPTED are seen in the vehicle's telemetry;
    unflyable items are refused at upload by name."""
    from pymavlink import mavutil

    m = mavutil.mavlink
    conn, node = gcs
    lat0, lon0 = 46.0503, 14.4686

    def item(seq: int, cmd: int, n: float = 0, e: float = 0, alt: float = 5, p1: float = 0, p2: float = 0) -> Any:
        return m.MAVLink_mission_item_int_message(1, 1, seq, m.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, cmd, 0, 1, p1, p2,
                                                  0, math.nan, int(north(lat0, n) * 1e7),
                                                  int(east(lat0, lon0, e) * 1e7), alt, m.MAV_MISSION_TYPE_MISSION)

    def upload(items: list[Any]) -> int:
        conn.mav.mission_count_send(1, 1, len(items), m.MAV_MISSION_TYPE_MISSION)
        while True:
            r = conn.recv_match(type=["MISSION_REQUEST_INT", "MISSION_ACK"], blocking=True, timeout=5)
            assert r is not None
            if r.get_type() == "MISSION_ACK":
                return int(r.type)
            conn.mav.send(items[r.seq])

    bad = [item(0, m.MAV_CMD_NAV_WAYPOINT, 5), item(1, m.MAV_CMD_CONDITION_DISTANCE, p1=3)]
    assert upload(bad) == m.MAV_MISSION_UNSUPPORTED
    words = wait_for(conn, "STATUSTEXT", lambda s: "refused" in s.text, timeout=3)
    assert "CONDITION_DISTANCE" in words.text
    items = [item(0, m.MAV_CMD_NAV_TAKEOFF, alt=4), item(1, m.MAV_CMD_DO_CHANGE_SPEED, p1=1, p2=0.8),
             item(2, m.MAV_CMD_NAV_WAYPOINT, 8), item(3, m.MAV_CMD_NAV_WAYPOINT, 8, 6)]
    assert upload(items) == m.MAV_MISSION_ACCEPTED
    assert command(conn, m.MAV_CMD_COMPONENT_ARM_DISARM, 1) == m.MAV_RESULT_ACCEPTED
    assert command(conn, m.MAV_CMD_MISSION_START) == m.MAV_RESULT_ACCEPTED
    reached: list[int] = []
    currents: list[int] = []
    top = 0.0
    end = time.monotonic() + scaled(60)
    while time.monotonic() < end and 3 not in reached:
        r = conn.recv_match(type=["MISSION_ITEM_REACHED", "MISSION_CURRENT", "VFR_HUD"], blocking=True, timeout=0.5)
        if r is None:
            continue
        if r.get_type() == "MISSION_ITEM_REACHED":
            reached.append(r.seq)
        elif r.get_type() == "MISSION_CURRENT" and (not currents or currents[-1] != r.seq):
            currents.append(r.seq)
        elif r.get_type() == "VFR_HUD" and 2 in currents:
            top = max(top, r.groundspeed)
    assert reached == [0, 1, 2, 3] and currents[-3:] == [1, 2, 3], (reached, currents)  # item numbers
    assert 0.5 < top < 0.85  # DO_CHANGE_SPEED's 0.8 m/s, not the 1.5 m/s limit
    # DO_CHANGE_SPEED as a command: refused beyond MPC_XY_VEL_MAX or NaN-free nonsense, then honoured
    assert command(conn, m.MAV_CMD_DO_CHANGE_SPEED, 1, 50) == m.MAV_RESULT_DENIED
    assert command(conn, m.MAV_CMD_DO_CHANGE_SPEED, 1, math.inf) == m.MAV_RESULT_DENIED
    assert command(conn, m.MAV_CMD_DO_CHANGE_SPEED, 1, 0.6) == m.MAV_RESULT_ACCEPTED
    conn.mav.command_int_send(1, 1, m.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, m.MAV_CMD_DO_REPOSITION, 0, 0, -1, 0, 0,
                              math.nan, int(north(lat0, 0) * 1e7), int(lon0 * 1e7), 5)
    hud = [wait_for(conn, "VFR_HUD", lambda h: h.groundspeed > 0.3, timeout=20).groundspeed]
    for _ in range(12):
        hud.append(wait_for(conn, "VFR_HUD", lambda h: True, timeout=3).groundspeed)
    assert max(hud) < 0.65
    # DO_SET_HOME: NaN refused; a position accepted and reported in HOME_POSITION
    assert command(conn, m.MAV_CMD_DO_SET_HOME, 0, 0, 0, 0, math.nan, math.nan, math.nan) == m.MAV_RESULT_DENIED
    new = (north(lat0, 3), east(lat0, lon0, 4))
    assert command(conn, m.MAV_CMD_DO_SET_HOME, 0, 0, 0, 0, new[0], new[1], 295.0) == m.MAV_RESULT_ACCEPTED
    hp = wait_for(conn, "HOME_POSITION", lambda h: abs(h.latitude / 1e7 - new[0]) < 1e-6, timeout=6)
    assert abs(hp.longitude / 1e7 - new[1]) < 1e-6
    assert command(conn, m.MAV_CMD_NAV_RETURN_TO_LAUNCH) == m.MAV_RESULT_ACCEPTED
    wait_for(conn, "EXTENDED_SYS_STATE", lambda e: e.landed_state == m.MAV_LANDED_STATE_ON_GROUND, timeout=60)
    back = wait_for(conn, "GLOBAL_POSITION_INT", lambda p: True, timeout=3)
    assert abs(back.lat / 1e7 - new[0]) < 3e-6 and abs(back.lon / 1e7 - new[1]) < 3e-6  # landed at the new home
    assert node.p.poll() is None and "Traceback" not in node.stderr


def test_mavproxy_sets_the_current_waypoint(tmp_path: Path, start: Start) -> None:
    """MAVProxy 1.8.75: `wp load` uploads, `wp set 2` (DO_SET_MISSION_CURRENT) is acknowledged and
    MISSION_CURRENT says 2; the mission then starts at item 2 (MISSION_START's param1 would say
    where to start, as on PX4: mode AUTO.MISSION continues from the current item)."""
    mavproxy_exe()
    lat0, lon0 = 46.0503, 14.4686
    rows = ["QGC WPL 110", f"0\t1\t0\t16\t0\t0\t0\t0\t{lat0}\t{lon0}\t295\t1"]
    for i, (n, e) in enumerate(((6, 0), (6, 6), (0, 6)), start=1):
        rows.append(f"{i}\t0\t3\t16\t0\t0\t0\t0\t{north(lat0, n):.7f}\t{east(lat0, lon0, e):.7f}\t5\t1")
    (tmp_path / "mission.txt").write_text("\n".join(rows) + "\n")
    port = free_port()
    node = start("onboard", "emulate", "onboard", "--gcs", f"udpout:{LOCAL}:{port}", "--listen", f"udpin:{LOCAL}:0",
                 "--no-entry-points", "--speed", "4")
    node.wait_for("onboard 1:")
    out = run_mavproxy(port, (("", 6.0), ("wp load mission.txt", 3.0), ("wp set 2", 2.0), ("arm throttle", 1.0),
                              ("long DO_SET_MODE 129 4 4", 8.0)), tmp_path)  # PX4's AUTO.MISSION: from the current item
    assert "Loaded 4 waypoint" in out or "Sent all 4 waypoints" in out, out[-2000:]
    assert "waypoint 2" in out, out[-2000:]
    assert "mission resumed at item 2" in node.stderr and "mission complete" in node.stderr, node.stderr
    assert "Traceback" not in node.stderr


def test_link_loss_watches_the_ground_station_flying_not_a_tablet_heard_once(start: Start) -> None:
    """A tablet is heard once and never again; a ground station (sending HEARTBEATs) arms and takes
    off: its flight goes on long past COM_DL_LOSS_T. When the ground station falls silent, its
    link is lost: hover, then return."""
    import socket

    from pymavlink import mavutil

    from conftest import shipped

    port = free_port()
    conn = mavutil.mavlink_connection(f"udpin:{LOCAL}:{port}", source_system=255, source_component=190,
                                      dialect="common")
    m = mavutil.mavlink
    node = start("onboard", "emulate", "onboard", "--gcs", f"udpout:{LOCAL}:{port}", "--listen", f"udpin:{LOCAL}:0",
                 "--no-entry-points", "--speed", "4")
    node.wait_for("onboard 1:")
    assert conn.recv_match(type="HEARTBEAT", blocking=True, timeout=10) is not None
    b = shipped()
    dtt = int(node.stderr.split("tablet link udpin:127.0.0.1:")[1].split(";")[0])
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.sendto(b.encoder(255, 190).encode(b.Heartbeat(type=6, autopilot=8, base_mode=0, custom_mode=0,
                                                        system_status=4, mavlink_version=3)), (LOCAL, dtt))
    node.wait_for("dtt: answering")  # the tablet was heard, once

    def pump(seconds: float, beat: bool) -> int:
        """Read for `seconds`, sending a HEARTBEAT every 0.25 s if `beat`; the last relative_alt."""
        end, alt = time.monotonic() + seconds, -1
        while time.monotonic() < end:
            if beat:
                conn.mav.heartbeat_send(m.MAV_TYPE_GCS, m.MAV_AUTOPILOT_INVALID, 0, 0, m.MAV_STATE_ACTIVE)
            r = conn.recv_match(type="GLOBAL_POSITION_INT", blocking=True, timeout=0.25)
            if r is not None:
                alt = r.relative_alt
        return alt

    pump(0.5, True)
    for name, value in (("COM_DL_LOSS_T", 3.0), ("COM_RTL_AFTER_T", 2.0), ("MIS_TAKEOFF_ALT", 5.0)):
        conn.mav.param_set_send(1, 1, name.encode(), value, m.MAV_PARAM_TYPE_REAL32)
        echo = wait_for(conn, "PARAM_VALUE", lambda p, name=name: p.param_id == name, timeout=3)
        assert echo.param_value == pytest.approx(value)
    assert command(conn, m.MAV_CMD_COMPONENT_ARM_DISARM, 1) == m.MAV_RESULT_ACCEPTED
    assert command(conn, m.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, math.nan, math.nan, math.nan, math.nan) == \
        m.MAV_RESULT_ACCEPTED  # to MIS_TAKEOFF_ALT
    assert pump(7.0, True) > 4500  # the tablet silent past COM_DL_LOSS_T and COM_RTL_AFTER_T (wall clock)
    assert "link lost" not in node.stderr and "hovering" in node.stderr
    pump(2.0, False)  # the ground station falls silent
    node.wait_for("ground station 255 link lost", timeout=5)
    node.wait_for("ground station 255 link still lost: returning home", timeout=6)
    assert "tablet link lost" not in node.stderr and "Traceback" not in node.stderr
