"""The tablet's promises (issue 20, "the tablet end"), with real processes on loopback:

- a set-point the vehicle refuses is a failed step with the vehicle's own words (output, --json,
  exit 1), and one it flies is confirmed by its echo, not assumed;
- every step is checked (types, ranges, NaN/inf, YAML 1.1 text such as 1e9) before the first runs;
- the vehicle refuses set-points beyond TT_MAX_DIST from home, and negative take-off altitudes;
- the tablet says "link lost" and "link back" on its own, a step failing during an outage says so,
  and Ctrl-C at the prompt cancels a waiting command and keeps the prompt;
- a vehicle that sends frames but no HEARTBEAT, or a silent port, is said in words (and in JSON).
"""

from __future__ import annotations

import contextlib
import json
import signal
import socket
import subprocess
import threading
import time
from pathlib import Path
from typing import Any

import pytest

from conftest import assert_no_traceback, run_ttctl, ttctl_cmd
from e2e_lib import LOCAL, Start, free_port, one_line, relay


def vehicle(start: Start, tmp_path: Path, port: int, *extra: str) -> Any:
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{port}",
                 "--no-entry-points", "--speed", "4", *extra)
    node.wait_for("onboard 1:")
    return node


def tablet(tmp_path: Path, port: int, script: str, *extra: str,
           timeout: float = 90) -> subprocess.CompletedProcess[str]:
    (tmp_path / "s.yaml").write_text(script)
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}", "--script", str(tmp_path / "s.yaml"),
                     *extra, timeout=timeout)
    assert_no_traceback(proc)
    return proc


def last(proc: subprocess.CompletedProcess[str]) -> str:
    return proc.stderr.strip().splitlines()[-1]


def test_refused_set_points_fail_the_step_in_the_vehicles_words(tmp_path: Path, start: Start) -> None:
    port = free_port()
    node = vehicle(start, tmp_path, port)
    landed = tablet(tmp_path, port, "- goto: [5, 0, 3]\n- status\n", "--json")
    assert landed.returncode == 1
    steps = [json.loads(x) for x in landed.stdout.splitlines() if '"event": "step"' in x]
    assert steps == [{"event": "step", "step": 1, "what": "goto 5 0 3", "ok": False, "reason":
                      "set-point 5.0 N, 0.0 E, 3.0 m: refused (set-point refused: on the ground: take off first)"}]
    assert json.loads(landed.stdout.splitlines()[-1])["event"] == "error"
    assert last(landed) == ("ttctl: error: step 1 (line 1: goto 5 0 3) failed: set-point 5.0 N, 0.0 E, 3.0 m: refused "
                            "(set-point refused: on the ground: take off first)")
    low = tablet(tmp_path, port, "- takeoff: 3\n- wait: {until: state == hovering, timeout: 40}\n"
                                 "- goto: [0, 0, 0.2]\n")
    assert low.returncode == 1 and last(low).endswith(
        "refused (set-point refused: altitude 0.2 m is below 0.5 m: land instead)"), low.stderr
    far = tablet(tmp_path, port, "- goto: [1e9, 0, 5]\n")  # YAML 1.1 reads 1e9 as text: the tablet reads a number
    assert far.returncode == 1 and last(far).endswith(
        "(set-point refused: 1000000 km from home is beyond the 1000 m limit (TT_MAX_DIST))"), far.stderr
    flown = tablet(tmp_path, port, "- goto: [10, 0, 4]\n- wait: {until: n >= 9.5 and state == hovering, "
                                   "timeout: 40}\n")
    assert flown.returncode == 0, flown.stderr
    assert "step 1 goto 10 0 4: set-point 10.0 N, 0.0 E, 4.0 m: accepted" in flown.stdout
    assert "set-point refused: on the ground: take off first" in node.stderr


@pytest.mark.parametrize("script,want", [
    ("- takeoff: -5\n", "line 1: takeoff: altitude -5 m is below 0 (0 or none: the vehicle's default)"),
    ("- takeoff: 3\n- goto: [0, 0, -50]\n", "line 2: goto: altitude -50 m is below home"),
    ("- goto: [.nan, 0, 5]\n", "line 1: goto: nan is not a finite number"),
    ("- goto: [1e400, 0, 5]\n", "line 1: goto: '1e400' is not a finite number"),
    ("- goto: [north, 0, 5]\n", "line 1: goto: 'north' is not a number"),
    ("- move: [true, 0, 0]\n", "line 1: move: True is not a number"),
    ("- wait: {until: state == hovering, timeout: .inf}\n", "line 1: timeout: inf is not a finite number"),
    ("- wait: .nan\n", "line 1: wait wants 0..86400 seconds"),
    ("- watch: true\n", "line 1: watch wants 1..3600 seconds"),
])
def test_every_step_is_checked_before_the_first_runs(tmp_path: Path, script: str, want: str) -> None:
    proc = tablet(tmp_path, free_port(), script, timeout=30)
    assert proc.returncode == 2 and one_line(proc.stderr).startswith(f"ttctl: error: --script {tmp_path / 's.yaml'}: "
                                                                     f"{want}"), proc.stderr


def test_the_vehicle_refuses_a_negative_take_off_and_keeps_its_limits() -> None:
    """Sans-IO, in process: what any tablet (not only ttctl's, which checks first) would meet."""
    import ttapi
    from ttctl.ends.onboard.node import OnboardConfig, OnboardNode
    from ttctl.ends.onboard.setpoints import SetpointDesk
    from ttctl.ends.onboard.vehicle import Refused, SimVehicle, Waypoint

    node = OnboardNode(_bindings(), OnboardConfig())
    result = node.tablet_action(ttapi.TtActionCommand(action=0, param=[-5.0, 0, 0, 0]))
    assert result == (4, "refused: take-off altitude -5 m is below 0 (0: the vehicle's default)")
    assert not node.vehicle.armed
    b = _bindings()
    assert node.vehicle.limits.max_dist == 1000.0
    _, complaint = node.ap.params.set(b.ParamSet(param_id="TT_MAX_DIST", param_value=50.0, param_type=9))
    assert complaint is None and node.vehicle.limits.max_dist == 50.0  # a parameter, as ground stations set it
    v = node.vehicle
    v.arm()
    v.takeoff(3)
    with pytest.raises(Refused, match="60 m from home is beyond the 50 m limit"):
        v.goto(0, 60, 3)
    with pytest.raises(Refused, match="beyond the 50 m limit"):
        v.fly([Waypoint(40, 40, 5)])
    assert isinstance(v, SimVehicle)
    desk, flown = SetpointDesk(), []
    first, again = desk.handle("t", (7, 1), lambda: flown.append(1)), desk.handle("t", (7, 1), lambda: flown.append(2))
    assert flown == [1] and first[0] == again[0] and again[1]  # a repeat is answered, not flown again


def _bindings() -> Any:
    from ttctl.commands.dialect import load_bindings

    return load_bindings(None, [])


def test_link_lost_and_back_are_said_and_a_step_failing_meanwhile_says_so(tmp_path: Path, start: Start) -> None:
    air, port = free_port(), free_port()
    relay(start, air, port, "--stats-interval", "0", "--outage", "5:6")  # the radio gone from 5 s to 11 s
    vehicle(start, tmp_path, port)
    ok = tablet(tmp_path, air, "- wait: 12\n- status\n")
    assert ok.returncode == 0, ok.stderr
    lost = [x for x in ok.stderr.splitlines() if "tablet: link" in x]
    assert len(lost) == 2 and lost[0].startswith("ttctl: tablet: link lost: nothing heard from the vehicle for 3.")
    assert lost[1].startswith("ttctl: tablet: link back after ")
    air, port = free_port(), free_port()
    relay(start, air, port, "--stats-interval", "0", "--outage", "4:600")
    vehicle(start, tmp_path, port)
    failed = tablet(tmp_path, air, "- wait: 9\n- status\n- wait: {until: n >= 39, timeout: 3}\n")
    assert failed.returncode == 1
    assert " (link lost: nothing heard from the vehicle for " in last(failed), failed.stderr
    assert "s ago (link lost), " in failed.stdout  # status says it too


def test_a_command_sent_during_an_outage_goes_again_as_soon_as_the_link_is_back(tmp_path: Path,
                                                                                start: Start) -> None:
    """The take-off leaves during an outage (tries 1.5 and 3 s apart, then 6 s later); when the
    vehicle is heard again it goes at once, not when the next doubled wait ends."""
    air, port = free_port(), free_port()
    relay(start, air, port, "--stats-interval", "0", "--outage", "8:8")  # gone from 8 s to 16 s
    vehicle(start, tmp_path, port)
    (tmp_path / "s.yaml").write_text("- wait: 9\n- takeoff: 3\n")  # connected at about 1..3 s
    p = subprocess.Popen(ttctl_cmd() + ["emulate", "tablet", "--to", f"udpout:{LOCAL}:{air}", "--script",
                                        str(tmp_path / "s.yaml"), "--json"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    seen: dict[str, float] = {}
    try:
        assert p.stdout is not None
        for line in p.stdout:
            if '"state": "back"' in line:
                seen["back"] = time.monotonic()
            if '"step": 2' in line:
                seen["step"] = time.monotonic()
                assert '"ok": true' in line, line
        p.wait(30)
    finally:
        p.kill()
    assert p.returncode == 0 and set(seen) == {"back", "step"}, (seen, p.stderr.read() if p.stderr else "")
    assert seen["step"] - seen["back"] < 2.0, seen  # without the hurry: the next try up to 6 s later


def test_ctrl_c_at_the_prompt_cancels_the_waiting_command_and_the_prompt_goes_on(tmp_path: Path,
                                                                                  start: Start) -> None:
    port = free_port()
    vehicle(start, tmp_path, port)
    p = subprocess.Popen(ttctl_cmd() + ["emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert p.stdin is not None
        p.stdin.write("wait 60\n")
        p.stdin.flush()
        time.sleep(4)
        p.send_signal(signal.SIGINT)
        time.sleep(1)
        out, err = p.communicate("status\nquit\n", timeout=20)
    finally:
        p.kill()
    assert p.returncode == 0, err
    assert "ttctl: wait 60: cancelled" in err
    assert "landed: 0.0 N 0.0 E 0.0 m" in out


def test_at_a_terminal_status_is_answered_while_a_command_waits(tmp_path: Path, start: Start) -> None:
    import os
    import pty

    port = free_port()
    vehicle(start, tmp_path, port)
    master, slave = pty.openpty()
    p = subprocess.Popen(ttctl_cmd() + ["emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}"], stdin=slave,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    os.close(slave)
    try:
        os.write(master, b"wait 30\n")
        time.sleep(3)
        t0 = time.monotonic()
        os.write(master, b"status\n")
        assert p.stdout is not None
        line = p.stdout.readline()
        answered = time.monotonic() - t0
        p.send_signal(signal.SIGINT)
        time.sleep(1)
        os.write(master, b"quit\n")
        _, err = p.communicate(timeout=20)
    finally:
        p.kill()
        os.close(master)
    assert "landed: 0.0 N 0.0 E 0.0 m" in line and answered < 5, (line, answered)
    assert p.returncode == 0 and "ttctl: wait 30: cancelled" in err, err
    master, slave = pty.openpty()  # Ctrl-C at an idle prompt ends the session, cleanly
    p = subprocess.Popen(ttctl_cmd() + ["emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}"], stdin=slave,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    os.close(slave)
    try:
        time.sleep(3)
        p.send_signal(signal.SIGINT)
        _, err = p.communicate(timeout=20)
    finally:
        p.kill()
        os.close(master)
    assert p.returncode == 130 and "Fatal" not in err and "Traceback" not in err, err


def test_the_prompt_gives_json_for_each_line_with_json(tmp_path: Path, start: Start) -> None:
    port = free_port()
    vehicle(start, tmp_path, port)
    proc = subprocess.run(ttctl_cmd() + ["emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}", "--json"],
                          input="status\ntakeoff -5\ngoto 5 0 3\nquit\n", capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    steps = [json.loads(x) for x in proc.stdout.splitlines() if '"event": "step"' in x]
    assert [s["ok"] for s in steps] == [True, False, False]
    assert steps[0]["result"].startswith("landed: 0.0 N 0.0 E 0.0 m")
    assert steps[1] == {"event": "step", "what": "takeoff -5", "ok": False,
                        "reason": "takeoff: altitude -5 m is below 0 (0 or none: the vehicle's default)"}
    assert steps[2]["reason"].endswith("(set-point refused: on the ground: take off first)")


class FakeVehicle:
    """A vehicle on raw UDP that answers with TT_ODOMETRY only (no HEARTBEAT), as `sysid`/240."""

    def __init__(self, sysid: int) -> None:
        import ttapi

        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind((LOCAL, 0))
        self.sock.settimeout(0.1)
        self.port = self.sock.getsockname()[1]
        self.enc = ttapi.Encoder(sysid, 240)
        self.stop = threading.Event()
        self.t = threading.Thread(target=self.run, daemon=True)
        self.t.start()

    def frame(self) -> bytes:
        import ttapi

        return bytes(self.enc.encode(ttapi.TtOdometry(time_usec=1, position=[0, 0, 0], orientation=[0, 0, 0, 1])))

    def run(self) -> None:
        peer = None
        while not self.stop.is_set():
            with contextlib.suppress(TimeoutError):
                _, peer = self.sock.recvfrom(2048)
            if peer is not None:
                self.sock.sendto(self.frame(), peer)

    def close(self) -> None:
        self.stop.set()
        self.t.join(2)
        self.sock.close()


def test_what_the_tablet_heard_is_said(tmp_path: Path) -> None:
    silent = tablet(tmp_path, free_port(), "- status\n", "--json", timeout=40)
    assert silent.returncode == 1
    assert "no vehicle answered" in one_line(silent.stderr) and "nothing came back" in silent.stderr
    assert json.loads(silent.stdout.splitlines()[-1])["event"] == "error"
    other = FakeVehicle(2)
    try:
        proc = tablet(tmp_path, other.port, "- status\n", timeout=40)
    finally:
        other.close()
    assert proc.returncode == 1 and "frames came only from 2/240, not from 1/240" in one_line(proc.stderr)
    quiet = FakeVehicle(1)
    try:
        proc = tablet(tmp_path, quiet.port, "- status\n", timeout=40)
    finally:
        quiet.close()
    assert proc.returncode == 0, proc.stderr
    assert "connected to 1/240" in proc.stderr and "but no HEARTBEAT from it in 3 s" in proc.stderr
    assert "(heard TT_ODOMETRY)" in proc.stderr


def test_no_gcs_with_gcs_is_refused() -> None:
    proc = run_ttctl("emulate", "onboard", "--no-gcs", "--gcs", f"udpout:{LOCAL}:14550", timeout=30)
    assert proc.returncode == 2
    assert one_line(proc.stderr) == "ttctl: error: --no-gcs and --gcs contradict each other: give one of them"


def test_a_fast_vehicle_clock_does_not_lose_the_tablet(tmp_path: Path, start: Start) -> None:
    """--speed 10 runs the vehicle's clock ten times faster; the link-loss watch keeps the wall
    clock, as the tablet's once-a-second HEARTBEAT does (regression: it once said "tablet link
    lost (10 s silent)" twice in a 3 s wait)."""
    port = free_port()
    node = vehicle(start, tmp_path, port, "--speed", "10")
    proc = tablet(tmp_path, port, "- takeoff: 3\n- wait: {until: state == hovering, timeout: 30}\n- wait: 3\n"
                                  "- status\n")
    assert proc.returncode == 0, proc.stderr
    assert "hovering (armed)" in proc.stdout
    assert "link lost" not in node.stderr


def test_a_ground_stations_reposition_beyond_tt_max_dist_is_refused_in_words() -> None:
    from flight_lib import Sim

    s = Sim()
    C = s.b.MavCmd
    s.takeoff(3)
    home = s.v.home
    far_lat = home.lat + 0.02  # 2227 m north
    denied = int(s.b.MavResult.MAV_RESULT_DENIED)
    assert s.command(int(C.MAV_CMD_DO_REPOSITION), -1, 1, 0, float("nan"), far_lat, home.lon, home.alt + 5) == denied
    assert "".join(s.said[2:]) == "refused: 2227 m from home is beyond the 1000 m limit (TT_MAX_DIST)", s.said


def test_a_command_waiting_for_a_lost_link_says_so_at_once_and_ctrl_c_gives_it_up(tmp_path: Path,
                                                                                  start: Start) -> None:
    """The vehicle gone, `land` at the prompt says at once that it waits for the link (not after
    its tries have run out, 46 s later on the m100's link), and Ctrl-C gives it up."""
    port = free_port()
    node = vehicle(start, tmp_path, port)
    p = subprocess.Popen(ttctl_cmd() + ["emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert p.stdin is not None and p.stderr is not None
        p.stdin.write("status\n")
        p.stdin.flush()
        assert p.stdout is not None and "landed" in p.stdout.readline()  # the vehicle heard
        node.kill()
        lines: list[str] = []
        reader = threading.Thread(target=lambda: lines.extend(iter(p.stderr.readline, "")), daemon=True)  # type: ignore[union-attr]
        reader.start()
        time.sleep(5)  # the link is lost after 3.5 s of silence
        p.stdin.write("land\n")
        p.stdin.flush()
        t0 = time.monotonic()
        while not any("waiting for the link" in ln for ln in lines) and time.monotonic() - t0 < 5:
            time.sleep(0.05)
        said = time.monotonic() - t0
        p.send_signal(signal.SIGINT)
        time.sleep(1)
        p.stdin.write("quit\n")
        p.stdin.flush()
        p.wait(timeout=20)
        reader.join(5)
    finally:
        p.kill()
    waiting = [ln for ln in lines if "waiting for the link" in ln]
    assert waiting and said < 2.0, (said, lines)
    assert waiting[0].startswith("ttctl: land: waiting for the link (nothing heard from the vehicle for "), waiting
    assert any("land: cancelled" in ln for ln in lines), lines
    assert p.returncode == 0, lines
