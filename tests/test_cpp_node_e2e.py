"""The generated C++ onboard end (ttapi::link::Node on UDP: onboard_node around the edited
skeleton, tests/cpp_node_lib.py) as a real process against ttctl's emulated tablet:

- the emulated tablet's script (commands, a file up, a file fetched, a message answered by a
  handler, a set-point flown) through `ttctl link relay --profile m100` (the emulated DJI radio)
  at 10 % random and burst loss: every command executed exactly once, acks repeated for
  retries, the set-point flown once, a trajectory flight refused in the handler's words;
- a retry whose ack was lost gets the recorded ack (deterministically, on raw UDP);
- the tablet's set-points answered by the handler's ctx.setpoint(): `goto` flown (echoed) or
  refused in the handler's words (exit 1), a repeated stamp flown once and answered each time;
- a user's dialect that includes ttapi.xml gets the node in its own namespace: its handler
  answers the tablet, a file goes up.
"""

from __future__ import annotations

import json
import random
import signal
import subprocess
from pathlib import Path
from typing import Any

import pytest

import ttapi
from conftest import ROOT, run_ttctl
from cpp_node_lib import WARN, Raw, gxx, needs_gxx, sha, write
from e2e_lib import LOCAL, Start, free_port, relay

pytestmark = needs_gxx


# -- against the emulated tablet ----------------------------------------------------------------

SCRIPT = """\
- takeoff: 5
- hover
- goto: [3, 4, 5]
- send: up.bin
- fetch: served.bin
- msg: {send: DJI_POSE_STAMPED sec=7 topic_name=DRONE_POSITION, until: DJI_POSE_STAMPED.sec == 7, timeout: 20}
- land
- return
- status
"""


def tablet(tmp: Path, port: int, script: str) -> tuple[subprocess.CompletedProcess[str], list[dict[str, Any]]]:
    (tmp / "script.yaml").write_text(script)
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}", "--profile", "m100", "--script",
                     "script.yaml", "--dir", str(tmp / "tablet"), "--json", cwd=tmp, timeout=150)
    steps = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
    return proc, [s for s in steps if s.get("event") == "step"]


@pytest.mark.parametrize("model,seed", [("random", 5), ("burst", 6)])
def test_against_the_emulated_tablet(cpp_node_bins: dict[str, Path], tmp_path: Path, start: Start, cpp_nodes: Any,
                                     model: str, seed: int) -> None:
    """`ttctl emulate tablet --script` through the m100 relay at 10 % loss: it sees the vehicle
    (HEARTBEAT), its commands are acknowledged and each runs once (retries answered from the
    record), a file goes up, another comes down, a message is answered by the skeleton's
    handler; a trajectory flight is refused in the handler's words."""
    inbox, serve = tmp_path / "inbox", tmp_path / "serve"
    served = write(serve / "served.bin", 8000, 1)
    up = write(tmp_path / "up.bin", 1000, 2)
    b = free_port()
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:{b}", "--inbox", str(inbox),
                     "--serve", str(serve))
    a = free_port()
    relay(start, a, b, "--profile", "m100", "--loss", "0.1", "--loss-model", model, "--seed", str(seed),
          "--stats-interval", "0")
    proc, steps = tablet(tmp_path, a, SCRIPT)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "tablet: connected to 1/240" in proc.stderr
    assert [s["ok"] for s in steps] == [True] * 9, proc.stdout
    assert sha(inbox / "up.bin") == sha(up)
    assert sha(tmp_path / "tablet" / "served.bin") == sha(served)
    proc, steps = tablet(tmp_path, a, "- fly: route.yaml\n")
    assert proc.returncode == 1 and len(steps) == 1 and not steps[0]["ok"], proc.stdout + proc.stderr
    assert "refused: this test vehicle flies no trajectories" in steps[0]["reason"], steps  # the handler's words
    commands = node.events("command")
    ran = [c for c in commands if not c["repeated"]]
    # take-off, hover, land, return and the refused flight: each run once, whatever was retried
    assert sorted(c["action"] for c in ran) == [0, 1, 2, 3, 5], commands
    assert len({c["command_id"] for c in ran}) == len(ran)
    assert [c["result"] for c in ran if c["action"] != 2] == [0, 0, 0, 0]  # ACCEPTED
    assert [c["result"] for c in ran if c["action"] == 2] == [4]  # DENIED
    stats = node.stop()
    assert stats["plugin_executed"] == stats["executed"] == 5, stats
    assert stats["plugin_flown"] == stats["setpoints_flown"] == 1, stats  # the goto, flown once however often sent
    assert stats["duplicates"] == sum(c["repeated"] for c in commands)
    print("MEASURED", json.dumps({"model": model, "commands": len(ran), "repeated_acks": stats["duplicates"]}))


def test_a_retry_whose_ack_was_lost_gets_the_recorded_ack(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                          cpp_nodes: Any) -> None:
    """The tablet's ack is lost (this test ignores it) and it sends the command again: the node
    answers with the same ack and does not run the action again; the same command id with a new
    issue time is a new command and runs. The refusal's words leave ahead of the refusing ack."""
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--heartbeat", "0")
    raw = Raw(node.port)
    try:
        cmd = ttapi.TtActionCommand(target_system=1, target_component=240, command_id=77, action=1, time_usec=1000)
        acks: list[Any] = []
        for _ in range(3):  # the first ack "lost", two retries
            raw.frames(cmd)
            got = raw.collect(2.0, until=lambda m: any(isinstance(x, ttapi.TtCommandAck) for x in m))
            acks += [m for m in got if isinstance(m, ttapi.TtCommandAck)]
        assert len(acks) == 3 and {(a.command_id, a.result, a.progress) for a in acks} == {(77, 0, 100)}
        raw.frames(ttapi.TtActionCommand(target_system=1, target_component=240, command_id=77, action=1,
                                         time_usec=2000))
        got = raw.collect(2.0, until=lambda m: any(isinstance(x, ttapi.TtCommandAck) for x in m))
        assert [m.command_id for m in got if isinstance(m, ttapi.TtCommandAck)] == [77]
        raw.frames(ttapi.TtActionCommand(target_system=1, target_component=240, command_id=78, action=2,
                                         time_usec=3000))
        got = raw.collect(2.0, until=lambda m: any(isinstance(x, ttapi.TtCommandAck) for x in m))
        kinds = [type(m).__name__ for m in got if isinstance(m, (ttapi.TtLog, ttapi.TtCommandAck))]
        assert kinds == ["TtLog", "TtCommandAck"], kinds  # the words first
        log = next(m for m in got if isinstance(m, ttapi.TtLog))
        assert log.text == "refused: this test vehicle flies no trajectories" and log.severity == 4
    finally:
        raw.close()
    stats = node.stop()
    assert (stats["executed"], stats["duplicates"], stats["plugin_executed"]) == (3, 2, 3), stats


# -- the tablet's set-points -------------------------------------------------------------------

def test_setpoints_flown_or_refused_in_the_handlers_words(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                          cpp_nodes: Any) -> None:
    """`goto` from the emulated tablet: the handler's ctx.setpoint() flies it and the node echoes
    it (the step succeeds), or the handler refuses it (altitude below 0.5 m) and the step fails,
    exit 1, in the handler's words."""
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--rate", "0")
    proc, steps = tablet(tmp_path, node.port, "- goto: [3, 4, 5]\n- goto: [-2, 1, 8]\n")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert [s["ok"] for s in steps] == [True, True], steps
    proc, steps = tablet(tmp_path, node.port, "- goto: [3, 4, 0.2]\n")
    assert proc.returncode == 1 and len(steps) == 1 and not steps[0]["ok"], proc.stdout + proc.stderr
    assert "set-point refused: altitude below 0.5 m: land instead" in steps[0]["reason"], steps
    assert "set-point refused: altitude below 0.5 m: land instead" in proc.stderr
    stats = node.stop()
    assert (stats["plugin_flown"], stats["setpoints_flown"], stats["setpoints_refused"]) == (2, 2, 1), stats


@pytest.mark.parametrize("exe", ["plain", "asan"])
def test_a_repeated_setpoint_is_answered_again_and_flown_once(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                              cpp_nodes: Any, exe: str) -> None:
    """The same stamp three times: three echoes, one flight; a refused one sent twice: the words
    twice; a 0/0 stamp is never a repeat; another topic is left to the handler (echoed by it),
    not counted as a set-point. The senders remembered are bounded: 20 more, and the first one's
    stamp is new again (also under the sanitizers)."""
    node = cpp_nodes(cpp_node_bins[exe], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--heartbeat", "0",
                     "--rate", "0")
    raw = Raw(node.port)

    def pose(sec: int, nsec: int, alt: float, topic: int = 0) -> Any:
        return ttapi.DjiPoseStamped(target_system=1, sec=sec, nsec=nsec, topic_name=topic, position=[1.0, 2.0, alt],
                                    orientation=[0.0, 0.0, 0.0, 1.0])

    def answers(msg: Any, raw: Raw = raw, sysid: int = 255) -> list[Any]:
        """The answers to `msg` from `sysid` (the node sends to every peer: another's are not)."""
        def mine(x: Any) -> bool:
            return isinstance(x, ttapi.TtLog) or (isinstance(x, ttapi.DjiPoseStamped) and x.target_system == sysid)

        raw.frames(msg)
        return [m for m in raw.collect(2.0, until=lambda got: any(mine(x) for x in got)) if mine(m)]

    try:
        for _ in range(3):
            got = answers(pose(100, 5, 3.0))
            assert len(got) == 1 and isinstance(got[0], ttapi.DjiPoseStamped), got
            assert (got[0].sec, got[0].nsec, got[0].topic_name, got[0].target_system) == (100, 5, 0, 255)
            assert list(got[0].position) == [1.0, 2.0, 3.0]
        for _ in range(2):
            got = answers(pose(101, 0, 0.1))
            assert len(got) == 1 and isinstance(got[0], ttapi.TtLog), got
            assert got[0].text == "set-point refused: altitude below 0.5 m: land instead" and got[0].severity == 4
        for _ in range(2):
            got = answers(pose(0, 0, 2.0))
            assert len(got) == 1 and isinstance(got[0], ttapi.DjiPoseStamped), got
        got = answers(pose(102, 0, 0.1, topic=1))  # DRONE_POSITION: the handler's own echo, no refusal
        assert len(got) == 1 and isinstance(got[0], ttapi.DjiPoseStamped) and got[0].topic_name == 1, got
        for sysid in range(10, 30):
            other = Raw(node.port, sysid=sysid)
            try:
                got = answers(pose(100, 5, 3.0), other, sysid)
                assert len(got) == 1 and got[0].target_system == sysid, got
            finally:
                other.close()
        got = answers(pose(100, 5, 3.0))  # forgotten: flown again
        assert len(got) == 1 and isinstance(got[0], ttapi.DjiPoseStamped), got
    finally:
        raw.close()
    stats = node.stop()
    assert (stats["plugin_flown"], stats["setpoints_flown"], stats["setpoints_refused"], stats["setpoints_repeated"],
            stats["setpoints_forgotten"]) == (24, 24, 1, 3, 6), stats


# -- a user's dialect ------------------------------------------------------------------------------

ROBOLAB_MAIN = r"""#include <atomic>
#include <csignal>
#include <cstdio>

#include "onboard/robolab_plugin.hpp"
#include "robolab/udp_link.hpp"

static std::atomic<bool> stop{false};

int main(int argc, char** argv)
{
    robolab::link::NodeConfig cfg;
    cfg.inbox = "inbox";
    robolab::link::Node node(cfg);
    robolab::onboard::RobolabPlugin plugin;
    node.add(plugin);
    robolab::link::Words why;
    robolab::link::UdpLink udp(node);
    if (argc != 2 || !node.start(why) || !udp.open(argv[1], why)) {
        std::fprintf(stderr, "%s\n", why.c_str());
        return 1;
    }
    std::printf("%u\n", static_cast<unsigned>(udp.local_port()));
    std::fflush(stdout);
    std::signal(SIGTERM, [](int) { stop = true; });
    udp.run(stop);
    return 0;
}
"""
ROBOLAB_REPLY = ("        // TODO: handle KR_MOTOR_CONTROL (from system frame.sysid, component frame.compid); "
                 "ctx.send(...) replies",
                 """        KrMotorStatus st;
        st.target_system = frame.sysid;
        st.seq = msg.seq;
        st.dir = msg.dir;
        st.speed = msg.speed;
        st.rpm = 12.5f * static_cast<float>(msg.speed);
        ctx.send(st);""")


def test_a_users_dialect_that_includes_ttapi_gets_the_node(tmp_path: Path) -> None:
    """dialects/examples/robolab.xml (ttapi.xml included, messages of its own): the node is
    generated in its namespace, the skeleton's KR_MOTOR_CONTROL handler answers with
    KR_MOTOR_STATUS, and the emulated tablet with --dialect gets the answer and sends a file."""
    xml = ROOT / "dialects" / "examples" / "robolab.xml"
    out = tmp_path / "out"
    proc = run_ttctl("gen", str(xml), "--lang", "cpp", "-o", str(out), timeout=300)
    assert proc.returncode == 0, proc.stderr
    cpp = out / "cpp"
    assert (cpp / "robolab" / "node.hpp").is_file()
    skeleton = cpp / "onboard" / "robolab_plugin.hpp"
    text = skeleton.read_text()
    assert ROBOLAB_REPLY[0] in text
    skeleton.write_text(text.replace(*ROBOLAB_REPLY))
    (tmp_path / "main.cpp").write_text(ROBOLAB_MAIN)
    gxx(*WARN, "-O1", "-I", str(cpp), str(tmp_path / "main.cpp"), "-o", str(tmp_path / "robolab_node"))
    prog = subprocess.Popen([str(tmp_path / "robolab_node"), f"udpin:{LOCAL}:0"], cwd=tmp_path, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        assert prog.stdout is not None
        port = int(prog.stdout.readline())
        (tmp_path / "up.bin").write_bytes(random.Random(1).randbytes(3000))
        (tmp_path / "drive.yaml").write_text(
            "- msg: {send: KR_MOTOR_CONTROL seq=1 dir=FORWARD speed=40, until: KR_MOTOR_STATUS.seq == 1, timeout: 20}\n"
            "- wait: {until: KR_MOTOR_STATUS.rpm >= 500, timeout: 5}\n"
            "- send: up.bin\n")
        run = run_ttctl("emulate", "tablet", "--dialect", str(xml), "--to", f"udpout:{LOCAL}:{port}", "--rate", "8000",
                        "--script", "drive.yaml", cwd=tmp_path, timeout=90)
        assert run.returncode == 0, run.stdout + run.stderr
        assert "answered after" in run.stdout and "up.bin: 3000 bytes delivered and verified" in run.stdout
        assert (tmp_path / "inbox" / "up.bin").read_bytes() == (tmp_path / "up.bin").read_bytes()
    finally:
        prog.send_signal(signal.SIGTERM)
        assert prog.wait(20) == 0
