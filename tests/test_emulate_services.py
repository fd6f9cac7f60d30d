"""`ttctl emulate onboard`'s services to ground stations, against real peers on loopback:
TIMESYNC, SYSTEM_TIME, GET_MESSAGE_INTERVAL, the log list, and the streams MAVSDK's telemetry
getters read (pymavlink as the oracle)."""

from __future__ import annotations

import math
import time
from pathlib import Path
from typing import Any

import pytest

from e2e_lib import LOCAL, Start, free_port, mavproxy_exe, run_mavproxy
from test_emulate_onboard import command, gcs, wait_for

__all__ = ["gcs"]  # the fixture, shared


def test_timesync_system_time_and_message_intervals(gcs: tuple[Any, Any]) -> None:
    conn, _ = gcs
    mav = conn.mav
    ts1 = 123_456_789
    mav.timesync_send(0, ts1)
    sync = wait_for(conn, "TIMESYNC", lambda m: m.ts1 == ts1, timeout=3)
    assert sync.tc1 > 0
    st = wait_for(conn, "SYSTEM_TIME", lambda m: True, timeout=3)
    assert abs(st.time_unix_usec / 1e6 - time.time()) < 2.0
    # GET_MESSAGE_INTERVAL reports what SET_MESSAGE_INTERVAL set, off (-1) and never sent (0)
    assert command(conn, 511, 31, 100_000) == 0  # ATTITUDE_QUATERNION at 10 Hz
    assert command(conn, 510, 31) == 0
    mi = wait_for(conn, "MESSAGE_INTERVAL", lambda m: m.message_id == 31, timeout=3)
    assert mi.interval_us == 100_000
    assert command(conn, 511, 141, -1) == 0  # ALTITUDE off
    assert command(conn, 510, 141) == 0
    assert wait_for(conn, "MESSAGE_INTERVAL", lambda m: m.message_id == 141, timeout=3).interval_us == -1
    assert command(conn, 510, 9000) == 0
    assert wait_for(conn, "MESSAGE_INTERVAL", lambda m: m.message_id == 9000, timeout=3).interval_us == 0
    for bad in (math.nan, math.inf, -1.0, 1.5, 2.0**30):
        mav.command_long_send(1, 1, 510, 0, bad, 0, 0, 0, 0, 0, 0)
        got = []
        end = time.monotonic() + 3
        while time.monotonic() < end and not any(m.get_type() == "COMMAND_ACK" for m in got):
            m = conn.recv_match(type=["COMMAND_ACK", "STATUSTEXT"], blocking=True, timeout=0.5)
            got += [m] if m is not None else []
        assert [m.result for m in got if m.get_type() == "COMMAND_ACK"] == [2]  # DENIED, and why:
        assert any("GET_MESSAGE_INTERVAL" in m.text for m in got if m.get_type() == "STATUSTEXT"), got
    assert command(conn, 519, 1) == 3  # REQUEST_PROTOCOL_VERSION: UNSUPPORTED (PROTOCOL_VERSION is not in the dialect)


def test_streams_asked_for_all_at_once_leave_the_on_request_ones_off(gcs: tuple[Any, Any]) -> None:
    conn, _ = gcs
    conn.mav.request_data_stream_send(1, 1, 0, 4, 1)  # MAVProxy's REQUEST_DATA_STREAM(ALL, 4 Hz)
    seen: set[str] = set()
    end = time.monotonic() + 2.0
    while time.monotonic() < end:
        m = conn.recv_match(blocking=True, timeout=0.5)
        if m is not None:
            seen.add(m.get_type())
    assert {"ATTITUDE_QUATERNION", "ODOMETRY", "HIGHRES_IMU", "WIND_COV"} <= seen
    assert not seen & {"HIL_STATE_QUATERNION", "SCALED_IMU"}
    assert command(conn, 511, 115, 200_000) == 0  # until asked for by name
    wait_for(conn, "HIL_STATE_QUATERNION", lambda m: m.lat == 460503000, timeout=3)


def test_log_list_is_answered_empty(gcs: tuple[Any, Any]) -> None:
    conn, _ = gcs
    conn.mav.log_request_list_send(1, 1, 0, 0xFFFF)
    entry = wait_for(conn, "LOG_ENTRY", lambda m: True, timeout=3)
    assert (entry.num_logs, entry.id, entry.size) == (0, 0, 0)


def test_streams_agree_with_the_attitude_and_position(gcs: tuple[Any, Any]) -> None:
    conn, _ = gcs
    assert command(conn, 400, 1) == 0
    assert command(conn, 22, 0, 0, 0, math.nan, math.nan, math.nan, math.nan) == 0  # to the default height
    pos = wait_for(conn, "GLOBAL_POSITION_INT", lambda m: m.relative_alt > 1800 and abs(m.vz) < 5, timeout=20)
    alt = wait_for(conn, "ALTITUDE", lambda m: m.altitude_relative > 1.8, timeout=5)
    assert abs(alt.altitude_amsl - pos.alt / 1000) < 1.0 and abs(alt.altitude_local - alt.altitude_relative) < 1e-3
    att = wait_for(conn, "ATTITUDE", lambda m: True, timeout=3)
    q = wait_for(conn, "ATTITUDE_QUATERNION", lambda m: True, timeout=3)
    assert abs(math.hypot(q.q1, q.q2, q.q3, q.q4) - 1) < 1e-5
    yaw = math.atan2(2 * (q.q1 * q.q4 + q.q2 * q.q3), 1 - 2 * (q.q3**2 + q.q4**2))
    assert abs(math.remainder(yaw - att.yaw, math.tau)) < 0.05
    odo = wait_for(conn, "ODOMETRY", lambda m: True, timeout=3)
    local = wait_for(conn, "LOCAL_POSITION_NED", lambda m: True, timeout=3)
    assert abs(odo.z - local.z) < 0.5 and odo.z < -1.8
    assert (odo.frame_id, odo.child_frame_id) == (1, 12)  # LOCAL_NED, velocity in BODY_FRD, as PX4 sends it
    imu = wait_for(conn, "HIGHRES_IMU", lambda m: True, timeout=3)
    assert abs(math.hypot(imu.xacc, imu.yacc, imu.zacc) - 9.81) < 0.3 and imu.zacc < -9.0  # hovering
    press = wait_for(conn, "SCALED_PRESSURE", lambda m: True, timeout=3).press_abs
    assert abs(press - 1013.25 * (1 - 2.25577e-5 * pos.alt / 1000) ** 5.25588) < 0.3  # the standard atmosphere
    assert math.isnan(odo.pose_covariance[0])


@pytest.mark.parametrize("mode", ["tcpin", "tcp"])
def test_ground_station_links_over_tcp(tmp_path: Path, start: Start, mode: str) -> None:
    """`--gcs tcpin:` takes ground stations' connections, `--gcs tcp:` connects to one: real TCP
    both ways (heartbeats out, a command in and its ack back), and a second connection after
    the first closed is served as well."""
    from pymavlink import mavutil

    port = free_port()
    listener = None
    if mode == "tcp":  # the ground station listens (as MAVProxy's --master=tcpin: does)
        listener = mavutil.mavlink_connection(f"tcpin:{LOCAL}:{port}", source_system=255, source_component=190,
                                              dialect="common")
    node = start("onboard", "emulate", "onboard", "--gcs", f"{mode}:{LOCAL}:{port}", "--listen", f"udpin:{LOCAL}:0",
                 "--no-entry-points")
    node.wait_for("onboard 1:")
    assert f"ground stations {mode}:{LOCAL}:{port}" in node.stderr
    for _ in range(2 if mode == "tcpin" else 1):
        conn = listener or mavutil.mavlink_connection(f"tcp:{LOCAL}:{port}", source_system=255,
                                                      source_component=190, dialect="common")
        try:
            hb = conn.recv_match(type="HEARTBEAT", blocking=True, timeout=10)
            assert hb is not None and hb.get_srcSystem() == 1, node.stderr
            conn.target_system, conn.target_component = 1, 1
            assert command(conn, 400, 1) == 0  # arm, over TCP
            wait_for(conn, "HEARTBEAT", lambda m: m.base_mode & 128, timeout=5)
            assert command(conn, 400, 0) == 0
        finally:
            conn.close()
            listener = None
        time.sleep(0.3)
    assert "Traceback" not in node.stderr


def test_a_tcp_ground_station_that_is_not_there_is_refused_in_one_line(start: Start) -> None:
    port = free_port()
    node = start("onboard", "emulate", "onboard", "--gcs", f"tcp:{LOCAL}:{port}", "--listen", f"udpin:{LOCAL}:0",
                 "--no-entry-points")
    assert node.wait() == 2
    assert node.stderr.strip().splitlines()[-1].startswith(f"ttctl: error: cannot connect to tcp:{LOCAL}:{port}")


def test_ground_station_links_signed_with_gcs_key(tmp_path: Path, start: Start) -> None:
    """--gcs-key: every frame to ground stations is signed (pymavlink, holding the key,
    verifies them), a signed command is carried out, an unsigned one is ignored and said once."""
    import hashlib

    from pymavlink import mavutil

    key_file = tmp_path / "gcs.key"
    key_file.write_text("rehearsal passphrase\n")
    port = free_port()
    conn = mavutil.mavlink_connection(f"udpin:{LOCAL}:{port}", source_system=255, source_component=190,
                                      dialect="common")
    node = start("onboard", "emulate", "onboard", "--gcs", f"udpout:{LOCAL}:{port}", "--listen", f"udpin:{LOCAL}:0",
                 "--no-entry-points", "--gcs-key", str(key_file))
    node.wait_for("onboard 1:")
    try:
        assert conn.recv_match(blocking=True, timeout=10) is not None  # mavutil now speaks MAVLink 2: key it
        conn.setup_signing(hashlib.sha256(b"rehearsal passphrase").digest(), sign_outgoing=True)
        hb = conn.recv_match(type="HEARTBEAT", blocking=True, timeout=10)
        assert hb is not None and hb._signed, node.stderr  # pymavlink refuses unsigned frames once keyed
        conn.target_system, conn.target_component = 1, 1
        assert command(conn, 400, 1) == 0
        wait_for(conn, "HEARTBEAT", lambda m: m.base_mode & 128, timeout=5)
        assert command(conn, 400, 0) == 0
        wait_for(conn, "HEARTBEAT", lambda m: not m.base_mode & 128, timeout=5)
        conn.mav.signing.sign_outgoing = False
        conn.mav.command_long_send(1, 1, 400, 0, 1, 0, 0, 0, 0, 0, 0)
        assert conn.recv_match(type="COMMAND_ACK", blocking=True, timeout=2) is None
        assert not wait_for(conn, "HEARTBEAT", lambda m: True, timeout=3).base_mode & 128
        assert "unsigned frames or signatures that do not verify" in node.stderr
    finally:
        conn.close()
    bad = start("bad", "emulate", "onboard", "--gcs-key", str(tmp_path / "none.key"), "--no-gcs")
    assert bad.wait() == 2
    assert "ttctl: error: --gcs-key " in bad.stderr and "Traceback" not in bad.stderr


def test_hostile_ftp_over_the_link_never_stops_the_node(gcs: tuple[Any, Any], tmp_path: Path) -> None:
    """Thousands of FTP requests with random payloads, bursts and traversing paths: answered
    (or ignored when not FTP at all), nothing written outside the inbox, the node still flies."""
    import random
    import struct

    conn, node = gcs
    rnd = random.Random(19)
    before = sorted(p.name for p in tmp_path.iterdir())
    for i in range(3000):
        if i % 3 == 0:
            payload = bytes(rnd.getrandbits(8) for _ in range(251))
        else:
            op = rnd.choice([4, 5, 6, 7, 8, 9, 10, 12, 13, 14, 15])
            path = rnd.choice([b"/inbox/../../x", b"/inbox/a/../../y", b"../../z", b"/inbox/" + b"n" * 230,
                               b"/inbox/ok.bin", b"\xff\xfe", b"/serve/x", b""])
            payload = struct.pack("<HBBBBBBI", i, rnd.randrange(4), op, min(len(path), 239), 0, 0, 0,
                                  rnd.choice([0, 2**31, 2**32 - 1])) + path[:239]
        conn.mav.file_transfer_protocol_send(0, 1, 1, list(payload.ljust(251, b"\0")))
        if i % 200 == 0:
            time.sleep(0.01)
    naks = 0
    end = time.monotonic() + 3
    while time.monotonic() < end:
        m = conn.recv_match(type="FILE_TRANSFER_PROTOCOL", blocking=True, timeout=0.5)
        if m is not None and m.payload[3] == 129:
            naks += 1
    assert naks > 100
    assert sorted(p.name for p in tmp_path.iterdir()) == before  # nothing beside the inbox
    assert all(p.resolve().is_relative_to((tmp_path / "inbox").resolve()) for p in (tmp_path / "inbox").rglob("*"))
    assert command(conn, 400, 1) == 0  # still flying
    assert "Traceback" not in node.stderr


def test_mavproxy_flies_over_a_signed_link(tmp_path: Path, start: Start) -> None:
    """MAVProxy 1.8.75 with `signing key PASSPHRASE` arms a vehicle started with --gcs-key holding
    the same passphrase; once it stops signing (`signing remove`) its disarm is ignored."""
    import re
    mavproxy_exe()
    (tmp_path / "gcs.key").write_text("rehearsal\n")
    port = free_port()
    node = start("onboard", "emulate", "onboard", "--gcs", f"udpout:{LOCAL}:{port}", "--listen", f"udpin:{LOCAL}:0",
                 "--no-entry-points", "--gcs-key", str(tmp_path / "gcs.key"))
    node.wait_for("onboard 1:")
    out = run_mavproxy(port, (("signing key rehearsal", 3.0), ("arm throttle", 1.5), ("status HEARTBEAT", 0.5),
                              ("signing remove", 0.5), ("disarm", 1.5), ("status HEARTBEAT", 0.5)), tmp_path)
    assert "COMPONENT_ARM_DISARM: ACCEPTED" in out, out[-2000:]
    modes = [int(m) for m in re.findall(r"HEARTBEAT \{type : 2, autopilot : \d+, base_mode : (\d+)", out)]
    assert len(modes) == 2 and all(m & 128 for m in modes), out[-2000:]  # armed, and still armed
