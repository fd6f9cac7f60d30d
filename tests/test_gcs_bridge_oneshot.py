"""One-shot requests through the tablet's bridge (issue 29, item 2): a ground station that sends a
command, a parameter read or a mission list request ONCE (as MAVProxy does) is answered at 10 %
loss as on a wire, because the bridge resends what the link may have lost until the vehicle's
answer passes back; a resend is recognised at the vehicle as a retry (never done twice); and a
second station's MISSION_COUNT beside an upload in progress is denied, the upload completes.
Real processes: pymavlink and MAVProxy -> `emulate tablet --gcs` -> `link relay --profile m100
--loss ...` -> `emulate onboard`."""

from __future__ import annotations

import contextlib
import math
import os
import re
import threading
import time
from pathlib import Path
from typing import Any

os.environ.setdefault("MAVLINK20", "1")  # before pymavlink is imported: ground stations speak MAVLink 2

from e2e_lib import Start, run_mavproxy
from machine import scaled
from test_gcs_bridge_peers import HOME, M_PER_DEG, Gcs, chain, no_traceback

MAX_TAKEOFFS = 40  # P(no resend reaches a vehicle that did the take-off) ~ 0.79 ** 40 < 1e-4
ANSWER_WAIT = 6.0  # s a station waits for the answer to its one request (the bridge's bound is ~4 s)


def once(gcs: Gcs, send: Any, answered: Any) -> bool:
    """`send()` once; True when a message satisfying `answered` comes within ANSWER_WAIT."""
    send()
    return gcs.pump(scaled(ANSWER_WAIT), answered) is not None  # (longer on a busy machine)


def ack_and(cmd: int, name: str) -> Any:
    """A predicate true once both the COMMAND_ACK of `cmd` and the message `name` have passed it:
    a request for a message is answered by both, which travel (and are lost) apart."""
    seen: set[str] = set()

    def answered(x: Any) -> bool:
        if x.get_type() == "COMMAND_ACK" and x.command == cmd:
            seen.add("ack")
        elif x.get_type() == name and x.get_srcSystem() == 1:
            seen.add(name)
        return seen == {"ack", name}

    return answered


def test_one_shot_requests_at_10_percent_loss_are_answered(tmp_path: Path, start: Start) -> None:
    """20 COMMAND_LONG (REQUEST_MESSAGE(HOME_POSITION)), 20 PARAM_REQUEST_READ and 20
    MISSION_REQUEST_LIST, each sent once: at least 19 of each answered, the command by its ack and
    the message it asked for (without the bridge's resends 75-90 % were)."""
    from conftest import shipped
    from ttctl.ends.onboard.autopilot import Autopilot
    from ttctl.ends.onboard.vehicle import SimVehicle

    names = [p.name for p in Autopilot(shipped(), SimVehicle()).params.params][:20]
    c = chain(start, tmp_path, model="random", seed=7)
    gcs = Gcs(c.gcs[0])
    m = gcs.m
    try:
        gcs.vehicle("HEARTBEAT", timeout=15)
        cmd = m.MAV_CMD_REQUEST_MESSAGE
        commands = sum(once(gcs, lambda: gcs.conn.mav.command_long_send(1, 1, cmd, 0, 242, 0, 0, 0, 0, 0, 0),
                            ack_and(cmd, "HOME_POSITION")) for _ in range(20))
        params = sum(once(gcs, lambda n=n: gcs.conn.mav.param_request_read_send(1, 1, n.encode(), -1),
                          lambda x, n=n: x.get_type() == "PARAM_VALUE" and x.param_id == n) for n in names)
        lists = sum(once(gcs, lambda: gcs.conn.mav.mission_request_list_send(1, 1, 0),
                         lambda x: x.get_type() == "MISSION_COUNT" and x.get_srcSystem() == 1) for _ in range(20))
    finally:
        gcs.close()
    summary = c.stop_tablet()
    assert (commands, params, lists) >= (19, 19, 19) and min(commands, params, lists) >= 19, (commands, params,
                                                                                             lists, summary)
    assert re.search(r"[1-9]\d* one-shot requests? resent", summary), summary  # the link did lose some
    no_traceback(c.onboard, c.relay, c.tablet)


def test_takeoffs_resent_by_the_bridge_are_done_once(tmp_path: Path, start: Start) -> None:
    """At 30 % loss a take-off sent once is resent by the bridge when its ack does not come back
    in a round trip; the vehicle, which did it, answers the resend as a retry: each take-off is
    done exactly once (the onboard end's log), and some were resends it recognised (the seeded loss
    falls on other packets as timing varies, so take-offs go on past 12 until one was). (Every one
    answered ACCEPTED was done; one whose every copy the link lost within the bridge's bound, as a
    busy machine's longer round trips allow, is not done, and not answered either.)"""
    c = chain(start, tmp_path, model="random", seed=3, loss="0.3")
    gcs = Gcs(c.gcs[0])
    m = gcs.m
    nan = math.nan
    sent = answered = 0
    try:
        gcs.vehicle("HEARTBEAT", timeout=20)
        assert gcs.command(m.MAV_CMD_COMPONENT_ARM_DISARM, 1) == m.MAV_RESULT_ACCEPTED
        tko = m.MAV_CMD_NAV_TAKEOFF
        again_re = r"NAV_TAKEOFF from \d+/\d+ again: answered as before"
        for i in range(MAX_TAKEOFFS):  # at least 12; more until a resend reached the vehicle after it did one
            if i >= 12 and re.search(again_re, c.onboard.stderr):
                break
            sent += 1  # each a new take-off (another altitude), sent once, confirmation 0
            answered += once(gcs, lambda i=i: gcs.conn.mav.command_long_send(1, 1, tko, 0, 0, 0, 0, nan, nan, nan,
                                                                             300.0 + i),
                             lambda x: x.get_type() == "COMMAND_ACK" and x.command == tko
                             and x.result == m.MAV_RESULT_ACCEPTED)
    finally:
        gcs.close()
    c.stop_tablet()
    log = c.onboard.stderr
    done = re.findall(r"NAV_TAKEOFF from \d+/\d+: ACCEPTED", log)
    again = re.findall(again_re, log)
    lost = 2 * math.ceil(sent / 12)  # take-offs whose every copy may be lost within the bridge's bound
    assert answered <= len(done) <= sent and answered >= sent - lost, (answered, sent, log[-3000:])  # none twice
    assert again, log[-3000:]  # the bridge's resends reached a vehicle that had done it
    no_traceback(c.onboard, c.relay, c.tablet)


def test_mavproxy_rtl_sent_once_after_takeoff_returns_the_vehicle(tmp_path: Path, start: Start) -> None:
    """MAVProxy 1.8.75 types `long NAV_RETURN_TO_LAUNCH` once (it never resends) while a pymavlink
    station has the vehicle flying: ACCEPTED comes back to MAVProxy and the vehicle returns (RTL)."""
    c = chain(start, tmp_path, stations=2, model="random", seed=11)
    gcs = Gcs(c.gcs[0])
    m = gcs.m
    nan = math.nan
    try:
        gcs.vehicle("HEARTBEAT", timeout=15)
        assert gcs.command(m.MAV_CMD_COMPONENT_ARM_DISARM, 1) == m.MAV_RESULT_ACCEPTED
        assert gcs.command(m.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, nan, nan, nan, 295 + 10) == m.MAV_RESULT_ACCEPTED
        gcs.vehicle("GLOBAL_POSITION_INT", lambda p: p.relative_alt > 5000, timeout=20)
        north = HOME[0] + 40 / M_PER_DEG  # 40 m away, so that returning is seen
        assert gcs.command(m.MAV_CMD_DO_REPOSITION, -1, 1, 0, nan, north, HOME[1], 295 + 10) == m.MAV_RESULT_ACCEPTED
        gcs.vehicle("GLOBAL_POSITION_INT", lambda p: p.lat > (HOME[0] + 30 / M_PER_DEG) * 1e7, timeout=30)
        got: list[str] = []
        mavproxy = threading.Thread(target=lambda: got.append(run_mavproxy(
            c.gcs[1], (("", 8.0), ("long NAV_RETURN_TO_LAUNCH", 5.0)), tmp_path, "--cmd=set param_ftp 0",
            "--source-system=250")), daemon=True)
        mavproxy.start()  # (this station keeps reading meanwhile: what the vehicle says is seen as it comes)
        hb = gcs.vehicle("HEARTBEAT", lambda h: (h.custom_mode >> 16) & 0xFF == 4 and h.custom_mode >> 24 == 5,
                         timeout=25)  # PX4's AUTO.RTL
        gcs.vehicle("GLOBAL_POSITION_INT", lambda p: p.lat < (HOME[0] + 10 / M_PER_DEG) * 1e7, timeout=30)  # back
        mavproxy.join(40)
    finally:
        gcs.close()
    assert hb is not None
    assert got and re.search(r"COMMAND_ACK.*NAV_RETURN_TO_LAUNCH.*ACCEPTED", got[0]), got[0][-3000:] if got else ""
    assert re.search(r"RETURN_TO_LAUNCH from 250/\d+: ACCEPTED", c.onboard.stderr), c.onboard.stderr[-3000:]
    c.stop_tablet()
    no_traceback(c.onboard, c.relay, c.tablet)


def test_a_second_stations_mission_count_is_denied_beside_an_upload(tmp_path: Path, start: Start) -> None:
    """Station A uploads 5 items (answering the vehicle's requests, as QGroundControl does) while
    station B floods MISSION_COUNT: A's upload completes (MISSION_ACK ACCEPTED, the vehicle's log),
    B gets MISSION_ACK DENIED, as PX4 denies a second transaction."""
    c = chain(start, tmp_path, stations=2, model="random", seed=5)
    a, b = Gcs(c.gcs[0]), Gcs(c.gcs[1], sysid=200, compid=190)
    m = a.m
    lat0, lon0 = HOME
    stop = threading.Event()
    b_acks: list[int] = []

    def intruder() -> None:
        while not stop.is_set():
            b.conn.mav.mission_count_send(1, 1, 3, 0)
            msg = b.pump(0.25, lambda x: x.get_type() == "MISSION_ACK")
            if msg is not None:
                b_acks.append(int(msg.type))

    try:
        a.vehicle("HEARTBEAT", timeout=15)
        b.vehicle("HEARTBEAT", timeout=15)
        a.conn.mav.mission_count_send(1, 1, 5, 0)
        first = a.pump(8.0, lambda x: x.get_type() in ("MISSION_REQUEST_INT", "MISSION_REQUEST"))
        assert first is not None, c.onboard.stderr[-2000:]
        flood = threading.Thread(target=intruder, daemon=True)
        flood.start()
        ack = None
        pending = first
        sent: int | None = None
        end = time.monotonic() + scaled(40)
        while time.monotonic() < end:
            if pending is None and sent is not None:
                s = sent  # no request and no ack for 1.5 s: the item again (QGroundControl's _ackTimeout)
            elif pending is not None and pending.get_type() in ("MISSION_REQUEST_INT", "MISSION_REQUEST"):
                s = int(pending.seq)
                a.pump(0.4)  # a station taking its time over each item: the upload lasts while B floods
            elif pending is not None and pending.get_type() == "MISSION_ACK":
                ack = pending
                break
            else:
                s = None
            if s is not None:
                a.conn.mav.mission_item_int_send(1, 1, s, m.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, m.MAV_CMD_NAV_WAYPOINT,
                                                 0, 1, 0, 0, 0, math.nan, int((lat0 + s * 1e-5) * 1e7),
                                                 int(lon0 * 1e7), 10.0, 0)
                sent = s
            pending = a.pump(1.5, lambda x: x.get_type() in ("MISSION_REQUEST_INT", "MISSION_REQUEST",
                                                             "MISSION_ACK"))
        time.sleep(1.0)
        stop.set()
        flood.join(5)
    finally:
        stop.set()
        a.close()
        b.close()
    assert "mission of 5 items received" in c.onboard.stderr, c.onboard.stderr[-3000:]
    assert ack is not None and ack.type == m.MAV_MISSION_ACCEPTED, (ack, c.onboard.stderr[-3000:])
    assert m.MAV_MISSION_DENIED in b_acks, b_acks
    c.stop_tablet()
    no_traceback(c.onboard, c.relay, c.tablet)


def run_mavproxy_on_a_pty(port: int, steps: tuple[tuple[str, float], ...], cwd: Path) -> str:
    """MAVProxy 1.8.75, unmodified, on a pseudo-terminal, as a user types at it (its console is
    interactive there, unlike on a pipe): each step types its line and waits its seconds.
    Returns what it printed."""
    import pty
    import subprocess

    from e2e_lib import LOCAL, mavproxy_exe

    master, slave = pty.openpty()
    p = subprocess.Popen([mavproxy_exe(), f"--master=udpin:{LOCAL}:{port}", "--source-system=255",
                          "--cmd=set param_ftp 0"], stdin=slave, stdout=slave, stderr=slave, cwd=cwd,
                         start_new_session=True)
    os.close(slave)
    out = bytearray()

    def read() -> None:
        with contextlib.suppress(OSError):  # EIO once MAVProxy has gone
            while data := os.read(master, 4096):
                out.extend(data)

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    try:
        for line, wait in steps:
            if line:
                os.write(master, (line + "\r").encode())
            time.sleep(scaled(wait))
    finally:
        p.kill()
        p.wait()
        reader.join(5)
        os.close(master)
    return out.decode(errors="replace")


def test_mavproxy_on_a_pty_sets_an_int32_and_returns_the_vehicle(tmp_path: Path, start: Start) -> None:
    """MAVProxy typed at on a terminal, through the RC link at 10 % loss (each of its commands
    sent once): `param set` of an INT32 parameter takes (a second station reads the new value
    from the vehicle), `arm throttle` and `takeoff` fly it, and `long NAV_RETURN_TO_LAUNCH` is
    ACCEPTED and the vehicle returns (PX4's AUTO.RTL in its HEARTBEAT, as MAVProxy shows it)."""
    c = chain(start, tmp_path, stations=2, model="random", seed=13)
    witness = Gcs(c.gcs[1], sysid=200, compid=190)
    try:
        witness.vehicle("HEARTBEAT", timeout=15)
        before = witness.param_int("NAV_DLL_ACT")
        want = 2 if before != 2 else 3
        got = run_mavproxy_on_a_pty(c.gcs[0], (("", 12.0), (f"param set NAV_DLL_ACT {want}", 4.0),
                                               ("param show NAV_DLL_ACT", 2.0), ("arm throttle", 3.0),
                                               ("takeoff 10", 8.0), ("long NAV_RETURN_TO_LAUNCH", 6.0)), tmp_path)
        witness.pump(3.0)  # what came while MAVProxy ran (its parameter list among it: the old value)
        # a PARAM_VALUE of that list still on its way down (a busy machine's) may answer the first
        # read with the old value: read until the vehicle says the new one, or the deadline
        deadline = time.monotonic() + scaled(10.0)
        after = witness.param_int("NAV_DLL_ACT")
        while after != want and time.monotonic() < deadline:
            after = witness.param_int("NAV_DLL_ACT")
    finally:
        witness.close()
    assert after == want, (before, after, got[-3000:])
    assert re.search(rf"NAV_DLL_ACT\s+{want}\b", got), got[-3000:]
    assert re.search(r"COMMAND_ACK: COMPONENT_ARM_DISARM: ACCEPTED", got), got[-3000:]
    assert re.search(r"COMMAND_ACK: NAV_TAKEOFF: ACCEPTED", got), got[-3000:]
    assert re.search(r"COMMAND_ACK: NAV_RETURN_TO_LAUNCH: ACCEPTED", got), got[-3000:]
    assert re.search(r"Mode RTL", got), got[-3000:]  # the vehicle's HEARTBEAT said AUTO.RTL, as MAVProxy read it
    assert re.search(r"RETURN_TO_LAUNCH from 255/\d+: ACCEPTED\n(.*\n)*.*returning", c.onboard.stderr), \
        c.onboard.stderr[-3000:]
    c.stop_tablet()
    no_traceback(c.onboard, c.relay, c.tablet)
