"""A ground station that speaks MAVLink 1 (pymavlink's default without MAVLINK20) through `ttctl
emulate tablet --gcs` -> `link relay --profile m100` -> `emulate onboard`, real processes on
loopback: its frames are carried (upgraded to MAVLink 2 for the link) and it is answered in
MAVLink 1, which is all it reads. The v1 codec is pymavlink's own MAVLink 1 dialect, used
directly (whatever MAVLINK20 other tests set in this process)."""

from __future__ import annotations

import re
import socket
import threading

from pymavlink.dialects.v10 import common as v1

from e2e_lib import LOCAL, Start, free_port, relay
from ttctl.bench import shipped
from ttctl.wire.v1 import Upgrader, downgrade
from v1_station import V1Station


def test_a_mavlink1_ground_station_is_carried_and_answered_in_kind(start: Start) -> None:
    a, b = free_port(), free_port()
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{b}", "--no-entry-points",
                 "--profile", "m100")
    node.wait_for("onboard 1:")
    relay(start, a, b, "--profile", "m100", "--stats-interval", "0")
    g = free_port()
    st = V1Station(g)
    tablet = start("tablet", "emulate", "tablet", "--to", f"udpout:{LOCAL}:{a}", "--profile", "m100",
                   "--gcs", f"udpout:{LOCAL}:{g}")
    tablet.wait_for("tablet: connected")
    while st.peer is None:  # the bridge's first (MAVLink 2) frames say where it is
        try:
            st.peer = st.sock.recvfrom(4096)[1]
        except TimeoutError:
            continue
    beater = threading.Thread(target=st.beat, daemon=True)
    beater.start()
    try:
        hb = st.recv("HEARTBEAT", lambda x: x.get_srcSystem() == 1 and x.get_srcComponent() == 1, 15)
        assert hb.autopilot == v1.MAV_AUTOPILOT_PX4
        ack = None
        for confirmation in range(6):  # as ground stations retry (the m100 link loses a little)
            st.send(st.mav.command_long_encode(1, 1, v1.MAV_CMD_COMPONENT_ARM_DISARM, confirmation, 1, 0, 0, 0, 0, 0,
                                               0))
            try:
                ack = st.recv("COMMAND_ACK", lambda x: x.command == v1.MAV_CMD_COMPONENT_ARM_DISARM, 2.0)
                break
            except AssertionError:
                continue
        assert ack is not None and ack.result == v1.MAV_RESULT_ACCEPTED
        assert len(ack.get_msgbuf()) == 8 + 3  # MAVLink 1's COMMAND_ACK: command and result, no extensions
        st.recv("HEARTBEAT", lambda x: x.get_srcComponent() == 1 and x.base_mode & 128, 10)  # armed, says so
        st.send(st.mav.param_request_read_encode(1, 1, b"", 0))
        assert st.recv("PARAM_VALUE", timeout=10).param_index == 0
    finally:
        st.stop.set()
    assert st.v2_frames == 0  # it was never sent what it cannot read
    tablet.signal(2)
    assert tablet.wait(10) == 0
    got = re.search(r"MAVLink 1: (\d+) up, (\d+) down", tablet.stderr)
    assert got and int(got.group(1)) >= 3 and int(got.group(2)) >= 10, tablet.stderr
    assert "Traceback" not in tablet.stderr


def test_mavlink1_frames_upgrade_and_downgrade_byte_for_byte() -> None:
    """Sans-IO: pymavlink's MAVLink 1 frames, split anywhere and mixed with MAVLink 2 and garbage,
    come out as the same messages; a bad CRC and an id the dialect lacks are dropped and counted;
    an answer goes back as the MAVLink 1 frame pymavlink itself would make."""
    b = shipped.bindings()
    mav = v1.MAVLink(None, srcSystem=255, srcComponent=190)
    frames = [bytes(mav.command_long_encode(1, 1, 400, 0, 1, 0, 0, 0, 0, 0, 0).pack(mav)),
              bytes(mav.heartbeat_encode(6, 8, 0, 0, 0).pack(mav)),
              bytes(mav.mission_request_list_encode(1, 1).pack(mav))]
    bad = bytearray(frames[1])
    bad[-1] ^= 0xFF
    unknown = bytes((0xFE, 1, 0, 255, 190, 250, 7, 0, 0))  # msgid 250 is not in the dialect... unless it is
    v2 = bytes(b.encoder(255, 190).encode(b.message("PING")(time_usec=5, seq=1, target_system=1,
                                                              target_component=1)))
    stream = frames[0] + b"\x00\x13" + bytes(bad) + frames[1] + v2 + frames[2]
    stream += unknown if b.registry.get(250) is None else b""
    told: list[int] = []
    for cut in range(1, len(stream)):
        u = Upgrader(b.registry, told.append)
        parser = b.parser()
        out = parser.feed(u.feed(stream[:cut])) + parser.feed(u.feed(stream[cut:]))
        assert [m.NAME for m in out] == ["COMMAND_LONG", "HEARTBEAT", "PING", "MISSION_REQUEST_LIST"], cut
        assert (out[0].command, out[0].param1, out[0].get_srcSystem()) == (400, 1.0, 255)
        assert u.v1_frames == 3 and u.v1_bad_crc >= 1
    assert set(told) <= {250}
    ack = bytes(b.encoder(1, 1).encode(b.message("COMMAND_ACK")(command=400, result=0, progress=0, result_param2=0,
                                                                  target_system=255, target_component=190)))
    old = downgrade(ack, b.registry)
    ref = v1.MAVLink(None, srcSystem=1, srcComponent=1)
    ref.seq = ack[4]
    assert old == bytes(ref.command_ack_encode(400, 0).pack(ref))
    assert downgrade(v2.replace(v2[7:10], (50011).to_bytes(3, "little"), 1), b.registry) is None  # id over 255


def test_a_mavlink1_ground_station_on_the_onboard_ends_own_link(start: Start) -> None:
    """`emulate onboard --gcs udpout:...` (where the station listens): the same station is taken
    and answered in MAVLink 1 once it has spoken; a MAVLink 1 station on a listening link is
    taken, and told in one line that answers there go as MAVLink 2."""
    g, h = free_port(), free_port()
    st = V1Station(g)
    node = start("onboard", "emulate", "onboard", "--gcs", f"udpout:{LOCAL}:{g}", "--gcs", f"udpin:{LOCAL}:{h}",
                 "--listen", f"udpin:{LOCAL}:0", "--no-entry-points")
    node.wait_for("onboard 1:")
    while st.peer is None:
        try:
            st.peer = st.sock.recvfrom(4096)[1]
        except TimeoutError:
            continue
    beater = threading.Thread(target=st.beat, daemon=True)
    beater.start()
    try:
        st.recv("HEARTBEAT", lambda x: x.get_srcComponent() == 1, 10)
        st.send(st.mav.command_long_encode(1, 1, v1.MAV_CMD_COMPONENT_ARM_DISARM, 0, 1, 0, 0, 0, 0, 0, 0))
        assert st.recv("COMMAND_ACK", lambda x: x.command == v1.MAV_CMD_COMPONENT_ARM_DISARM).result == 0
        other = v1.MAVLink(None, srcSystem=247, srcComponent=190)
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            s.sendto(other.heartbeat_encode(6, 8, 0, 0, 0).pack(other), (LOCAL, h))
            node.wait_for("speaks MAVLink 1", 10)
    finally:
        st.stop.set()
    assert st.v2_frames == 0
    assert node.stderr.count("speaks MAVLink 1") == 1 and "Traceback" not in node.stderr
