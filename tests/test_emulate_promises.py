"""The vehicle's promise, as a ground station and a tablet see it: a real `emulate onboard`
process, a pymavlink ground station on its --gcs link and a tablet speaking the shipped
dialect on its DTT link, both sending random sequences of commands (random parameters, NaN and
infinities among them, in random order, from both links). Every ACCEPTED must be followed by the
state it promises, read from the vehicle's own telemetry: the mode at once (or the mode that
documentedly follows it: a take-off ends in hold, a return in a landing), arming at once, a
take-off at its height, a landing or a return on the ground and disarmed, a reposition where it
was sent, a pause that holds, a new home where the vehicle is, in the documented time, unless a
later accepted command changed the plan. Every refusal comes with the vehicle's words."""

from __future__ import annotations

import math
import random
import socket
import threading
import time
from dataclasses import dataclass, field
from typing import Any

import pytest

from e2e_lib import LOCAL, Start, free_port

SPEED = 8.0  # the vehicle's clock against the wall clock
NAN, INF = float("nan"), float("inf")
M_PER_DEG = 111_319.49
# PX4 modes (main, sub): px4_custom_mode.h
MANUAL, ALTCTL, POSCTL, AUTO, OFFBOARD = 1, 2, 3, 4, 6
READY, TAKEOFF, LOITER, MISSION, RTL, LAND = 1, 2, 3, 4, 5, 6
MODES = [(MANUAL, 0), (ALTCTL, 0), (POSCTL, 0), (AUTO, LOITER), (AUTO, TAKEOFF), (AUTO, MISSION), (AUTO, RTL),
         (AUTO, LAND), (OFFBOARD, 0), (5, 0), (7, 0), (AUTO, 9), (99, 0)]
# what a mode documentedly becomes by itself: a take-off ends in hold, a landing on the ground
# (READY), a return in a landing, a mission in its end (hold, return or land)
AFTER = {(AUTO, TAKEOFF): {(AUTO, LOITER)}, (AUTO, LAND): {(AUTO, READY)},
         (AUTO, RTL): {(AUTO, LAND), (AUTO, READY)},
         (AUTO, MISSION): {(AUTO, LOITER), (AUTO, RTL), (AUTO, LAND), (AUTO, READY)}}
# the mission stored before the flights: take-off, then a square of waypoints 12 m wide
ROUTE = [(0.0, 0.0), (12.0, 0.0), (12.0, 12.0), (0.0, 12.0)]


@dataclass
class Seen:
    """The vehicle as its telemetry tells it (a thread keeps it current)."""

    mode: tuple[int, int] = (0, 0)
    armed: bool = False
    landed: int = 0  # EXTENDED_SYS_STATE.landed_state: 1 on ground, 2 in air, 3 taking off, 4 landing
    alt: float = 0.0  # relative, m
    n: float = 0.0
    e: float = 0.0
    speed: float = 0.0
    home: tuple[float, float] | None = None
    lat0: float = 0.0
    lon0: float = 0.0
    texts: list[tuple[float, str]] = field(default_factory=list)
    acks: list[tuple[float, int, int]] = field(default_factory=list)  # (when, command, result)
    tablet_acks: dict[int, int] = field(default_factory=dict)  # command_id -> result
    tablet_logs: list[tuple[float, str]] = field(default_factory=list)
    modes_seen: list[tuple[float, tuple[int, int]]] = field(default_factory=list)


class Rig:
    """The vehicle under test and its two peers."""

    def __init__(self, start: Start, seed: int) -> None:
        from pymavlink import mavutil

        import ttapi

        self.ttapi = ttapi
        port, self.dtt = free_port(), free_port()
        self.gcs = mavutil.mavlink_connection(f"udpin:{LOCAL}:{port}", source_system=255, source_component=190,
                                              dialect="common")
        self.node = start(f"onboard{seed}", "emulate", "onboard", "--gcs", f"udpout:{LOCAL}:{port}", "--listen",
                          f"udpin:{LOCAL}:{self.dtt}", "--no-entry-points", "--speed", str(SPEED))
        self.node.wait_for("onboard 1:")
        self.tablet = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.tablet.bind((LOCAL, 0))
        self.tablet.settimeout(0.1)
        self.enc = ttapi.Encoder(sysid=255, compid=190)
        self.parser = ttapi.Parser()
        self.seen = Seen()
        self.lock = threading.Lock()  # pymavlink's sender is not for two threads
        self.stop = threading.Event()
        hb = self.gcs.recv_match(type="HEARTBEAT", blocking=True, timeout=10)
        assert hb is not None, self.node.stderr
        self.gcs.target_system, self.gcs.target_component = 1, 1
        pos = self.gcs.recv_match(type="GLOBAL_POSITION_INT", blocking=True, timeout=10)
        self.seen.lat0, self.seen.lon0 = pos.lat / 1e7, pos.lon / 1e7
        m = mavutil.mavlink
        for msgid in (m.MAVLINK_MSG_ID_HEARTBEAT, m.MAVLINK_MSG_ID_GLOBAL_POSITION_INT,
                      m.MAVLINK_MSG_ID_EXTENDED_SYS_STATE, m.MAVLINK_MSG_ID_VFR_HUD):  # 10 Hz: see changes at once
            self.gcs.mav.command_long_send(1, 1, m.MAV_CMD_SET_MESSAGE_INTERVAL, 0, msgid, 100_000, 0, 0, 0, 0, 0)
        self.threads = [threading.Thread(target=self._gcs_loop, daemon=True),
                        threading.Thread(target=self._tablet_loop, daemon=True)]
        for t in self.threads:
            t.start()
        self._upload_mission()

    def close(self) -> None:
        self.stop.set()
        for t in self.threads:
            t.join(2)
        self.gcs.close()
        self.tablet.close()

    # -- the two peers' receive loops ------------------------------------------------------------

    def _gcs_loop(self) -> None:
        s = self.seen
        beat = 0.0
        while not self.stop.is_set():
            now = time.monotonic()
            if now - beat > 0.5:  # a ground station's HEARTBEAT: the vehicle watches the commanding link
                beat = now
                with self.lock:
                    self.gcs.mav.heartbeat_send(6, 8, 0, 0, 0)
            m = self.gcs.recv_match(blocking=True, timeout=0.05)
            if m is None or m.get_srcSystem() != 1:
                continue
            t, kind = time.monotonic(), m.get_type()
            if kind == "HEARTBEAT" and m.get_srcComponent() == 1:
                mode = ((m.custom_mode >> 16) & 0xFF, (m.custom_mode >> 24) & 0xFF)
                mode = (mode[0], mode[1] if mode[0] == AUTO else 0)
                if mode != s.mode:
                    s.modes_seen.append((t, mode))
                s.mode, s.armed = mode, bool(m.base_mode & 128)
            elif kind == "EXTENDED_SYS_STATE":
                s.landed = m.landed_state
            elif kind == "GLOBAL_POSITION_INT":
                s.alt = m.relative_alt / 1000.0
                s.n = (m.lat / 1e7 - s.lat0) * M_PER_DEG
                s.e = (m.lon / 1e7 - s.lon0) * M_PER_DEG * math.cos(math.radians(s.lat0))
            elif kind == "VFR_HUD":
                s.speed = m.groundspeed
            elif kind == "HOME_POSITION":
                s.home = ((m.latitude / 1e7 - s.lat0) * M_PER_DEG,
                          (m.longitude / 1e7 - s.lon0) * M_PER_DEG * math.cos(math.radians(s.lat0)))
            elif kind == "STATUSTEXT":
                s.texts.append((t, m.text))
            elif kind == "COMMAND_ACK":
                s.acks.append((t, m.command, m.result))
            elif kind in ("MISSION_REQUEST_INT", "MISSION_REQUEST", "MISSION_ACK"):
                self._mission_reply(m)

    def _tablet_loop(self) -> None:
        tt = self.ttapi
        beat = 0.0
        while not self.stop.is_set():
            now = time.monotonic()
            if now - beat > 0.5:  # the tablet app's keepalive
                beat = now
                self._to_vehicle(tt.Heartbeat(type=6, autopilot=8, base_mode=0, custom_mode=0, system_status=4,
                                              mavlink_version=3))
            try:
                data = self.tablet.recv(4096)
            except (TimeoutError, OSError):
                continue
            for msg in self.parser.feed(data):
                if isinstance(msg, tt.TtCommandAck):
                    self.seen.tablet_acks[msg.command_id] = msg.result
                elif isinstance(msg, tt.TtLog):
                    self.seen.tablet_logs.append((time.monotonic(), msg.text))

    def _to_vehicle(self, msg: Any) -> None:
        self.tablet.sendto(self.enc.encode(msg), (LOCAL, self.dtt))

    # -- the mission, stored once ------------------------------------------------------------------

    def _upload_mission(self) -> None:
        from pymavlink import mavutil

        m = mavutil.mavlink
        s = self.seen
        items = [(m.MAV_CMD_NAV_TAKEOFF, s.lat0, s.lon0)]
        for n, e in ROUTE:
            items.append((m.MAV_CMD_NAV_WAYPOINT, s.lat0 + n / M_PER_DEG,
                          s.lon0 + e / (M_PER_DEG * math.cos(math.radians(s.lat0)))))
        self.mission = items
        self.mission_acked = threading.Event()
        with self.lock:
            self.gcs.mav.mission_count_send(1, 1, len(items), 0)
        assert self.mission_acked.wait(10), "the mission upload did not end"

    def _mission_reply(self, req: Any) -> None:
        from pymavlink import mavutil

        m = mavutil.mavlink
        if req.get_type() == "MISSION_ACK":
            assert req.type == m.MAV_MISSION_ACCEPTED, req
            self.mission_acked.set()
            return
        cmd, lat, lon = self.mission[req.seq]
        with self.lock:
            self.gcs.mav.mission_item_int_send(1, 1, req.seq, m.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, cmd, 0, 1,
                                               0, 0, 0, NAN, int(lat * 1e7), int(lon * 1e7), 5.0, 0)

    # -- commands --------------------------------------------------------------------------------

    def command(self, cmd: int, *params: float) -> tuple[bool, list[str]]:
        """COMMAND_LONG from the ground station: accepted or not, and the vehicle's words after it."""
        p = list(params) + [0.0] * (7 - len(params))
        t0 = time.monotonic()
        with self.lock:
            self.gcs.mav.command_long_send(1, 1, cmd, 0, *p)
        end = t0 + 5
        while time.monotonic() < end:
            got = [r for t, c, r in self.seen.acks if t >= t0 and c == cmd]
            if got:
                return got[0] == 0, self._words(self.seen.texts, t0, got[0] == 0)  # MAV_RESULT_ACCEPTED
            time.sleep(0.02)
        raise AssertionError(f"no COMMAND_ACK for {cmd} in 5 s")

    def tablet_command(self, action: int, arg: float = 0.0) -> tuple[bool, list[str]]:
        tt = self.ttapi
        cid = random.randrange(1, 65535)
        t0 = time.monotonic()
        msg = tt.TtActionCommand(target_system=1, target_component=240, command_id=cid, action=action,
                                 time_usec=time.time_ns() // 1000, param=[arg, 0.0, 0.0, 0.0], argument="")
        end, resend = t0 + 6, t0
        while time.monotonic() < end:
            if time.monotonic() >= resend:  # a lossless link, but the tablet retries as the app does
                self._to_vehicle(msg)
                resend += 1.5
            if cid in self.seen.tablet_acks:
                ok = self.seen.tablet_acks[cid] in (0, 1, 2)  # TT_RESULT ACCEPTED, IN_PROGRESS, DONE
                return ok, self._words(self.seen.tablet_logs, t0, ok)
            time.sleep(0.02)
        raise AssertionError(f"no TT_COMMAND_ACK for action {action} in 6 s")

    @staticmethod
    def _words(log: list[tuple[float, str]], t0: float, accepted: bool) -> list[str]:
        if accepted:
            return []
        end = time.monotonic() + 1.5  # a refusal's words follow its ack
        while time.monotonic() < end:
            words = [text for t, text in log if t >= t0]
            if words:
                return words
            time.sleep(0.02)
        return []


@dataclass
class Promise:
    what: str
    until: float  # wall-clock deadline
    check: Any  # Seen -> bool
    why: str


def _vehicle_seconds(s: float) -> float:
    return s / SPEED + 1.5  # the wall clock, with a margin for telemetry at 10 Hz and a loaded machine


def _wait_until(rig: Rig, p: Promise) -> None:
    while time.monotonic() < p.until:
        if p.check(rig.seen):
            return
        time.sleep(0.05)
    s = rig.seen
    raise AssertionError(f"{p.what}: ACCEPTED, but not {p.why}: mode {s.mode}, armed {s.armed}, landed "
                         f"{s.landed}, alt {s.alt:.1f}, at {s.n:.1f} N {s.e:.1f} E, speed {s.speed:.1f}; "
                         f"said {[t for _, t in s.texts[-5:]]}\n{rig.node.stderr[-1500:]}")


def _mode_now(rig: Rig, want: tuple[int, int], what: str) -> None:
    """The promised mode, or what it documentedly turns into, within a moment."""
    ok = {want} | AFTER.get(want, set())
    _wait_until(rig, Promise(what, time.monotonic() + 1.5, lambda s: s.mode in ok, f"in mode {want}"))


def _step(rig: Rig, rng: random.Random) -> tuple[bool, list[Promise]]:
    """One random command from one of the two links: whether it was accepted, and the promises
    its ACCEPTED makes for later (a mode promised at once is checked here)."""
    from pymavlink import mavutil

    m = mavutil.mavlink
    s = rig.seen
    now = time.monotonic()
    landed = lambda v: v.landed == 1 and not v.armed  # noqa: E731
    kinds = ["arm", "takeoff", "land", "rtl", "mode", "mode", "reposition", "start", "pause", "continue", "speed",
             "home", "tablet", "tablet", "tablet"]
    if s.landed == 1:  # on the ground most commands are refused: get into the air more often than not
        kinds += ["arm"] * 4 + ["takeoff"] * 3 + ["start"] * 2
    kind = rng.choice(kinds)
    if kind == "home" and s.landed != 1:
        kind = "arm"  # DO_SET_HOME in the air moves home's altitude too: the heights below are from home
    if kind == "arm":
        value = rng.choice([1.0, 1.0, 0.0, NAN, 2.0])
        accepted, words = rig.command(m.MAV_CMD_COMPONENT_ARM_DISARM, value)
        promises = [Promise(f"arm {value}", now + 1.5, lambda v: v.armed is bool(value), f"armed {bool(value)}")]
    elif kind == "takeoff":
        alt = rng.choice([NAN, 3.0, 6.0, 150.0, -3.0, INF])
        accepted, words = rig.command(m.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, NAN, NAN, NAN, 295.0 + alt)
        want = 2.0 if not math.isfinite(alt) or alt < 2.0 else alt  # MIS_TAKEOFF_ALT 2 m, PX4's minimum
        if s.armed:
            promises = [Promise(f"takeoff {alt}", now + _vehicle_seconds(want / 1.0 + 5),
                                lambda v: v.mode == (AUTO, LOITER) and abs(v.alt - want) < 0.6,
                                f"hovering at {want} m")]
        else:  # PX4: TAKEOFF selected, flown at arming
            promises = [Promise(f"takeoff {alt} (disarmed)", now + 1.5, lambda v: v.mode == (AUTO, TAKEOFF),
                                "TAKEOFF selected")]
    elif kind in ("land", "rtl"):
        cmd = m.MAV_CMD_NAV_LAND if kind == "land" else m.MAV_CMD_NAV_RETURN_TO_LAUNCH
        accepted, words = rig.command(cmd)
        promises = [Promise(kind, now + _vehicle_seconds(90), landed, "landed and disarmed")]
    elif kind == "mode":
        main, sub = rng.choice(MODES)
        accepted, words = rig.command(m.MAV_CMD_DO_SET_MODE, 1, main, sub)
        if accepted:
            _mode_now(rig, (main, sub), f"DO_SET_MODE {main}/{sub}")
        promises = []
    elif kind == "reposition":
        n, e = rng.uniform(-25, 25), rng.uniform(-25, 25)
        alt = rng.choice([4.0, 8.0, NAN])
        lat = s.lat0 + n / M_PER_DEG
        lon = s.lon0 + e / (M_PER_DEG * math.cos(math.radians(s.lat0)))
        accepted, words = rig.command(m.MAV_CMD_DO_REPOSITION, -1, 1, 0, NAN, lat, lon, 295.0 + alt)
        dist = math.hypot(n - s.n, e - s.e)
        promises = [Promise(f"reposition {n:.0f} {e:.0f}", now + _vehicle_seconds(dist / 2.0 + 10),
                            lambda v: math.hypot(v.n - n, v.e - e) < 1.5 and v.mode == (AUTO, LOITER),
                            f"holding at {n:.1f} N {e:.1f} E")]
    elif kind == "start":
        accepted, words = rig.command(m.MAV_CMD_MISSION_START, 0, 0)
        promises = []
        if accepted:
            _mode_now(rig, (AUTO, MISSION), "MISSION_START")
    elif kind in ("pause", "continue"):
        accepted, words = rig.command(m.MAV_CMD_DO_PAUSE_CONTINUE, 0.0 if kind == "pause" else 1.0)
        if kind == "pause":
            promises = [Promise("pause", now + _vehicle_seconds(6),
                                lambda v: v.mode == (AUTO, LOITER) and v.speed < 0.3, "holding still")]
        else:
            promises = []
            if accepted:
                _mode_now(rig, (AUTO, MISSION), "continue")
    elif kind == "speed":
        speed = rng.choice([1.5, 4.0, NAN, -1.0, 1000.0])
        accepted, words = rig.command(m.MAV_CMD_DO_CHANGE_SPEED, 1, speed, -1)
        promises = []  # -1 (and 0 in PX4): no change
        if math.isfinite(speed) and speed > 0:
            promises = [Promise(f"speed {speed}", now + _vehicle_seconds(4),
                                lambda v: v.speed <= speed * 1.15 + 0.3, f"at most {speed} m/s")]
    elif kind == "home":
        accepted, words = rig.command(m.MAV_CMD_DO_SET_HOME, 1)
        where = (s.n, s.e)
        promises = [Promise("set home", now + 2.0, lambda v: v.home is not None
                            and math.hypot(v.home[0] - where[0], v.home[1] - where[1]) < 1.0 + 0.5 * v.speed,
                            f"home at {where[0]:.1f} N {where[1]:.1f} E")]
    else:
        tt = rig.ttapi.TtAction
        action = rng.choice([tt.TT_ACTION_TAKE_OFF, tt.TT_ACTION_LAND, tt.TT_ACTION_HOVER, tt.TT_ACTION_RETURN_HOME])
        arg = rng.choice([4.0, 7.0]) if action == tt.TT_ACTION_TAKE_OFF else 0.0
        accepted, words = rig.tablet_command(int(action), arg)
        kind = f"tablet {action.name}"
        if action == tt.TT_ACTION_TAKE_OFF:
            promises = [Promise(kind, now + _vehicle_seconds(arg + 5),
                                lambda v: v.mode == (AUTO, LOITER) and abs(v.alt - arg) < 0.6, f"hovering at {arg} m")]
        elif action == tt.TT_ACTION_HOVER:
            promises = [Promise(kind, now + _vehicle_seconds(6),
                                lambda v: v.mode == (AUTO, LOITER) and v.speed < 0.3, "holding still")]
        else:
            promises = [Promise(kind, now + _vehicle_seconds(90), landed, "landed and disarmed")]
    if not accepted:
        assert words, f"{kind}: refused without a word"
        return False, []
    return True, promises


@pytest.mark.parametrize("seed", [1, 2, 5, 7])  # 12 seeds ran clean; these four keep the most promises
def test_every_accepted_command_keeps_its_promise(start: Start, seed: int) -> None:
    """A random sequence of commands from a ground station and a tablet; after each ACCEPTED,
    either the next command comes at once (it may change the plan) or the test waits for the
    promise to be kept in its documented time and checks it."""
    pytest.importorskip("pymavlink")
    rng = random.Random(seed)
    random.seed(seed)
    rig = Rig(start, seed)
    accepted = refused = kept = 0
    try:
        for _ in range(32):
            ok, promises = _step(rig, rng)
            if ok:
                accepted += 1
                if promises and rng.random() < 0.7:
                    for p in promises:
                        _wait_until(rig, p)
                        kept += 1
            else:
                refused += 1
            time.sleep(rng.choice([0.0, 0.1, 0.5]))
    finally:
        rig.close()
    assert "Traceback" not in rig.node.stderr
    print(f"seed {seed}: {accepted} accepted, {refused} refused, {kept} promises kept")
    assert kept >= 2, (accepted, refused, kept)  # the run exercised the promise, not only refusals
