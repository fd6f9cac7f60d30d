"""`ttctl hmd dump --to` against a real `ttctl emulate onboard` through `ttctl link relay` (real
processes on loopback): on a lossy link every button change reaches the onboard end, once and in
order, and the summary counts what the onboard end confirmed; with nobody listening the dump
says so and exits 1."""

from __future__ import annotations

import contextlib
import json
import re
import subprocess
from pathlib import Path

from conftest import ttctl_cmd
from e2e_lib import LOCAL, Start, free_port, relay

LINE = re.compile(r"vr controller (\d+): buttons (.*) \(packet (\d+)\)")
NAMES = ("trigger_click", "pad_touched", "pad_pressed", "menu", "grip")


def recorded_changes(rec: Path) -> list[tuple[int, str, int]]:
    """(index, held buttons, packet) of every button change in a JSONL recording."""
    last: dict[int, str] = {}
    out = []
    for line in rec.read_text().splitlines():
        d = json.loads(line)
        if "buttons" not in d:
            continue
        held = ", ".join(n for n in NAMES if d["buttons"].get(n)) or "none"
        if held != last.get(d["index"], "none"):
            last[d["index"]] = held
            out.append((d["index"], held, d["packet"]))
    return out


def test_button_changes_survive_a_lossy_link_and_are_confirmed(tmp_path: Path, start: Start) -> None:
    air, port = free_port(), free_port()
    relay(start, air, port, "--profile", "m100", "--distance", "10", "--loss", "0.2", "--seed", "4",
          "--stats-interval", "0")
    node = start("onboard", "emulate", "onboard", "--listen", f"udpin:{LOCAL}:{port}", "--no-entry-points")
    node.wait_for("onboard 1:")
    rec = tmp_path / "rec.jsonl"
    dump = subprocess.run(ttctl_cmd() + ["hmd", "dump", "--duration", "8", "--seed", "2", "-o", str(rec),
                                         "--to", f"udpout:{LOCAL}:{air}"],
                          capture_output=True, text=True, timeout=60)
    want = recorded_changes(rec)
    got = [(int(i), held, int(p)) for i, held, p in LINE.findall(node.stderr)]
    assert dump.returncode == 0, dump.stderr
    assert len(want) >= 8
    for index in {i for i, _, _ in want}:  # every change, once, in each controller's order, with its packet
        assert [g for g in got if g[0] == index] == [w for w in want if w[0] == index]
    assert len(got) == len(want)
    m = re.search(r"button changes: (\d+) of (\d+) confirmed by the onboard end \((\d+) resent\)", dump.stderr)
    assert m is not None, dump.stderr
    assert int(m[1]) == int(m[2]) == len(want) and int(m[3]) > 0  # 20 % loss: some were resent
    taken = re.search(r"(\d+) taken = (\d+) sent \+ (\d+) superseded(?: \+ (\d+) not sent)?", dump.stderr)
    assert taken is not None, dump.stderr
    assert int(taken[1]) == int(taken[2]) + int(taken[3]) + int(taken[4] or 0)
    assert "none dropped" not in dump.stderr


def test_nobody_listening_is_not_success(tmp_path: Path) -> None:
    nobody = free_port()
    dump = subprocess.run(ttctl_cmd() + ["hmd", "dump", "--duration", "3", "--speed", "0", "-o",
                                         str(tmp_path / "r.jsonl"), "--to", f"udpout:{LOCAL}:{nobody}"],
                          capture_output=True, text=True, timeout=60)
    assert dump.returncode == 1, dump.stderr
    assert f"nothing heard from the onboard end at udpout:{LOCAL}:{nobody}" in dump.stderr
    assert "none dropped" not in dump.stderr
    assert dump.stderr.count("\n") <= 4 and "Traceback" not in dump.stderr


def test_openvr_frame_files_still_stream_rep103(tmp_path: Path) -> None:
    """TT_VR_POSE is REP-103 (z up): with --frame openvr the file is y-up, the link is not."""
    import socket

    import ttapi

    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sock.bind((LOCAL, 0))
    sock.settimeout(0.2)
    port = sock.getsockname()[1]
    rec = tmp_path / "r.jsonl"
    dump = subprocess.Popen(ttctl_cmd() + ["hmd", "dump", "--frame", "openvr", "--duration", "2", "-o", str(rec),
                                           "--to", f"udpout:{LOCAL}:{port}"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    heads = []
    while dump.poll() is None:
        try:
            data = sock.recv(2048)
        except TimeoutError:
            continue
        heads += [m for m in ttapi.parse_all(data) if isinstance(m, ttapi.TtVrPose)
                  and m.device == ttapi.TtVrDevice.TT_VR_DEVICE_HMD]
    sock.close()
    assert dump.wait(30) == 1  # nobody answered
    assert len(heads) >= 3
    assert all(1.2 < m.position[2] < 2.2 for m in heads)  # standing head height, z up
    poses = [json.loads(line) for line in rec.read_text().splitlines()[1:]]
    head_file = [p for p in poses if p.get("device") == "hmd"]
    assert all(1.2 < p["position"][1] < 2.2 for p in head_file)  # the file keeps OpenVR's y up


def test_an_onboard_end_that_never_confirms_is_named(tmp_path: Path) -> None:
    """A peer that answers (heartbeats) but does not confirm button changes: exit 1, and the
    error says what the onboard end must send."""
    import socket
    import threading

    import ttapi
    from ttctl.hmd.formats import open_writer
    from ttctl.hmd.model import ControllerSample, Device

    rec = tmp_path / "clicks.jsonl"
    w = open_writer(str(rec), "jsonl", "ros", "vr_world", {})
    left = Device(3, "controller", "left", "C")
    for k in range(6):
        w.write(ControllerSample(1_800_000_000.0 + k * 0.1, left, k + 1, buttons={"menu": k % 2 == 0}))
    w.close()
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sock.bind((LOCAL, 0))
    sock.settimeout(0.1)
    done = threading.Event()
    heartbeat = ttapi.Encoder(1, 240).encode(ttapi.Heartbeat(type=2, autopilot=12, base_mode=0, custom_mode=0,
                                                             system_status=4, mavlink_version=3))

    def answer() -> None:
        peer = None
        while not done.is_set():
            with contextlib.suppress(TimeoutError):
                _, peer = sock.recvfrom(2048)
            if peer is not None:
                sock.sendto(heartbeat, peer)

    t = threading.Thread(target=answer, daemon=True)
    t.start()
    try:
        dump = subprocess.run(ttctl_cmd() + ["hmd", "dump", "--source", "replay", str(rec), "--to",
                                             f"udpout:{LOCAL}:{sock.getsockname()[1]}", "-q"],
                              capture_output=True, text=True, timeout=60)
    finally:
        done.set()
        t.join(2)
        sock.close()
    assert dump.returncode == 1, dump.stderr
    assert "confirmed none of 6 button changes" in dump.stderr and "NAMED_VALUE_INT 'vrbtn<index>'" in dump.stderr
    assert dump.stderr.count("\n") == 1 and "Traceback" not in dump.stderr
