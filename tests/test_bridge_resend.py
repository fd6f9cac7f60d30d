"""The bridge's resends of one-shot requests (bridge/resend.py) and the vehicle's retry rule
(onboard/gcs.py) together, sans-IO: frames go through the real encoder and parser."""

from __future__ import annotations

import math
from typing import Any

from conftest import shipped
from flight_lib import Sim
from ttctl.bridge.resend import BOUND, Resender

WHO = (254, 190)


class Up:
    """The bridge's side: what it would put in the uplink queue; `held` frames still wait there."""

    def __init__(self) -> None:
        self.b = shipped()
        self.parser = self.b.parser()
        self.held: set[bytes] = set()
        self.r = Resender(lambda msg, seq, who: bytes(msg.pack(seq, *who)), lambda f: f in self.held)

    def request(self, now: float, msg: Any) -> Any:
        frame = bytes(self.b.encoder(*WHO).encode(msg))
        (m,) = self.parser.feed(frame)
        self.r.request(now, m.NAME, m, WHO, frame)
        return m

    def decode(self, frame: bytes) -> Any:
        (m,) = self.parser.feed(frame)
        return m


def command(b: Any, cmd: int, *p: float, confirmation: int = 0) -> Any:
    q = [*p] + [0.0] * (7 - len(p))
    return b.CommandLong(target_system=1, target_component=1, command=cmd, confirmation=confirmation,
                         param1=q[0], param2=q[1], param3=q[2], param4=q[3], param5=q[4], param6=q[5], param7=q[6])


def test_a_command_is_resent_with_confirmation_counted_up_until_its_ack() -> None:
    u = Up()
    b = u.b
    u.request(0.0, command(b, 512, 242))
    assert u.r.tick(0.1) == []  # within a round trip
    times = [t / 10 for t in range(1, 60)]
    sent = [(t, u.decode(f)) for t in times for _, f in u.r.tick(t)]
    assert [m.confirmation for _, m in sent] == list(range(1, len(sent) + 1)) and len(sent) >= 3
    assert sent[-1][0] < BOUND and not u.r.pending  # bounded
    u.request(10.0, command(b, 512, 242))
    u.r.answer(10.3, b.CommandAck(command=512, result=0, target_system=WHO[0], target_component=WHO[1]), WHO)
    # REQUEST_MESSAGE(HOME_POSITION) accepted, but the message travels apart and was lost: asked again
    assert u.r.pending and [n for n, _ in u.r.tick(11.2)] == ["COMMAND_LONG"]
    u.r.answer(11.5, b.HomePosition(latitude=1, longitude=2, altitude=3, x=0, y=0, z=0, q=[1, 0, 0, 0],
                                    approach_x=0, approach_y=0, approach_z=0), None)
    assert not u.r.pending and u.r.tick(12.0) == []  # answered: no resend
    u.request(20.0, command(b, 512, 9999))  # refused: the ack is the whole answer
    u.r.answer(20.3, b.CommandAck(command=512, result=3, target_system=WHO[0], target_component=WHO[1]), WHO)
    assert not u.r.pending


def test_no_resend_while_the_request_still_waits_in_the_uplink_queue() -> None:
    u = Up()
    b = u.b
    frame = bytes(b.encoder(*WHO).encode(b.ParamRequestRead(target_system=1, target_component=1,
                                                            param_id=b"MPC_XY_CRUISE", param_index=-1)))
    u.held.add(frame)
    (m,) = u.parser.feed(frame)
    u.r.request(0.0, m.NAME, m, WHO, frame)
    assert u.r.tick(2.0) == []
    u.held.clear()
    assert [n for n, _ in u.r.tick(3.5)] == ["PARAM_REQUEST_READ"]
    pv = b.ParamValue(param_id=b"MPC_XY_CRUISE", param_value=5.0, param_type=9, param_count=1, param_index=3)
    u.r.answer(3.6, pv, None)
    assert not u.r.pending


def test_a_takeoff_resent_by_the_bridge_after_a_land_is_not_done_again() -> None:
    """The vehicle did a take-off and then a land for the same station; the bridge's resend of the
    take-off (its ack lost) comes after: answered ACCEPTED as before, the vehicle lands on."""
    s = Sim()
    b, C = s.b, s.b.MavCmd
    assert s.command(int(C.MAV_CMD_COMPONENT_ARM_DISARM), 1) == 0
    takeoff = command(b, int(C.MAV_CMD_NAV_TAKEOFF), 0, 0, 0, math.nan, math.nan, math.nan, 305)
    s.send(takeoff)
    s.run(3.0)
    assert s.command(int(C.MAV_CMD_NAV_LAND)) == 0
    s.g.out.clear()
    takeoff.confirmation = 1  # the bridge's resend
    s.send(takeoff)
    acks = [m for m, _ in s.g.out if m.NAME == "COMMAND_ACK"]
    assert [(a.command, a.result) for a in acks] == [(int(C.MAV_CMD_NAV_TAKEOFF), 0)]
    s.run(0.5)
    assert s.v.snapshot().state.name == "LANDING", s.v.snapshot().state
    s.send(command(b, int(C.MAV_CMD_NAV_TAKEOFF), 0, 0, 0, math.nan, math.nan, math.nan, 305))  # a new one: done
    s.run(0.5)
    assert s.v.snapshot().state.name != "LANDING"


def test_a_flood_of_requests_is_followed_boundedly_and_resends_stop_at_the_bound() -> None:
    """A station flooding parameter reads: at most MAX_PENDING followed (the oldest left to the
    station), each resent a few times at most, none after BOUND."""
    from ttctl.bridge.resend import MAX_PENDING

    u = Up()
    b = u.b
    for i in range(500):
        u.request(i * 0.001, b.ParamRequestRead(target_system=1, target_component=1, param_id=f"P{i}".encode(),
                                                param_index=-1))
    assert len(u.r.pending) == MAX_PENDING
    sent = [f for t in range(1, 100) for _, f in u.r.tick(0.5 + t / 10)]
    assert len(sent) <= 4 * MAX_PENDING and not u.r.pending and u.r.given_up == MAX_PENDING
    # a command for another component (a camera) is not followed: the onboard end answers for the autopilot
    u.request(20.0, b.CommandLong(target_system=1, target_component=100, command=512, confirmation=0, param1=0,
                                  param2=0, param3=0, param4=0, param5=0, param6=0, param7=0))
    assert not u.r.pending


def ftp(b: Any, seq: int, opcode: int, offset: int = 0, req_opcode: int = 0, to: tuple[int, int] = (1, 1)) -> Any:
    import struct

    head = struct.pack("<HBBBBBBI", seq, 0, opcode, 239 if opcode in (5, 15) else 0, req_opcode, 0, 0, offset)
    return b.FileTransferProtocol(target_network=0, target_system=to[0], target_component=to[1],
                                  payload=list(head + bytes(251 - len(head))))


def test_an_ftp_request_the_station_sent_twice_is_resent_until_its_reply() -> None:
    """MAVLink FTP: a request is followed from the station's own retry (mavftp asks for every gap of
    a burst at once; following those would flood the uplink), resent until the reply of sequence
    number + 1 for that opcode; a burst read never (a resend would start the burst again)."""
    u = Up()
    b = u.b
    u.request(0.0, ftp(b, 24, 5, 4063))  # ReadFile, sent once: the station's own business
    u.request(0.0, ftp(b, 2, 15))  # BurstReadFile
    assert not u.r.pending and [f for t in range(1, 40) for f in u.r.tick(t / 10)] == []
    u.request(4.0, ftp(b, 24, 5, 4063))  # its retry: followed now
    u.request(4.0, ftp(b, 2, 15))  # (a burst's retry: still not)
    sent = [u.decode(f) for t in range(41, 75) for _, f in u.r.tick(t / 10)]
    assert len(sent) >= 2 and all(bytes(m.payload[:3]) == bytes([24, 0, 0]) and m.payload[3] == 5 for m in sent)
    # the reply to another request (seq 23 answered as 24), or to another opcode, is not its answer
    u.r.answer(7.5, ftp(b, 24, 128, 3107, req_opcode=5, to=WHO), WHO)
    u.r.answer(7.5, ftp(b, 25, 128, 5258, req_opcode=15, to=WHO), WHO)
    assert list(u.r.pending) == [(WHO, "ftp", 24, 5)]
    u.r.answer(7.6, ftp(b, 25, 128, 4063, req_opcode=5, to=WHO), WHO)  # ACK of seq 24's ReadFile
    assert not u.r.pending and u.r.tick(9.0) == []
