"""MAVLink FTP and the other services of `ttctl emulate onboard`, with unmodified ground stations
as real peers on loopback: MAVProxy 1.8.75 on a pipe (`ftp list/get/put`, its parameter download
not waiting for an FTP answer) and MAVSDK 4 in a child process of its own (ftp upload/download, the log list, the
attitude quaternion, odometry and altitude getters). Files compared by SHA-256."""

from __future__ import annotations

import hashlib
import math
import os
import re
import time
from pathlib import Path
from typing import Any

import pytest

from e2e_lib import LOCAL, Start, free_port, mavproxy_exe, run_mavproxy, until
from mavsdk_child import fly


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


_until = until


def onboard(start: Start, tmp_path: Path, port: int, *extra: str) -> Any:
    serve = tmp_path / "serve"
    serve.mkdir(exist_ok=True)
    node = start("onboard", "emulate", "onboard", "--gcs", f"udpout:{LOCAL}:{port}", "--listen", f"udpin:{LOCAL}:0",
                 "--no-entry-points", "--serve", str(serve), "--inbox", str(tmp_path / "inbox"), *extra)
    node.wait_for("onboard 1:")
    return node


def test_mavproxy_lists_gets_and_puts_files(tmp_path: Path, start: Start) -> None:
    mavproxy_exe()
    port = free_port()
    node = onboard(start, tmp_path, port)
    (tmp_path / "serve" / "down.bin").write_bytes(os.urandom(60_001))
    work = tmp_path / "mavproxy"
    work.mkdir()
    (work / "up.bin").write_bytes(os.urandom(30_000))
    # 3.5 s: the parameters arrive without MAVProxy waiting for an FTP answer about @PARAM
    out = run_mavproxy(port, (("", 3.5), ("ftp list /", 1.0), ("ftp list /serve", 1.0),
                              ("ftp get /serve/down.bin got.bin", 2.5), ("ftp put up.bin /inbox/up.bin", 2.5),
                              ("ftp put up.bin /serve/no.bin", 1.5), ("ftp get /serve/../../etc/passwd pw", 1.5),
                              ("ftp list /inbox", 1.0), ("log list", 1.0)), work)
    got = re.search(r"Received \d+ parameters", out)
    assert got and got.start() < out.index("Listing /"), out[-3000:]  # within 3.5 s, before the first command
    assert " D inbox" in out and " D serve" in out and "down.bin\t60001" in out
    assert sha(work / "got.bin") == sha(tmp_path / "serve" / "down.bin")
    assert sha(tmp_path / "inbox" / "up.bin") == sha(work / "up.bin")
    assert "up.bin\t30000" in out
    assert not (tmp_path / "serve" / "no.bin").exists() and not (work / "pw").exists()
    assert "Requesting log list\nNo logs" in out  # LOG_REQUEST_LIST answered: no logs
    assert "Traceback" not in node.stderr




def test_mavsdk_moves_files_and_reads_logs_and_every_attitude(tmp_path: Path, start: Start) -> None:
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")
    from mavsdk.asyncio.plugins.ftp import FtpAsync, FtpError
    from mavsdk.asyncio.plugins.log_files import LogFilesAsync, LogFilesError
    from mavsdk.asyncio.plugins.telemetry import TelemetryAsync

    port = free_port()
    node = onboard(start, tmp_path, port)
    (tmp_path / "serve" / "route.csv").write_bytes(os.urandom(20_000))
    local = tmp_path / "local"
    local.mkdir()
    (local / "plan.bin").write_bytes(os.urandom(12_345))

    async def main(m: Any) -> None:
        await m.add_any_connection(f"udpin://{LOCAL}:{port}")
        system = await m.first_autopilot(timeout_s=15)
        assert system is not None
        ftp, logs, tel = FtpAsync(system), LogFilesAsync(system), TelemetryAsync(system)
        listing = await ftp.list_directory("/")
        assert sorted((e.name, e.entry_type.name) for e in listing.entries) == [("inbox", "DIRECTORY"),
                                                                          ("serve", "DIRECTORY")], listing
        async for _ in ftp.upload(str(local / "plan.bin"), "/inbox"):
            pass
        assert sha(tmp_path / "inbox" / "plan.bin") == sha(local / "plan.bin")
        assert await ftp.are_files_identical(str(local / "plan.bin"), "/inbox/plan.bin")
        down = tmp_path / "down"
        down.mkdir()
        for burst in (False, True):
            async for _ in ftp.download("/serve/route.csv", str(down), burst):
                pass
            assert sha(down / "route.csv") == sha(tmp_path / "serve" / "route.csv")
            (down / "route.csv").unlink()
        listing = await ftp.list_directory("/serve")
        assert [(e.name, e.size_bytes) for e in listing.entries] == [("route.csv", 20_000)], listing
        await ftp.create_directory("/inbox/day1")
        await ftp.rename("/inbox/plan.bin", "/inbox/day1/plan2.bin")
        assert sha(tmp_path / "inbox" / "day1" / "plan2.bin") == sha(local / "plan.bin")
        with pytest.raises(FtpError):
            await ftp.remove_directory("/inbox/day1")  # not empty
        await ftp.remove_file("/inbox/day1/plan2.bin")
        await ftp.remove_directory("/inbox/day1")
        assert [p.name for p in (tmp_path / "inbox").iterdir() if p.name != ".ttctl-partial"] == []
        with pytest.raises(FtpError, match="FILE_PROTECTED"):
            await ftp.remove_file("/serve/route.csv")
        assert (tmp_path / "serve" / "route.csv").exists()
        t0 = time.monotonic()
        with pytest.raises(LogFilesError, match="NO_LOGFILES"):  # answered at once: no logs (not TIMEOUT)
            await logs.get_entries()
        assert time.monotonic() - t0 < 2.0
        q = await _until(tel.attitude_quaternion, lambda q: math.isfinite(q.w), 5)
        assert abs(math.hypot(q.w, q.x, q.y, q.z) - 1) < 1e-4
        odo = await _until(tel.odometry, lambda o: math.isfinite(o.q.w), 5)
        assert abs(odo.position_body.z_m) < 0.5 and abs(math.hypot(odo.q.w, odo.q.x, odo.q.y, odo.q.z) - 1) < 1e-4
        alt = await _until(tel.altitude, lambda a: math.isfinite(a.altitude_amsl_m), 5)
        assert abs(alt.altitude_amsl_m - 295) < 1 and abs(alt.altitude_relative_m) < 0.5
        imu = await _until(tel.imu, lambda i: math.isfinite(i.acceleration_frd.down_m_s2), 5)
        assert abs(imu.acceleration_frd.down_m_s2 + 9.81) < 0.1  # standing still: thrust-free, gravity only
        assert abs(imu.magnetic_field_frd.forward_gauss) > 0.1
        pressure = await _until(tel.scaled_pressure, lambda p: p.absolute_pressure_hpa > 0, 5)
        assert 970 < pressure.absolute_pressure_hpa < 985  # 295 m above sea level
        wind = await _until(tel.wind, lambda w: math.isfinite(w.wind_x_ned_m_s), 5)
        assert wind.wind_x_ned_m_s == 0.0 and wind.wind_y_ned_m_s == 0.0
        await tel.set_rate_ground_truth(2.0)  # the simulation's truth, sent when asked for
        truth = await _until(tel.ground_truth, lambda g: math.isfinite(g.latitude_deg), 5)
        assert abs(truth.latitude_deg - 46.0503) < 1e-6 and abs(truth.absolute_altitude_m - 295) < 0.5

    fly(main, 90)
    assert "Traceback" not in node.stderr


def test_mavsdk_over_tcp(tmp_path: Path, start: Start) -> None:
    """`--gcs tcpin:` with MAVSDK connecting by `tcpout://`: the vehicle is found, its position
    read and its files listed over the one TCP connection."""
    pytest.importorskip("mavsdk", reason="mavsdk is in the test extra")
    from mavsdk.asyncio.plugins.ftp import FtpAsync
    from mavsdk.asyncio.plugins.telemetry import TelemetryAsync

    port = free_port()
    (tmp_path / "serve").mkdir()
    (tmp_path / "serve" / "a.txt").write_text("over tcp")
    node = start("onboard", "emulate", "onboard", "--gcs", f"tcpin:{LOCAL}:{port}", "--listen", f"udpin:{LOCAL}:0",
                 "--no-entry-points", "--serve", str(tmp_path / "serve"))
    node.wait_for("onboard 1:")

    async def main(m: Any) -> None:
        await m.add_any_connection(f"tcpout://{LOCAL}:{port}")
        system = await m.first_autopilot(timeout_s=15)
        assert system is not None
        pos = await _until(TelemetryAsync(system).position, lambda p: math.isfinite(p.latitude_deg), 10)
        assert abs(pos.latitude_deg - 46.0503) < 1e-6
        listing = await FtpAsync(system).list_directory("/serve")
        assert [(e.name, e.size_bytes) for e in listing.entries] == [("a.txt", 8)]

    fly(main, 60)
    assert "connection from" in node.stderr and "Traceback" not in node.stderr
