"""The generated Java tablet waits for the answer to its set-points (README: "The tablet's
set-points ..."): tests/java/setpoint/SetpointDriver.java sends them with the runtime's
SendSetpoint in one Session, as an app does, built with javac --release 11 -Xlint:all -Werror
from a freshly generated tree, against a real `ttctl emulate onboard` and a plain UDP sink:

- a set-point while landed, and one at 0.2 m or 1e9 m away once airborne, fail REFUSED in the
  vehicle's words (those of two TT_LOG chunks joined);
- a flyable one completes with the vehicle's echo (the same stamp) and the vehicle's odometry
  moves toward it; a newer one submitted behind an older supersedes it (SUPERSEDED);
- results and callbacks arrive on the session's listener thread, as command results do;
- nobody answering: 5 sends of the same stamp 1.5 s apart, then TIMEOUT "no answer"; an older
  set-point in flight meanwhile ends SUPERSEDED;
- a session that takes off and then sends nothing for 13 s is still heard by the vehicle (the
  Session's own HEARTBEAT a second: no "link lost"); with them off (heartbeatMillis 0) the
  vehicle says "link lost".
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conformance_lib import build_java
from conftest import ROOT
from e2e_lib import Start, free_port
from test_java_session import Java, onboard

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    cls, _ = build_java(tmp_path_factory.mktemp("java_setpoints"),
                        [ROOT / "tests" / "java" / "setpoint" / "SetpointDriver.java"])
    return cls


class SetpointJava(Java):
    def __init__(self, classes: Path, folder: Path, name: str, mode: str, port: int) -> None:
        self.name = name
        self.out_path = folder / f"{name}.out"
        self._out = open(self.out_path, "w")  # noqa: SIM115 - closed in finish()
        self.p = subprocess.Popen(["java", "-cp", str(classes), "SetpointDriver", mode, f"port={port}"],
                                  stdout=self._out, stderr=subprocess.STDOUT, cwd=folder)


def test_set_points_are_done_refused_or_superseded_as_the_vehicle_answers(classes: Path, tmp_path: Path,
                                                                           start: Start) -> None:
    port = free_port()
    node = onboard(start, tmp_path, port, "--speed", "4")
    r = SetpointJava(classes, tmp_path, "fly", "fly", port).finish(60)
    text = r["_text"][-3000:]
    assert r["landed"].startswith("REFUSED ") and r["landed"].endswith(
        ": set-point refused: on the ground: take off first (tries 1)"), text
    assert r["takeoff"] == "ok ACCEPTED" and r["airborne"], text
    assert r["fly"] == f"DONE {r['north_before'] + 5:.1f} 0.0 5.0", text
    assert r["fly_callback"].startswith("onSuccess on ttctl-listeners echo "), text
    assert r["moved"], "the set-point was reported done but the vehicle did not move:\n" + text
    assert r["low"].endswith(": set-point refused: altitude 0.2 m is below 0.5 m: land instead (tries 1)"), text
    assert r["low_callback"] == "onFailure on ttctl-listeners", text
    # 80 bytes of words: two TT_LOG chunks (a full one and an empty last one), joined
    assert r["far"].endswith(": set-point refused: 1000000 km from home is beyond the 1000 m limit (TT_MAX_DIST)"
                             " (tries 1)"), text
    superseded = "SUPERSEDED set-point 0.0 N, 0.0 E, 6.0 m: superseded by set-point 0.0 N, 0.0 E, 7.0 m"
    assert r["older"].startswith(superseded), text
    assert r["older_callback"] == "onFailure on ttctl-listeners", text
    assert r["newer"] == "DONE 0.0 0.0 7.0", text
    assert node.stderr.count("set-point refused") == 3, node.stderr


SINK = r'''
import socket, sys
sys.path.insert(0, sys.argv[1])
from ttapi.mavlink import Parser
from ttapi.messages import DjiPoseStamped

sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
sock.bind(("127.0.0.1", int(sys.argv[2])))
parser = Parser()
print("ready", flush=True)
while True:
    data, addr = sock.recvfrom(65536)
    for msg in parser.feed(data):
        if isinstance(msg, DjiPoseStamped):
            print(msg.sec, msg.nsec, msg.topic_name, list(msg.position), flush=True)
'''


def test_an_unanswered_set_point_fails_after_five_sends_of_the_same_stamp(classes: Path, tmp_path: Path) -> None:
    port = free_port()
    sink = subprocess.Popen([sys.executable, "-c", SINK, str(ROOT / "generated" / "python"), str(port)],
                            stdout=subprocess.PIPE, text=True)
    try:
        assert sink.stdout is not None and sink.stdout.readline().strip() == "ready"
        r = SetpointJava(classes, tmp_path, "silent", "silent", port).finish(40)
    finally:
        sink.kill()
        out, _ = sink.communicate(5)
    assert r["silent"].startswith("TIMEOUT set-point 5.0 N, 0.0 E, 10.0 m: no answer after 5 tries"), r["_text"]
    assert r["silent"].endswith("(tries 5)") and r["silent_callback"] == "onFailure on ttctl-listeners", r
    assert 7.0 <= r["silent_s"] <= 9.5, r  # 5 tries, 1.5 s each
    # the older one, in flight when the newer came: superseded, reported as such
    assert r["first"].startswith("SUPERSEDED set-point 1.0 N, 0.0 E, 10.0 m: superseded by set-point 5.0 N"), r
    assert r["first_callback"] == "onFailure on ttctl-listeners", r
    sent = out.splitlines()
    first, second = sent[:2], sent[2:]
    assert len(set(first)) == 1 and first[0].endswith("[1.0, 0.0, 10.0]"), sent  # sent at 0 and 1.5 s
    assert len(second) == 5 and len(set(second)) == 1, sent  # the same stamp, topic SETPOINT (0), position
    sec, _nsec, topic, *_ = second[0].split()
    assert int(sec) > 0 and topic == "0" and second[0].endswith("[5.0, 0.0, 10.0]"), sent




@pytest.mark.parametrize("heartbeats", [True, False], ids=["heartbeats", "heartbeats-off"])
def test_an_idle_tablet_session_is_heard_by_its_own_heartbeats(classes: Path, tmp_path: Path, start: Start,
                                                              heartbeats: bool) -> None:
    """The Session's HEARTBEAT a second keeps a tablet that took off and then sends nothing from
    being taken for lost by the vehicle (COM_DL_LOSS_T, 10 s); with them off (heartbeatMillis 0)
    the vehicle says "link lost" (the test can fail)."""
    port = free_port()
    node = onboard(start, tmp_path, port, "--speed", "4")
    mode = "idle" if heartbeats else "idle-no-heartbeat"
    r = SetpointJava(classes, tmp_path, mode, mode, port).finish(60)
    text = r["_text"][-3000:]
    assert r["takeoff"] == "ok ACCEPTED" and r["airborne"] and r["idle_s"] == 13, text
    if heartbeats:
        assert "link lost" not in node.stderr, node.stderr
    else:
        node.wait_for("link lost", 5)
