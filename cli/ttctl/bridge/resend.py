"""A ground station's one-shot requests, delivered over DTT as over a wire: the bridge sends again
what the link may have lost until the vehicle's answer passes back down, or BOUND passes.

MAVProxy sends a command, `wp list` or a parameter read once; over a radio that loses one packet
in ten, one such request in five went unanswered (the request or its answer lost). Telemetry
radios retransmit for this (ExpressLRS's "stubborn sender"); here the bridge, which sees both the
request going up and the answer coming down, resends the request at the link's round trip (its
own measure: request to answer, from requests answered at the first send), backing off, for at
most BOUND seconds. What answers what:

- COMMAND_LONG / COMMAND_INT: the COMMAND_ACK for that command to that station; for a command
  that asks for a message (MAV_CMD_REQUEST_MESSAGE, REQUEST_AUTOPILOT_CAPABILITIES,
  GET_HOME_POSITION) also that message, which travels apart from the ack and is lost apart from
  it (an accepting ack without it is not the answer: QGroundControl waits 3 s before asking
  again for AUTOPILOT_VERSION, the first thing it asks). A resent
  COMMAND_LONG goes with its confirmation counted up, which the vehicle takes as a retry of one it
  did (answered with its recorded result, never done twice: onboard/gcs.py); a COMMAND_INT, which
  has no confirmation, is taken as a retry when it equals one done within its REPEAT seconds.
- MISSION_REQUEST_LIST: that station's MISSION_COUNT (or a MISSION_ACK); MISSION_REQUEST_INT (one
  the bridge passed up): that item (or a MISSION_ACK); MISSION_CLEAR_ALL: a MISSION_ACK.
  (MISSION_COUNT and the items of an upload are resent by missions.py, which knows the upload.)
- PARAM_REQUEST_READ, PARAM_SET: a PARAM_VALUE of that name (or index); PARAM_REQUEST_LIST: any
  PARAM_VALUE (the list has begun; the station asks again for what it misses).
- FILE_TRANSFER_PROTOCOL (MAVLink FTP), once the station has sent the same request (its sequence
  number and opcode) a second time: the reply of sequence number + 1 for that opcode. A reply is a
  frame of up to 266 bytes, three or four DTT packets, so at 10 % loss a third of them are lost,
  and pymavlink's mavftp, once its burst is done, asks for a missing piece once a second and gives
  the download up after 5 s without a reply (a lost open: after three tries). The vehicle answers a
  request it has answered with its recorded reply, so a resend is safe. Not a burst read (its
  answer is a burst, which a resend would start again), and not before the station's own retry:
  mavftp asks for all the gaps of a burst at once, and following each of those would flood the
  uplink with resends of requests whose replies only queue behind the burst.

A resend is not made while the request (or an earlier send of it) still waits in the bridge's
uplink queue: the link has not had it yet, and the resends use that queue, inside its share of
the uplink and behind the app's own commands. Sans-IO: `request` when a station's frame goes up,
`answer` for each frame the vehicle sends a station, `tick` for the frames to send again.
"""

from __future__ import annotations

import struct
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

BOUND = 4.0  # s after the station's request: no more resends (a station's own retry starts it again)
FIRST_RTT = 0.4  # s: the round trip assumed before one is measured (m100: 0.2-0.3 s)
MIN_RTO, MAX_RTO = 0.3, 1.5  # s: a resend's wait, at least and at most
BACKOFF = 1.5
MAX_PENDING = 32  # requests followed at once; beyond that the oldest is left to its station
REQUESTS = frozenset({"COMMAND_LONG", "COMMAND_INT", "MISSION_REQUEST_LIST", "MISSION_REQUEST_INT",
                      "MISSION_REQUEST", "MISSION_CLEAR_ALL", "PARAM_REQUEST_READ", "PARAM_SET",
                      "PARAM_REQUEST_LIST", "FILE_TRANSFER_PROTOCOL"})
FTP_HEADER = struct.Struct("<HBBBB")  # seq, session, opcode, size, req_opcode (MAVLink FTP's payload)
FTP_BURST = 15  # BurstReadFile
FTP_SEEN = 64  # FTP requests remembered to know a station's retry

Key = tuple[Any, ...]

# commands whose answer is a message as well as the ack: command id -> the message id (None: param1)
ASKS_FOR = {512: None, 520: 148, 410: 242}  # REQUEST_MESSAGE; AUTOPILOT_VERSION; HOME_POSITION
ACCEPTED = 0  # MAV_RESULT_ACCEPTED


@dataclass
class _Pending:
    name: str
    msg: Any  # the station's message, as decoded
    who: tuple[int, int]  # the ids it is carried under
    frame: bytes  # the last frame of it sent up
    first: float  # when the station sent it (its latest send)
    due: float  # when to send it again
    rto: float
    sends: int = 1
    seq: int = 0
    wants: int | None = None  # a command asking for a message: that message's id
    acked: bool = False  # ... its COMMAND_ACK (accepted) has come
    got: bool = False  # ... the message has come


class Resender:
    """`pack(msg, seq, who)` makes the frame of `msg` as carried under `who`; `waiting(frame)`
    says whether the uplink queue still holds that frame (it has not gone yet)."""

    def __init__(self, pack: Callable[[Any, int, tuple[int, int]], bytes], waiting: Callable[[bytes], bool],
                 bound: float = BOUND) -> None:
        self.pack = pack
        self.waiting = waiting
        self.bound = bound
        self.pending: OrderedDict[Key, _Pending] = OrderedDict()
        self.srtt: float | None = None
        self.rttvar = FIRST_RTT / 4  # (a first resend after 0.8 s: three within BOUND)
        self.resent = 0  # frames sent again
        self.answered = 0  # requests whose answer came
        self.rescued = 0  # ... after a resend
        self.given_up = 0  # requests BOUND passed over without an answer
        self._ftp_seen: OrderedDict[Key, None] = OrderedDict()  # FTP requests sent once by their station

    def rto(self) -> float:
        srtt = FIRST_RTT if self.srtt is None else self.srtt
        return min(MAX_RTO, max(MIN_RTO, srtt + 4 * self.rttvar))

    @staticmethod
    def key(name: str, msg: Any, who: tuple[int, int]) -> Key | None:
        """What identifies the request and its answer; None: not a request followed here."""
        if name in ("COMMAND_LONG", "COMMAND_INT"):
            if int(getattr(msg, "target_component", 0)) not in (0, 1):
                return None  # (another component: the onboard end answers for the autopilot only)
            return who, "cmd", int(msg.command)
        if name == "MISSION_REQUEST_LIST":
            return who, "mlist", int(msg.mission_type)
        if name in ("MISSION_REQUEST_INT", "MISSION_REQUEST"):
            return who, "mitem", int(msg.mission_type), int(msg.seq)
        if name == "MISSION_CLEAR_ALL":
            return who, "mclear"
        if name in ("PARAM_REQUEST_READ", "PARAM_SET"):
            index = int(getattr(msg, "param_index", -1))
            return who, "param", _name(msg.param_id) if index < 0 else index
        if name == "PARAM_REQUEST_LIST":
            return who, "params"
        if name == "FILE_TRANSFER_PROTOCOL":
            seq, _, opcode, _, _ = _ftp_header(msg)
            if int(msg.target_network) != 0 or opcode == FTP_BURST:
                return None
            return who, "ftp", seq, opcode
        return None

    # -- a station's request going up ------------------------------------------------------------
    def request(self, now: float, name: str, msg: Any, who: tuple[int, int], frame: bytes) -> None:
        if name not in REQUESTS:
            return
        key = self.key(name, msg, who)
        if key is None:
            return
        if key[1] == "ftp" and key not in self.pending and key not in self._ftp_seen:
            self._ftp_seen[key] = None  # followed from the station's own retry on
            while len(self._ftp_seen) > FTP_SEEN:
                self._ftp_seen.popitem(last=False)
            return
        p = self.pending.pop(key, None)
        if p is not None and p.name == name:  # the station's own retry (or a new one like it): followed afresh
            p.msg, p.frame, p.first, p.due, p.rto = msg, frame, now, now + self.rto(), self.rto()
        else:
            p = _Pending(name, msg, who, frame, now, now + self.rto(), self.rto(), seq=msg.get_seq())
        if name in ("COMMAND_LONG", "COMMAND_INT") and int(msg.command) in ASKS_FOR:
            wants = ASKS_FOR[int(msg.command)]
            param1 = float(msg.param1)
            p.wants = wants if wants is not None else (int(param1) if param1 == param1 and param1 >= 0 else None)
            p.acked = p.got = False
        self.pending[key] = p
        while len(self.pending) > MAX_PENDING:
            self.pending.popitem(last=False)

    # -- the vehicle's answer coming down ----------------------------------------------------------
    def answer(self, now: float, msg: Any, who: tuple[int, int] | None) -> None:
        """A frame from the vehicle for the station carried as `who` (None: for every station)."""
        name = msg.NAME
        done: list[Key] = []
        msgid = getattr(msg, "MSG_ID", None)
        for key, waits in self.pending.items():  # a message a command asked for (AUTOPILOT_VERSION has no target)
            if waits.wants is not None and waits.wants == msgid and (who is None or key[0] == who):
                waits.got = True
                if waits.acked:
                    done.append(key)
        if name == "COMMAND_ACK" and who is not None:
            key = (who, "cmd", int(msg.command))
            waits_for = self.pending.get(key)
            if waits_for is not None and waits_for.wants is not None and not waits_for.got \
                    and int(msg.result) == ACCEPTED:
                waits_for.acked = True  # the message is still to come (or was lost): not answered yet
            else:
                done.append(key)
        elif name == "PARAM_VALUE":  # (no target: every station gets it)
            pid, index = _name(msg.param_id), int(msg.param_index)
            done += [k for k in self.pending if k[1] == "params" or (k[1] == "param" and k[2] in (pid, index))]
        elif name == "MISSION_COUNT" and who is not None:
            done.append((who, "mlist", int(msg.mission_type)))
        elif name in ("MISSION_ITEM_INT", "MISSION_ITEM") and who is not None:
            done.append((who, "mitem", int(msg.mission_type), int(msg.seq)))
        elif name == "MISSION_ACK" and who is not None:
            done += [k for k in self.pending if k[0] == who and k[1] in ("mlist", "mitem", "mclear")]
        elif name == "FILE_TRANSFER_PROTOCOL" and who is not None:
            seq, _, _, _, req_opcode = _ftp_header(msg)
            done.append((who, "ftp", (seq - 1) & 0xFFFF, req_opcode))
        for k in done:
            p = self.pending.pop(k, None)
            if p is None:
                continue
            self.answered += 1
            if p.sends == 1:  # an unrepeated request only (Karn): its round trip
                self._sample(now - p.first)
            else:
                self.rescued += 1

    def _sample(self, rtt: float) -> None:
        rtt = min(5.0, max(0.0, rtt))
        if self.srtt is None:
            self.srtt, self.rttvar = rtt, rtt / 2
        else:
            self.rttvar = 0.75 * self.rttvar + 0.25 * abs(self.srtt - rtt)
            self.srtt = 0.875 * self.srtt + 0.125 * rtt

    # -- time ----------------------------------------------------------------------------------------
    def tick(self, now: float) -> list[tuple[str, bytes]]:
        """(name, frame) to put in the uplink queue again now."""
        out: list[tuple[str, bytes]] = []
        for key in list(self.pending):
            p = self.pending[key]
            if now - p.first >= self.bound:
                del self.pending[key]
                self.given_up += 1
                continue
            if now < p.due:
                continue
            if self.waiting(p.frame):  # not gone yet: its round trip starts when it goes
                p.due = now + p.rto
                continue
            if p.name == "COMMAND_LONG":  # counted up: the vehicle takes it as a retry, never a second command
                p.msg.confirmation = min(255, int(p.msg.confirmation) + 1)
            p.seq = (p.seq + 1) & 0xFF
            p.frame = self.pack(p.msg, p.seq, p.who)
            p.sends += 1
            p.rto = min(MAX_RTO * 2, p.rto * BACKOFF)
            p.due = now + p.rto
            self.resent += 1
            out.append((p.name, p.frame))
        return out

    def deadline(self) -> float | None:
        return min((p.due for p in self.pending.values()), default=None)


def _ftp_header(msg: Any) -> tuple[int, int, int, int, int]:
    """(seq, session, opcode, size, req_opcode) of a FILE_TRANSFER_PROTOCOL's payload."""
    return FTP_HEADER.unpack_from(bytes(msg.payload).ljust(FTP_HEADER.size, b"\0"))


def _name(raw: Any) -> str:
    if isinstance(raw, bytes):
        raw = raw.decode("utf-8", "replace")
    return str(raw).split("\x00", 1)[0]
