"""Head poses streamed by `ttctl hmd dump --to` through `ttctl link relay` (the M100 model at 10 m)
steer the orbit camera of `ttctl emulate onboard`: a ground station (pymavlink, real process
boundary: UDP) sees CAMERA_FOV_STATUS follow a 90-degree head turn within the link's latency
plus the smoothing time constant."""

from __future__ import annotations

import json
import math
import subprocess
import threading
import time
from pathlib import Path

from pymavlink import mavutil

from conftest import ttctl_cmd
from e2e_lib import LOCAL, Start, free_port, relay
from ttctl.commands.hmd import HEADROOM
from ttctl.hmd.formats import open_writer
from ttctl.hmd.model import Device, PoseSample
from ttctl.hmd.orbit import OrbitParams
from ttctl.link.model import load_profile

HEAD = Device(0, "hmd", serial="HMD-1")
TURN = math.radians(90)  # the head turns right: the view turns right (east of the drone's heading)
STEP_AT = 5.0  # s into the recording


def head_quat(yaw: float) -> tuple[float, float, float, float]:
    return (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))


def view_yaw(m: object) -> float:
    w, x, y, z = m.q  # type: ignore[attr-defined]
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def test_the_orbit_camera_follows_the_head_over_the_link(tmp_path: Path, start: Start) -> None:
    rec = tmp_path / "turn.jsonl"
    w = open_writer(str(rec), "jsonl", "ros", "vr_world", {})
    t0 = 1_800_000_000.0
    for k in range(10 * 90):  # 10 s at 90 Hz: level for STEP_AT s, then turned 90 degrees right
        t = k / 90
        w.write(PoseSample(t0 + t, HEAD, position=(0.0, 0.0, 1.7), orientation=head_quat(-TURN if t >= STEP_AT else 0)))
    w.close()

    air, port, gcs_port = free_port(), free_port(), free_port()
    relay(start, air, port, "--profile", "m100", "--distance", "10", "--seed", "5", "--stats-interval", "0")
    gcs = mavutil.mavlink_connection(f"udpin:{LOCAL}:{gcs_port}", source_system=255)
    node = start("onboard", "emulate", "onboard", "--listen", f"udpin:{LOCAL}:{port}", "--gcs",
                 f"udpout:{LOCAL}:{gcs_port}", "--no-entry-points")
    node.wait_for("onboard 1:")
    seen: list[tuple[float, float]] = []  # (arrival, view yaw)
    done = threading.Event()

    def listen() -> None:
        while not done.is_set():
            m = gcs.recv_match(type="CAMERA_FOV_STATUS", blocking=True, timeout=0.2)
            if m is not None:
                seen.append((time.monotonic(), view_yaw(m)))

    listener = threading.Thread(target=listen, daemon=True)
    listener.start()
    # the dump's own JSONL on stdout, line by line as it streams: when the turned head left
    dump = subprocess.Popen(ttctl_cmd() + ["hmd", "dump", "--source", "replay", str(rec), "--to",
                                           f"udpout:{LOCAL}:{air}", "--profile", "m100", "--distance", "10"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, bufsize=1)
    turned_at = None
    assert dump.stdout is not None
    for line in dump.stdout:
        if turned_at is None and json.loads(line).get("t", 0) >= t0 + STEP_AT:
            turned_at = time.monotonic()
    _, err = dump.communicate(timeout=30)
    time.sleep(1.0)
    done.set()
    listener.join(2)
    assert dump.returncode == 0, err
    assert "streamed to" in err and "superseded" in err, err
    assert turned_at is not None
    before = [y for t, y in seen if t < turned_at]
    assert len(before) > 20 and all(abs(y) < math.radians(2) for y in before[-10:]), before[-10:]
    # 63 % of the turn is reached after tau of smoothing, once the pose is over the link
    crossed = next(t for t, y in seen if t > turned_at and y > (1 - math.exp(-1)) * TURN)
    prof = load_profile("m100")
    cap = prof.capacity_Bps("up", 10)
    frame = 76  # a TT_VR_POSE frame
    # the link's latency for a newest-wins pose: waiting for the pacer (one frame at 85 % of the
    # capacity), the frame's airtime, the radio's delay
    link_latency = frame / (HEADROOM * cap) + frame / cap + prof.up.latency_s
    bound = link_latency + OrbitParams().tau_angle
    slack = 1 / 10 + 0.1  # the camera publishes at 10 Hz; scheduling on a shared machine
    trace = [(round(t - turned_at, 3), round(math.degrees(y), 1)) for t, y in seen if -0.3 < t - turned_at < 1.5]
    assert crossed - turned_at <= bound + slack, (crossed - turned_at, bound, trace)
    final = [y for t, y in seen if t > crossed + 1.0]
    assert final and abs(final[-1] - TURN) < math.radians(2)
