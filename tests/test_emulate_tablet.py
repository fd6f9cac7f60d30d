"""`ttctl emulate tablet --script` flying `ttctl emulate onboard` through `ttctl link relay` (real
processes on loopback): a whole mission at 10 m and 150 m; a link that dies mid-flight makes the
script fail on the step it was at, and the vehicle hover, return and land on its own."""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest

from conftest import assert_no_traceback, run_ttctl
from e2e_lib import LOCAL, Start, free_port, one_line, relay

MISSION = """\
- takeoff: 5
- wait: {until: altitude >= 4.5 and state == hovering, timeout: 40}
- send: square.yaml
- fly: square.yaml
- wait: {until: state == flying trajectory, timeout: 15}
- wait: {until: state == hovering, timeout: 120}
- goto: [0, 0, 3]
- wait: {until: altitude <= 3.3, timeout: 40}
- land
- wait: {until: state == landed, timeout: 60}
"""
SQUARE = ("speed: 1.5\nwaypoints:\n  - position: [5, 0, 5]\n  - position: [5, 5, 5]\n    hold: 1\n"
          "  - position: [0, 5, 6]\n")


def vehicle(start: Start, tmp_path: Path, port: int, *extra: str) -> object:
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{port}", "--inbox",
                 str(tmp_path / "inbox"), "--no-entry-points", "--speed", "4", *extra)
    node.wait_for("onboard 1:")  # type: ignore[attr-defined]
    return node


@pytest.mark.parametrize("distance", [10, 150])
def test_a_scripted_mission_through_the_emulated_radio(tmp_path: Path, start: Start, distance: int) -> None:
    (tmp_path / "flight.yaml").write_text(MISSION)
    (tmp_path / "square.yaml").write_text(SQUARE)
    air, port = free_port(), free_port()
    relay(start, air, port, "--profile", "m100", "--distance", str(distance), "--seed", "2", "--stats-interval", "0")
    node = vehicle(start, tmp_path, port)
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{air}", "--script", str(tmp_path / "flight.yaml"),
                     "--profile", "m100", "--distance", str(distance), "--json", timeout=300)
    assert_no_traceback(proc)
    assert proc.returncode == 0, proc.stderr + proc.stdout
    steps = [json.loads(line) for line in proc.stdout.splitlines() if '"event": "step"' in line]
    assert [s["step"] for s in steps] == list(range(1, 11)) and all(s["ok"] for s in steps)
    assert (tmp_path / "inbox" / "square.yaml").read_text() == SQUARE
    assert "flying square.yaml: 3 waypoints" in node.stderr and "landed" in node.stderr  # type: ignore[attr-defined]


def test_a_link_that_dies_mid_flight(tmp_path: Path, start: Start) -> None:
    script = "- takeoff: 5\n- wait: {until: state == hovering, timeout: 40}\n- wait: 4\n- goto: [20, 0, 5]\n- land\n"
    (tmp_path / "flight.yaml").write_text(script)
    air, port = free_port(), free_port()
    radio = relay(start, air, port, "--profile", "m100", "--distance", "10", "--seed", "3", "--stats-interval", "0",
                  "--outage", "6:600")  # the radio dies 6 s in: out of range, for good
    node = vehicle(start, tmp_path, port)
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{air}", "--script", str(tmp_path / "flight.yaml"),
                     timeout=120)
    assert_no_traceback(proc)
    assert proc.returncode == 1
    line = one_line(proc.stderr.replace("ttctl: tablet: connected", "").strip().splitlines()[-1])
    # the set-point is not answered (before, it was taken as flown): the step says so, and that the link is gone
    assert line.startswith("ttctl: error: step 4 (line 4: goto 20 0 5) failed: set-point 20.0 N, 0.0 E, 5.0 m: "
                           "no answer after 5 sends"), line
    assert "(link lost: nothing heard from the vehicle for " in line
    assert "ttctl: tablet: link lost: nothing heard from the vehicle for" in proc.stderr
    # the vehicle on its own: link lost (COM_DL_LOSS_T 10 s of its clock), hover, return, land
    node.wait_for("tablet link lost", timeout=30)  # type: ignore[attr-defined]
    node.wait_for("returning home", timeout=30)  # type: ignore[attr-defined]
    node.wait_for("landed", timeout=60)  # type: ignore[attr-defined]
    assert radio is not None


def test_a_bad_trajectory_is_refused_with_its_line_and_the_vehicle_keeps_hovering(tmp_path: Path,
                                                                                  start: Start) -> None:
    (tmp_path / "bad.yaml").write_text("waypoints:\n  - position: [5, 0]\n")
    (tmp_path / "flight.yaml").write_text("- takeoff: 3\n- wait: {until: state == hovering, timeout: 40}\n"
                                          "- send: bad.yaml\n- fly: bad.yaml\n")
    port = free_port()
    vehicle(start, tmp_path, port)
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}", "--script", str(tmp_path / "flight.yaml"),
                     timeout=120)
    assert proc.returncode == 1
    assert proc.stderr.strip().splitlines()[-1] == (
        "ttctl: error: step 4 (line 4: fly bad.yaml) failed: fly_trajectory: refused: FAILED (trajectory refused: "
        "bad.yaml: line 2, column 15: position is [north, east, altitude])")
    status = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}", "--script",
                       str(_write(tmp_path / "s.yaml", "- status\n")), timeout=60)
    assert status.returncode == 0 and "hovering (armed)" in status.stdout


def _write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


def test_bad_scripts_and_no_vehicle(tmp_path: Path) -> None:
    cases = {"- takeof: 5\n": "line 1: unknown step 'takeof'",
             "- wait: {until: altitude >> 5}\n": "line 1: cannot read condition",
             "- goto: [1, 2]\n": "line 1: goto wants 3 numbers",
             "takeoff: 5\n": "a script is a non-empty YAML list of steps"}
    for text, want in cases.items():
        proc = run_ttctl("emulate", "tablet", "--script", str(_write(tmp_path / "s.yaml", text)), timeout=30)
        assert proc.returncode == 2 and want in one_line(proc.stderr), proc.stderr
    t0 = time.monotonic()
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{free_port()}", "--script",
                     str(_write(tmp_path / "s.yaml", "- status\n")), timeout=60)
    assert proc.returncode == 1 and "no vehicle answered" in one_line(proc.stderr)
    assert time.monotonic() - t0 < 30


PLUGIN = '''
from pathlib import Path

import ttapi
from ttctl.ends.plugins import Context, Plugin, handles

OUT = Path(__file__).with_name("plugin.log")


class Recorder(Plugin):
    def start(self, ctx: Context) -> None:
        ctx.every(1.0, lambda: OUT.open("a").write(f"tick {ctx.vehicle.snapshot().alt_rel:.1f}\\n"))

    @handles(ttapi.DjiPoseStamped)
    def on_pose(self, msg, ctx: Context) -> None:
        OUT.open("a").write(f"pose {list(msg.position)}\\n")
        ctx.send(ttapi.TtLog(severity=6, text="plugin saw a set-point"))


class Broken(Plugin):
    @handles(ttapi.DjiPoseStamped)
    def explode(self, msg, ctx: Context) -> None:
        raise RuntimeError("boom")
'''


def test_user_plugins_get_their_messages_and_one_that_raises_is_isolated(tmp_path: Path, start: Start) -> None:
    (tmp_path / "myplugin.py").write_text(PLUGIN)
    (tmp_path / "flight.yaml").write_text("- takeoff: 3\n- wait: {until: state == hovering, timeout: 40}\n"
                                          "- goto: [2, 0, 3]\n- wait: 2\n- goto: [0, 0, 3]\n"
                                          "- wait: {until: state == hovering, timeout: 40}\n")
    port = free_port()
    node = vehicle(start, tmp_path, port, "--plugin", str(tmp_path / "myplugin.py"))
    assert "plugins Recorder, Broken" in node.stderr  # type: ignore[attr-defined]
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}", "--script", str(tmp_path / "flight.yaml"),
                     timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.count("vehicle: plugin saw a set-point") == 2
    log = (tmp_path / "plugin.log").read_text().splitlines()
    assert [line for line in log if line.startswith("pose")] == ["pose [2.0, 0.0, 3.0]", "pose [0.0, 0.0, 3.0]"]
    assert sum(line.startswith("tick") for line in log) >= 5 and any(line == "tick 3.0" for line in log)
    assert node.stderr.count("plugin Broken.explode failed on DJI_POSE_STAMPED: RuntimeError: boom") == 2  # type: ignore[attr-defined]


def test_the_prompt_reads_commands_from_a_pipe(tmp_path: Path, start: Start) -> None:
    import subprocess

    from conftest import ttctl_cmd

    port = free_port()
    vehicle(start, tmp_path, port)
    lines = "takeoff 3\nwait until state == hovering timeout 40\nbogus 1\nwatch 1.5\nmove 1 0 0\nstatus\nland\nquit\n"
    proc = subprocess.run(ttctl_cmd() + ["emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}"], input=lines,
                          capture_output=True, text=True, timeout=120)
    assert_no_traceback(proc)
    assert proc.returncode == 0, proc.stderr
    out = proc.stdout.splitlines()
    assert "take_off: accepted" in out and "state == hovering" in out and "land: accepted" in out
    assert sum("hovering (armed)" in line for line in out) >= 2  # watch printed lines, then status
    assert any(line.startswith("set-point 1.0 N, 0.0 E, 3.0 m") for line in out)
    assert "ttctl: unknown step 'bogus'" in proc.stderr  # a bad line is said and skipped, the prompt goes on


def test_at_300_m_the_script_fails_cleanly(tmp_path: Path, start: Start) -> None:
    """Out of range (the M100 model loses every uplink packet by 300 m): nothing the tablet says
    arrives, so the vehicle never learns where to answer either; the script ends, in one line,
    before any step."""
    (tmp_path / "flight.yaml").write_text(MISSION)
    (tmp_path / "square.yaml").write_text(SQUARE)
    air, port = free_port(), free_port()
    relay(start, air, port, "--profile", "m100", "--distance", "300", "--seed", "2", "--stats-interval", "0")
    node = vehicle(start, tmp_path, port)
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{air}", "--script", str(tmp_path / "flight.yaml"),
                     "--profile", "m100", "--distance", "300", timeout=120)
    assert_no_traceback(proc)
    assert proc.returncode == 1
    warning, error = proc.stderr.strip().splitlines()  # m100's rates were measured up to 200 m: it says so
    assert warning.startswith("ttctl: warning: profile 'm100' is extrapolated at 300 m")
    assert error.startswith(f"ttctl: error: no vehicle answered at udpout:{LOCAL}:{air} within 15 s: nothing came back")
    assert "taking off" not in node.stderr  # type: ignore[attr-defined]


def test_a_refusals_words_lost_on_the_way_are_asked_for_again(tmp_path: Path, start: Start) -> None:
    """A proxy between the tablet and the vehicle drops the packets that carry the vehicle's
    words (TT_LOG) the first time it sees them: the refusal still reaches the script with the
    vehicle's own words (the tablet asks again with the same command id and issue time; the
    vehicle repeats the recorded ack and its words, and runs nothing twice)."""
    import socket
    import threading

    import ttapi

    port, air = free_port(), free_port()
    vehicle(start, tmp_path, port)
    dropped: list[int] = []
    stop = threading.Event()

    def proxy() -> None:
        tablet_addr = None
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as up, \
                socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as down:
            up.bind((LOCAL, air))
            up.settimeout(0.05)
            down.settimeout(0.05)
            while not stop.is_set():
                try:
                    data, tablet_addr = up.recvfrom(2048)
                    down.sendto(data, (LOCAL, port))
                except TimeoutError:
                    pass
                try:
                    data, _ = down.recvfrom(2048)
                except TimeoutError:
                    continue
                frames = ttapi.Parser().feed(data)
                if any(isinstance(f, ttapi.TtLog) for f in frames) and not dropped:
                    dropped.append(len(data))  # the words, once
                    continue
                if tablet_addr is not None:
                    up.sendto(data, tablet_addr)

    t = threading.Thread(target=proxy, daemon=True)
    t.start()
    try:
        (tmp_path / "flight.yaml").write_text("- fly: missing.yaml\n")
        proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{air}", "--script",
                         str(tmp_path / "flight.yaml"), timeout=120)
    finally:
        stop.set()
        t.join(5)
    assert dropped, "the proxy saw no words to drop"
    assert proc.returncode == 1
    assert proc.stderr.strip().splitlines()[-1].startswith(
        "ttctl: error: step 1 (line 1: fly missing.yaml) failed: fly_trajectory: refused: FAILED (trajectory refused: "
        "missing.yaml:"), proc.stderr
