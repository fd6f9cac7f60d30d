"""MAVSDK (4.x, the ctypes library, no server), unmodified, as the ground station of `ttctl emulate
onboard`: it connects, sees position, home, armed, in-air and flight mode, arms, takes off,
lands, returns to launch, uploads and downloads a mission, reads and sets parameters; and one
MAVSDK sees a fleet of five onboard ends as five vehicles (real processes on loopback)."""

from __future__ import annotations

import asyncio
import math
import time
from pathlib import Path
from typing import Any

import pytest

from e2e_lib import LOCAL, Start, free_port, until
from machine import scaled
from mavsdk_child import fly

mavsdk = pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")


def onboard(start: Start, port: int, sysid: int = 1, name: str = "onboard") -> Any:
    node = start(name, "emulate", "onboard", "--gcs", f"udpout:{LOCAL}:{port}", "--listen", f"udpin:{LOCAL}:0",
                 "--no-entry-points", "--speed", "4", "--sysid", str(sysid))
    node.wait_for(f"onboard {sysid}:")
    return node


_until = until


def test_mavsdk_flies_the_emulated_vehicle(tmp_path: Path, start: Start) -> None:
    from mavsdk.asyncio.plugins.action import ActionAsync, ActionError
    from mavsdk.asyncio.plugins.mission import MissionAsync
    from mavsdk.asyncio.plugins.param import ParamAsync
    from mavsdk.asyncio.plugins.telemetry import TelemetryAsync
    from mavsdk.plugins.mission import MissionItem, MissionPlan
    from mavsdk.plugins.telemetry import FlightMode

    port = free_port()
    node = onboard(start, port)

    async def main(m: Any) -> None:
        await m.add_any_connection(f"udpin://{LOCAL}:{port}")
        system = await m.first_autopilot(timeout_s=15)
        assert system is not None and await system.get_system_id() == 1
        tel, act, par, mis = TelemetryAsync(system), ActionAsync(system), ParamAsync(system), MissionAsync(system)
        home = await _until(tel.home, lambda h: abs(h.latitude_deg - 46.0503) < 1e-6, 10)
        # HOME_POSITION may come before the first GLOBAL_POSITION_INT (position is NaN until then)
        pos = await _until(tel.position, lambda p: abs(p.latitude_deg - home.latitude_deg) < 1e-6, 10)
        assert pos.relative_altitude_m < 0.1
        assert not await tel.armed() and not await tel.in_air()
        assert await tel.flight_mode() == FlightMode.HOLD
        await _until(tel.health, lambda h: h.is_armable and h.is_global_position_ok, 10)
        with pytest.raises(ActionError, match="COMMAND_DENIED"):
            await act.land()  # on the ground
        assert await par.get_param_float("MPC_XY_VEL_MAX") == pytest.approx(1.5)
        await par.set_param_float("MPC_XY_VEL_MAX", 2.0)
        assert await par.get_param_float("MPC_XY_VEL_MAX") == pytest.approx(2.0)
        assert await par.get_param_int("NAV_DLL_ACT") == 2
        await act.arm()
        await _until(tel.armed, bool, 5)
        await act.set_takeoff_altitude(4.0)
        await act.takeoff()
        await _until(tel.position, lambda p: p.relative_altitude_m > 3.8, 20)
        assert await tel.in_air()
        items = [MissionItem(home.latitude_deg + 1e-4, home.longitude_deg + dlon, alt, 2.0, True, math.nan,
                             math.nan, MissionItem.CameraAction.NONE, math.nan, math.nan, math.nan, math.nan,
                             math.nan, MissionItem.VehicleAction.NONE)
                 for dlon, alt in ((0.0, 5.0), (1.4e-4, 6.0))]
        await mis.upload_mission(MissionPlan(items))
        plan = await mis.download_mission()
        assert [(round(i.latitude_deg, 7), round(i.longitude_deg, 7), i.relative_altitude_m)
                for i in plan.mission_items] == [(round(i.latitude_deg, 7), round(i.longitude_deg, 7),
                                                  i.relative_altitude_m) for i in items]
        await mis.start_mission()
        await _until(tel.flight_mode, lambda f: f == FlightMode.MISSION, 10)
        await _until(tel.position, lambda p: p.longitude_deg > home.longitude_deg + 1.2e-4, 60)
        await act.return_to_launch()
        await _until(tel.flight_mode, lambda f: f in (FlightMode.RETURN_TO_LAUNCH, FlightMode.LAND), 10)
        await _until(tel.in_air, lambda a: not a, 90)
        back = await tel.position()
        assert abs(back.latitude_deg - home.latitude_deg) < 2e-6
        assert abs(back.longitude_deg - home.longitude_deg) < 2e-6
        await _until(tel.armed, lambda a: not a, 10)  # disarmed on landing
        await act.arm()
        await act.takeoff()
        await _until(tel.position, lambda p: p.relative_altitude_m > 3.0, 20)
        await act.land()
        await _until(tel.landed_state, lambda s: s.name == "ON_GROUND", 60)

    fly(main, 240)
    assert "Traceback" not in node.stderr


def test_one_mavsdk_sees_a_fleet_of_five(tmp_path: Path, start: Start) -> None:
    port = free_port()
    for sysid in range(1, 6):
        onboard(start, port, sysid, name=f"onboard{sysid}")

    async def main(m: Any) -> None:
        await m.add_any_connection(f"udpin://{LOCAL}:{port}")
        end = time.monotonic() + scaled(20)
        while time.monotonic() < end and await m.system_count() < 5:
            await asyncio.sleep(0.2)
        assert await m.system_count() == 5
        ids = sorted([await s.get_system_id() for s in await m.get_systems()])
        assert ids == [1, 2, 3, 4, 5]

    fly(main, 60)
