"""The ground station of `ttctl bench gcs`: a pymavlink peer doing what QGroundControl does at
connect, and a mission upload and download, with QGroundControl's timeouts and retries.

Timeouts and retries, from QGroundControl's source (src/FactSystem/ParameterManager.h,
src/MissionManager/PlanManager.h, src/Vehicle/Vehicle.cc):
- HEARTBEAT at 1 Hz as 255/190; the vehicle is the first HEARTBEAT from component 1;
- MAV_CMD_REQUEST_MESSAGE(AUTOPILOT_VERSION) to component 1: 3 tries, 3 s each;
- PARAM_REQUEST_LIST to all components: again after 5 s without a PARAM_VALUE, 4 times at most;
  once values come, 3 s without a new one sends PARAM_REQUEST_READ by index for the missing
  ones, at most 10 in flight, each index 5 times at most;
- missions: MISSION_REQUEST_LIST / MISSION_COUNT again after 1.5 s without an answer, an item
  (MISSION_REQUEST_INT) again after 0.25 s, 5 retries each; the download ends with MISSION_ACK.
  QGroundControl gives up an upload when 1.5 s pass without a request after the first item (it
  counts on the vehicle to ask again) or without the last MISSION_ACK; this peer sends the last
  item again in the first case and starts over (MISSION_COUNT) in the second, within the same 5
  retries, so a lost frame costs time, not the run.

With an FTP step (`bench gcs --ftp KB`), after the mission the peer listens for a few seconds, then
fetches a file from the vehicle by MAVLink FTP with pymavlink's own client (mavftp, whole 239-byte
reads): the longest gap between the vehicle's HEARTBEATs and the rate of its GLOBAL_POSITION_INT
during the download, against the same while idle just before (issue 29).

Every GLOBAL_POSITION_INT is stamped on receipt: its age is the receive time minus the moment
the vehicle stamped it (time_boot_ms), placed on this machine's clock by SYSTEM_TIME (which
carries time_unix_usec and time_boot_ms of one instant; both ends share the clock on loopback).
Without SYSTEM_TIME the offset is the minimum over the run (ages then start at 0).
"""

from __future__ import annotations

import itertools
import math
import os
import time
from dataclasses import dataclass, field
from typing import Any

HEARTBEAT_S = 1.0
COMMAND_TRIES, COMMAND_TIMEOUT = 3, 3.0
PARAM_LIST_TIMEOUT, PARAM_LIST_RETRIES = 5.0, 4
PARAM_WAIT, PARAM_BATCH, PARAM_READ_TRIES = 3.0, 10, 5
MISSION_ACK_TIMEOUT, MISSION_ITEM_TIMEOUT, MISSION_RETRIES = 1.5, 0.25, 5
VEHICLE_COMPID = 1
AUTOPILOT_VERSION = 148
MAV_CMD_REQUEST_MESSAGE = 512
HOME = (46.0503, 14.4686)


class StepFailed(Exception):
    """A step of the sequence gave up, in QGroundControl's manner; the words say why."""


@dataclass
class Figures:
    connect_s: float | None = None
    heartbeat_s: float | None = None  # to the vehicle's first HEARTBEAT
    version_s: float | None = None  # REQUEST_MESSAGE(AUTOPILOT_VERSION) to its answer
    mission_list_s: float | None = None  # the connect's mission download (the vehicle's plan)
    params_s: float | None = None
    param_count: int = 0
    param_reads: int = 0  # PARAM_REQUEST_READ sent for missing indices
    upload_s: float | None = None
    upload_restarts: int = 0
    ack_wait_s: float | None = None  # the last item first sent -> the upload's MISSION_ACK
    download_s: float | None = None
    items_checked: bool = False  # the 20 items downloaded are the ones uploaded
    ages_ms: list[float] = field(default_factory=list)
    age_method: str = ""
    ftp_s: float | None = None  # the FTP download
    hb_gap_idle_s: float | None = None  # the longest HEARTBEAT gap, listening idle just before it
    hb_gap_ftp_s: float | None = None  # ... during it
    gpi_idle_hz: float | None = None  # GLOBAL_POSITION_INT a second, idle and during it
    gpi_ftp_hz: float | None = None
    failed: dict[str, str] = field(default_factory=dict)  # step -> why


class QgcLikePeer:
    """Blocking, on one thread: every wait pumps the socket and sends the 1 Hz HEARTBEAT."""

    def __init__(self, port: int, target: int = 1, sysid: int = 255, compid: int = 190,
                 deadline_s: float = 60.0, sticks_hz: float = 0.0) -> None:
        os.environ["MAVLINK20"] = "1"  # QGroundControl speaks MAVLink 2 (pymavlink picks its bindings by this)
        from pymavlink import mavutil

        self.mavutil = mavutil
        self.conn = mavutil.mavlink_connection(f"udpin:127.0.0.1:{port}", source_system=sysid,
                                               source_component=compid, dialect="common", robust_parsing=True)
        self.m = mavutil.mavlink
        self.target = target
        self.deadline_s = deadline_s  # per step
        self.next_hb = 0.0
        self.sticks_s = 1.0 / sticks_hz if sticks_hz > 0 else None  # MANUAL_CONTROL, as a joystick sends it
        self.next_stick = 0.0
        self.sticks = 0
        self.boot_unix: float | None = None
        self.positions: list[tuple[float, int]] = []  # (receive unix time, time_boot_ms)
        self.heard = False
        self.f = Figures()
        self.beats: list[float] = []  # when each of the vehicle's HEARTBEATs came (whoever read it: mavftp too)
        self.fixes: list[float] = []  # ... each GLOBAL_POSITION_INT
        self.conn.message_hooks.append(self._hook)

    def close(self) -> None:
        self.conn.close()

    # -- the socket -----------------------------------------------------------------------------
    def _send(self, msg: Any) -> None:
        self.conn.mav.send(msg)  # to whoever it heard (pymavlink's udpin sends nothing before that)

    def recv(self, until: float) -> Any:
        """The next message from the vehicle, or None at `until` (monotonic)."""
        while True:
            now = time.monotonic()
            if now >= self.next_hb:
                self.next_hb = now + HEARTBEAT_S
                self._send(self.m.MAVLink_heartbeat_message(self.m.MAV_TYPE_GCS, self.m.MAV_AUTOPILOT_INVALID,
                                                            0, 0, 0, 3))
            wake = min(until, self.next_hb)
            if self.sticks_s is not None and self.heard:
                if now >= self.next_stick:
                    self.next_stick = max(now, self.next_stick + self.sticks_s)
                    self.sticks += 1  # centred sticks, throttle at hover (z 500), as QGC's joystick sends
                    self._send(self.m.MAVLink_manual_control_message(self.target, 0, 0, 500, 0, 0))
                wake = min(wake, self.next_stick)
            if now >= until:
                return None
            msg = self.conn.recv_match(blocking=True, timeout=max(0.001, wake - now))
            if msg is None or msg.get_type() == "BAD_DATA" or msg.get_srcSystem() != self.target:
                continue
            self._note(msg)
            return msg

    def _hook(self, conn: Any, msg: Any) -> None:
        if msg.get_type() == "BAD_DATA" or (msg.get_srcSystem(), msg.get_srcComponent()) != (self.target,
                                                                                                VEHICLE_COMPID):
            return
        if msg.get_type() == "HEARTBEAT":
            self.beats.append(time.monotonic())
        elif msg.get_type() == "GLOBAL_POSITION_INT":
            self.fixes.append(time.monotonic())

    def _stream(self, t0: float, t1: float) -> tuple[float, float]:
        """The longest HEARTBEAT gap and the GLOBAL_POSITION_INT rate between t0 and t1."""
        beats = [t0, *(t for t in self.beats if t0 <= t <= t1), t1]
        gap = max(b - a for a, b in itertools.pairwise(beats))
        return round(gap, 2), round(sum(1 for t in self.fixes if t0 <= t <= t1) / (t1 - t0), 2)

    def ftp(self, path: str, expect: bytes, idle_s: float = 6.0) -> None:
        """Listen `idle_s`, then fetch `path` by MAVLink FTP (pymavlink's mavftp): it must be `expect`."""
        from pymavlink import mavftp

        t0 = time.monotonic()
        self.pump(idle_s)
        t1 = time.monotonic()
        self.f.hb_gap_idle_s, self.f.gpi_idle_hz = self._stream(t0, t1)
        client = mavftp.MAVFTP(self.conn, target_system=self.target, target_component=VEHICLE_COMPID)
        client.ftp_settings.burst_read_size = 239
        got = client.read(path, len(expect))
        t2 = time.monotonic()
        self.f.hb_gap_ftp_s, self.f.gpi_ftp_hz = self._stream(t1, t2)
        if got != expect:
            raise StepFailed(f"FTP download of {path}: " + ("nothing came whole" if got is None else
                                                           f"{len(got)} bytes, not the {len(expect)} served"))
        self.f.ftp_s = t2 - t1

    def _note(self, msg: Any) -> None:
        kind = msg.get_type()
        if kind == "SYSTEM_TIME" and msg.time_unix_usec:
            self.boot_unix = msg.time_unix_usec / 1e6 - msg.time_boot_ms / 1e3
        elif kind == "GLOBAL_POSITION_INT" and self.heard:
            self.positions.append((time.time(), msg.time_boot_ms))

    def pump(self, seconds: float) -> None:
        until = time.monotonic() + seconds
        while self.recv(until) is not None:
            pass

    def ages(self) -> tuple[list[float], str]:
        if not self.positions:
            return [], ""
        if self.boot_unix is not None:
            boot = self.boot_unix
            method = "receive time - time_boot_ms, placed by the vehicle's SYSTEM_TIME"
        else:
            boot = min(t - ms / 1e3 for t, ms in self.positions)
            method = "receive time - time_boot_ms, offset = the run's minimum (no SYSTEM_TIME heard)"
        return [max(0.0, (t - boot - ms / 1e3) * 1000) for t, ms in self.positions], method

    # -- the connect sequence -----------------------------------------------------------------
    def connect(self) -> None:
        t0 = time.monotonic()
        self._wait_heartbeat()
        self.f.heartbeat_s = time.monotonic() - t0
        v0 = time.monotonic()
        self._autopilot_version()
        self.f.version_s = time.monotonic() - v0
        p0 = time.monotonic()
        self._params()
        self.f.params_s = time.monotonic() - p0
        m0 = time.monotonic()
        self._download(expect=None)
        self.f.mission_list_s = time.monotonic() - m0
        self.f.connect_s = time.monotonic() - t0

    def _wait_heartbeat(self) -> None:
        until = time.monotonic() + self.deadline_s
        while True:
            msg = self.recv(until)
            if msg is None:
                raise StepFailed(f"no HEARTBEAT from {self.target}/{VEHICLE_COMPID} in {self.deadline_s:g} s")
            if msg.get_type() == "HEARTBEAT" and msg.get_srcComponent() == VEHICLE_COMPID:
                self.heard = True
                return

    def _autopilot_version(self) -> None:
        acked = got = False
        for _ in range(COMMAND_TRIES):
            self._send(self.m.MAVLink_command_long_message(self.target, VEHICLE_COMPID, MAV_CMD_REQUEST_MESSAGE, 0,
                                                           AUTOPILOT_VERSION, 0, 0, 0, 0, 0, 0))
            until = time.monotonic() + COMMAND_TIMEOUT
            while not acked:
                msg = self.recv(until)
                if msg is None:
                    break
                kind = msg.get_type()
                got = got or kind == "AUTOPILOT_VERSION"
                if kind == "COMMAND_ACK" and msg.command == MAV_CMD_REQUEST_MESSAGE:
                    acked = True
            if acked:
                break
        if not acked:
            raise StepFailed(f"REQUEST_MESSAGE(AUTOPILOT_VERSION): no COMMAND_ACK in {COMMAND_TRIES} tries")
        until = time.monotonic() + COMMAND_TIMEOUT  # the message follows its ack, or was lost (QGC goes on)
        while not got:
            msg = self.recv(until)
            if msg is None:
                break
            got = msg.get_type() == "AUTOPILOT_VERSION"

    def _params(self) -> None:
        have: set[int] = set()
        count: int | None = None
        lists = 0
        tries: dict[int, int] = {}
        in_flight: list[int] = []
        last_value = time.monotonic()
        end = time.monotonic() + 4 * self.deadline_s
        self._send(self.m.MAVLink_param_request_list_message(self.target, 0))
        while count is None or len(have) < count:
            now = time.monotonic()
            if now >= end:
                raise StepFailed(f"parameters: {len(have)} of {count} after {4 * self.deadline_s:g} s")
            wait = last_value + (PARAM_LIST_TIMEOUT if count is None else PARAM_WAIT)
            msg = self.recv(min(wait, end))
            if msg is None:
                if time.monotonic() < wait:
                    continue
                if count is None:
                    lists += 1
                    if lists > PARAM_LIST_RETRIES:
                        raise StepFailed(f"parameters: no PARAM_VALUE after {lists} PARAM_REQUEST_LIST")
                    self._send(self.m.MAVLink_param_request_list_message(self.target, 0))
                else:
                    in_flight = [i for i in in_flight if i not in have]
                    for i in range(count):
                        if len(in_flight) >= PARAM_BATCH:
                            break
                        if i in have or i in in_flight:
                            continue
                        in_flight.append(i)
                    for i in in_flight:
                        tries[i] = tries.get(i, 0) + 1
                        if tries[i] > PARAM_READ_TRIES:
                            raise StepFailed(f"parameters: index {i} missing after {PARAM_READ_TRIES} reads")
                        self.f.param_reads += 1
                        self._send(self.m.MAVLink_param_request_read_message(self.target, VEHICLE_COMPID, b"", i))
                last_value = time.monotonic()
                continue
            if msg.get_type() != "PARAM_VALUE" or msg.get_srcComponent() != VEHICLE_COMPID:
                continue
            last_value = time.monotonic()
            count = msg.param_count
            if 0 <= msg.param_index < count:
                have.add(msg.param_index)
        self.f.param_count = count

    # -- missions -----------------------------------------------------------------------------
    def items(self, n: int) -> list[Any]:
        m = self.m
        out = []
        for i in range(n):
            angle = 2 * math.pi * i / n
            lat = HOME[0] + 0.0005 * math.cos(angle)
            lon = HOME[1] + 0.0007 * math.sin(angle)
            out.append(m.MAVLink_mission_item_int_message(
                self.target, VEHICLE_COMPID, i, m.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, m.MAV_CMD_NAV_WAYPOINT,
                0, 1, 0.0, 2.0, 0.0, float("nan"), round(lat * 1e7), round(lon * 1e7), 20.0 + i, 0))
        return out

    def upload(self, n: int) -> None:
        m = self.m
        items = self.items(n)
        t0 = time.monotonic()
        retries = 0
        last_sent: int | None = None
        last_item_at: float | None = None  # when the last item first went: the vehicle may have it all

        def count() -> None:
            self._send(m.MAVLink_mission_count_message(self.target, VEHICLE_COMPID, n, 0))

        count()
        until = time.monotonic() + MISSION_ACK_TIMEOUT
        while True:
            msg = self.recv(until)
            if msg is None:
                retries += 1
                if retries > MISSION_RETRIES:
                    raise StepFailed(f"mission upload: no answer after {MISSION_RETRIES} retries "
                                     f"(last item sent {last_sent})")
                if last_sent is None:
                    count()  # no item asked for yet: MISSION_COUNT again, as QGC does
                elif last_sent == n - 1:
                    self.f.upload_restarts += 1  # the last MISSION_ACK was lost: QGC would give up here
                    count()
                    last_sent = None
                else:
                    self._send(items[last_sent])  # QGC would give up; the vehicle ignores an item it has
                until = time.monotonic() + MISSION_ACK_TIMEOUT
                continue
            kind = msg.get_type()
            if kind in ("MISSION_REQUEST_INT", "MISSION_REQUEST") and msg.mission_type == 0:
                if not 0 <= msg.seq < n:
                    raise StepFailed(f"mission upload: the vehicle asked for item {msg.seq} of {n}")
                self._send(items[msg.seq])
                last_sent = msg.seq
                if msg.seq == n - 1 and last_item_at is None:
                    last_item_at = time.monotonic()
                retries = 0  # progress: the retries count again from here
                until = time.monotonic() + MISSION_ACK_TIMEOUT
            elif kind == "MISSION_ACK" and msg.mission_type == 0:
                if msg.type != m.MAV_MISSION_ACCEPTED:
                    raise StepFailed(f"mission upload: MISSION_ACK {msg.type}")
                if last_item_at is None:  # no attempt has sent every item yet: not ours
                    continue
                now = time.monotonic()
                self.f.upload_s = now - t0
                self.f.ack_wait_s = now - last_item_at  # QGroundControl gives up after 1.5 s
                return

    def download(self, n: int) -> None:
        t0 = time.monotonic()
        got = self._download(expect=n)
        self.f.download_s = time.monotonic() - t0
        want = self.items(n)
        self.f.items_checked = len(got) == n and all(
            (a.seq, a.x, a.y, a.command) == (b.seq, b.x, b.y, b.command) and abs(a.z - b.z) < 1e-3
            for a, b in zip(got, want, strict=True))

    def _download(self, expect: int | None) -> list[Any]:
        m = self.m
        retries = 0
        self._send(m.MAVLink_mission_request_list_message(self.target, VEHICLE_COMPID, 0))
        until = time.monotonic() + MISSION_ACK_TIMEOUT
        count: int | None = None
        got: list[Any] = []
        while count is None or len(got) < count:
            msg = self.recv(until)
            if msg is None:
                retries += 1
                if retries > MISSION_RETRIES:
                    raise StepFailed(f"mission download: no answer after {MISSION_RETRIES} retries "
                                     f"({len(got)} of {count} items)")
                if count is None:
                    self._send(m.MAVLink_mission_request_list_message(self.target, VEHICLE_COMPID, 0))
                    until = time.monotonic() + MISSION_ACK_TIMEOUT
                else:
                    self._request(len(got))
                    until = time.monotonic() + MISSION_ITEM_TIMEOUT
                continue
            kind = msg.get_type()
            if kind == "MISSION_COUNT" and msg.mission_type == 0 and count is None:
                count = msg.count
                retries = 0
                if expect is not None and count != expect:
                    raise StepFailed(f"mission download: {count} items, {expect} uploaded")
                if count:
                    self._request(0)
                    until = time.monotonic() + MISSION_ITEM_TIMEOUT
            elif kind == "MISSION_ITEM_INT" and count is not None and msg.seq == len(got):
                got.append(msg)
                retries = 0
                if len(got) < count:
                    self._request(len(got))
                    until = time.monotonic() + MISSION_ITEM_TIMEOUT
        self._send(m.MAVLink_mission_ack_message(self.target, VEHICLE_COMPID, m.MAV_MISSION_ACCEPTED, 0))
        return got

    def _request(self, seq: int) -> None:
        self._send(self.m.MAVLink_mission_request_int_message(self.target, VEHICLE_COMPID, seq, 0))


def run_sequence(peer: QgcLikePeer, items: int, linger: Any = None, ftp: tuple[str, bytes] | None = None) -> Figures:
    """Connect, upload `items`, download them (and fetch `ftp`'s file, if any); then keep the link
    up (heartbeats, position ages) until `linger()` is true. A step that fails is named in
    Figures.failed, and the rest skipped where they need it."""
    f = peer.f
    try:
        peer.connect()
    except StepFailed as e:
        f.failed["connect"] = str(e)
    if "connect" not in f.failed or peer.heard:
        for name, step in (("upload", lambda: peer.upload(items)), ("download", lambda: peer.download(items))):
            if name == "download" and "upload" in f.failed:
                break
            try:
                step()
            except StepFailed as e:
                f.failed[name] = str(e)
        if ftp is not None and peer.heard:
            try:
                peer.ftp(*ftp)
            except StepFailed as e:
                f.failed["ftp"] = str(e)
    while linger is not None and not linger():
        peer.pump(0.2)
    f.ages_ms, f.age_method = peer.ages()
    return f
