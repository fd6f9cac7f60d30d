"""The onboard C++ handler skeleton plugs into a link::Node (the onboard end of the link): a
handler per message the onboard end receives, each with the NodeContext to reply through, and
on_command(), the action the node's command server runs once per TT_ACTION_COMMAND (the ack is
the node's). Its comments list each message's fields and show the program around it. Built with
g++ -Werror as a user would edit it: the DJI_POSE_STAMPED handler echoes the pose, on_command
accepts and counts; packets go through the node sans-IO (no socket) and what comes out is read
back by ttctl's Python bindings: the ack (the same for a retry, the action run once), the echo,
the heartbeat; a file. Receiving, dispatching, replying, acking, storing file data, reporting it
(statuses) and building packets allocate nothing (accepting an offer and completing a file may:
paths, the folder's size for its quota)."""

from __future__ import annotations

import hashlib
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import TTAPI, run_ttctl

pytestmark = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

WARN = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]

# What the user writes in the skeleton: a counter, the command's action, the pose handler's reply.
MEMBER = ("public:\n    const char* name() const noexcept override",
          "public:\n    int executed = 0;\n\n    const char* name() const noexcept override")
ACTION = ("""        // TODO: carry out cmd.action (a TtAction) with cmd.param and cmd.argument, from system frame.sysid
        return {TtResult::TT_RESULT_UNSUPPORTED, "not implemented on this vehicle yet"};""",
          """        ++executed;
        return TtResult::TT_RESULT_ACCEPTED;""")
REPLY = ("        // TODO: handle DJI_POSE_STAMPED (from system frame.sysid, component frame.compid); "
         "ctx.send(...) replies",
         """        DjiPoseStamped echo = msg;
        echo.target_system = frame.sysid;
        ctx.send(echo);""")

# The user's program, sans-IO: packets read from stdin (hex, one per line) go into the node at
# t = 1 s; what it sends until t = 2 s is printed; operator new counts allocations.
MAIN = r"""#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>
#include <string>

#include "onboard/ttapi_plugin.hpp"

static std::size_t allocations = 0;

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"  // malloc/free behind new/delete, on purpose
#endif

void* operator new(std::size_t n)
{
    ++allocations;
    if (void* p = std::malloc(n == 0 ? 1 : n)) {
        return p;
    }
    throw std::bad_alloc();
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

int main(int argc, char** argv)
{
    ttapi::link::NodeConfig cfg;
    cfg.compid = 191;
    cfg.inbox = argc > 1 ? argv[1] : "inbox";
    ttapi::link::Node node(cfg);
    ttapi::onboard::TtapiPlugin plugin;
    node.add(plugin);
    ttapi::link::Words why;
    if (!node.start(why)) {
        std::fprintf(stderr, "%s\n", why.c_str());
        return 1;
    }
    // Lines: a phase letter and a packet's hex. Phase A (commands, replies, data frames) is
    // counted; phase S (an offer being accepted: paths, a look at the folder) and phase C (the
    // file completing) are not.
    static std::uint8_t out[1024][100];
    static std::size_t out_len[1024];
    std::size_t sent = 0;
    std::size_t delivered = 0;
    std::size_t counted = 0;
    double t = 1.0;
    std::string line;
    std::uint8_t packet[128];
    while (std::getline(std::cin, line)) {
        const char phase = line[0];
        const std::size_t n = (line.size() - 2) / 2;
        for (std::size_t i = 0; i < n; ++i) {
            packet[i] = static_cast<std::uint8_t>(std::stoul(line.substr(2 + 2 * i, 2), nullptr, 16));
        }
        const std::size_t before = allocations;
        delivered += node.receive(t, packet, n);
        for (double end = t + 0.3; t < end && sent < 1024; t += 0.01) {
            while (sent < 1024 && (out_len[sent] = node.poll(t, out[sent])) != 0) {
                ++sent;
            }
        }
        if (phase == 'A') {
            counted += allocations - before;
        }
    }
    std::printf("delivered %zu executed %d allocations %zu\n", delivered, plugin.executed, counted);
    for (std::size_t i = 0; i < sent; ++i) {
        for (std::size_t k = 0; k < out_len[i]; ++k) {
            std::printf("%02x", static_cast<unsigned>(out[i][k]));
        }
        std::printf("\n");
    }
    return 0;
}
"""


@pytest.fixture(scope="module")
def skeleton(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("handlers") / "out"
    proc = run_ttctl("gen", str(TTAPI), "--lang", "cpp", "-o", str(out))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return out


def test_the_skeleton_documents_the_node_and_each_messages_fields(skeleton: Path) -> None:
    text = (skeleton / "cpp" / "onboard" / "ttapi_plugin.hpp").read_text()
    assert "class TtapiPlugin : public link::NodePlugin" in text and '#include "ttapi/node.hpp"' in text
    assert "udp.run(stop);" in text and "node.add(plugin);" in text and "DttLink" in text
    assert "link::NodeContext& ctx" in text and "ctx.send(" in text
    start = text.index("/// TT_ACTION_COMMAND (id 50005)")
    doc = text[start:text.index("link::CommandOutcome on_command(", start)]
    for field in ("target_system (uint8_t)", "command_id (uint16_t)", "action (uint8_t, enum TtAction)",
                  "time_usec (uint64_t, us)", "param (float[4])", "argument (char[48])"):
        assert field in doc, (field, doc)
    assert "void on_tt_action_command" not in text  # the command server's: on_command() is its action


def test_handlers_reply_and_commands_run_once_through_the_node(skeleton: Path, tmp_path: Path) -> None:
    import ttapi

    plugin = skeleton / "cpp" / "onboard" / "ttapi_plugin.hpp"
    text = plugin.read_text()
    for old, new in (MEMBER, ACTION, REPLY):
        assert old in text, old
        text = text.replace(old, new)
    plugin.write_text(text)
    main = tmp_path / "main.cpp"
    main.write_text(MAIN)
    exe = tmp_path / "handlers"
    build = subprocess.run(["g++", *WARN, "-O1", "-I", str(skeleton / "cpp"), str(main), "-o", str(exe), "-lz"],
                           capture_output=True, text=True, timeout=600)
    assert build.returncode == 0, build.stderr[-5000:]
    cmd = ttapi.TtActionCommand(target_system=1, target_component=191, command_id=4242,
                                action=ttapi.TtAction.TT_ACTION_LAND, time_usec=123456, argument="here")
    pose = ttapi.DjiPoseStamped(target_system=1, sec=7, position=[1.0, 2.0, 3.0], orientation=[0, 0, 0, 1])
    other = ttapi.Heartbeat(type=2)
    stranger = ttapi.TtActionCommand(target_system=9, command_id=1)  # for another vehicle: ignored
    frames = (ttapi.encode(other, 0, 255, 190) + ttapi.encode(cmd, 1, 255, 190) + ttapi.encode(pose, 2, 255, 190)
              + ttapi.encode(cmd, 3, 255, 190) + ttapi.encode(stranger, 4, 255, 190))
    lines_in = ["A " + frames[i:i + 100].hex() for i in range(0, len(frames), 100)]
    # a file: its offer accepted (not counted), its data stored and reported (counted), its end
    payload = bytes(range(256)) * 8
    meta = hashlib.sha256(payload).digest() + b"f.bin"
    enc = ttapi.Encoder(sysid=255, compid=190)
    lines_in.append("S " + enc.encode(ttapi.TtFileOffer(
        target_system=1, target_component=191, transfer_id=77, size=len(payload), meta_length=len(meta),
        meta_offset=0, meta=meta)).hex())  # one part: the name is short
    chunks = [enc.encode(ttapi.TtFileData(transfer_id=77, offset=o, data=payload[o:o + 80]))
              for o in range(0, len(payload), 80)]
    lines_in += ["A " + c.hex() for c in chunks[:-1]] + ["C " + chunks[-1].hex()]
    run = subprocess.run([str(exe), str(tmp_path / "inbox")], input="".join(x + "\n" for x in lines_in),
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert lines[0] == f"delivered {5 + 1 + len(chunks)} executed 1 allocations 0", lines
    assert (tmp_path / "inbox" / "f.bin").read_bytes() == payload
    assert all(len(bytes.fromhex(p)) <= 100 for p in lines[1:])
    replies = ttapi.Parser().feed(b"".join(bytes.fromhex(p) for p in lines[1:]))
    acks = [m for m in replies if isinstance(m, ttapi.TtCommandAck)]
    assert len(acks) == 2  # the retry gets the recorded ack again
    for ack in acks:
        assert (ack.command_id, ack.action, ack.result, ack.progress, ack.target_system, ack.target_component) == (
            4242, ttapi.TtAction.TT_ACTION_LAND, ttapi.TtResult.TT_RESULT_ACCEPTED, 100, 255, 190)
        assert (ack.get_srcSystem(), ack.get_srcComponent()) == (1, 191)
    echoes = [m for m in replies if isinstance(m, ttapi.DjiPoseStamped)]
    assert len(echoes) == 1 and echoes[0].sec == 7 and list(echoes[0].position) == [1.0, 2.0, 3.0]
    beats = [m for m in replies if isinstance(m, ttapi.Heartbeat)]
    assert beats and beats[0].type == ttapi.MavType.MAV_TYPE_ONBOARD_CONTROLLER
    # control frames (acks, replies) leave ahead of telemetry (the heartbeat)
    assert replies.index(beats[0]) > replies.index(acks[0])
    statuses = [m for m in replies if isinstance(m, ttapi.TtFileStatus)]
    assert statuses[0].result == ttapi.TtFileResult.TT_FILE_RESULT_IN_PROGRESS
    assert statuses[-1].result == ttapi.TtFileResult.TT_FILE_RESULT_COMPLETE
