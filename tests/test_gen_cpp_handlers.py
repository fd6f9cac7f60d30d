"""The onboard C++ handler skeleton: every handler gets an Outbox to send any message of the
dialect back (wired by the user to an Encoder and a Packetizer), its comment lists the
message's fields, and its usage comment feeds DTT packets to a PacketReceiver. Built with g++
-Werror as a user would edit it: the TT_ACTION_COMMAND handler answers with TT_COMMAND_ACK,
which ttctl's Python bindings read back out of the packets; dispatching and replying allocate
nothing."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import TTAPI, run_ttctl

pytestmark = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

WARN = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]

# What the user writes in the skeleton's TT_ACTION_COMMAND handler.
REPLY = """TtCommandAck ack;
        ack.target_system = frame.sysid;
        ack.target_component = frame.compid;
        ack.command_id = msg.command_id;
        ack.action = msg.action;
        ack.result = 0;
        ack.progress = 100;
        out.send(ack);"""

# The user's wiring: an Outbox that frames with an Encoder and cuts packets with a Packetizer
# (here into a fixed buffer the test prints), and a PacketReceiver fed with the packets read
# from stdin (hex, one per line); operator new counts allocations.
MAIN = r"""#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <string>

#include "ttapi/ttapi.hpp"
#include "onboard/ttapi_plugin.hpp"

static std::size_t allocations = 0;

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

namespace {

struct Packets {
    std::uint8_t bytes[4096];
    std::size_t len[64];
    std::size_t count = 0;
    std::size_t used = 0;
};

class LinkOutbox : public ttapi::Outbox {
public:
    LinkOutbox(ttapi::Encoder& encoder, ttapi::Packetizer& packetizer, Packets& packets)
        : encoder_(encoder), packetizer_(packetizer), packets_(packets)
    {
    }

    bool send_payload(const ttapi::MessageInfo& info, const std::uint8_t* payload, std::size_t n) override
    {
        std::uint8_t frame[ttapi::MAX_FRAME];
        const std::size_t len = encoder_.encode_payload(info, payload, n, frame, sizeof frame);
        if (len == 0) {
            return false;
        }
        packetizer_.add(frame, len, [this](const std::uint8_t* p, std::size_t k) { keep(p, k); });
        packetizer_.flush([this](const std::uint8_t* p, std::size_t k) { keep(p, k); });
        return true;
    }

private:
    void keep(const std::uint8_t* p, std::size_t k)
    {
        std::memcpy(packets_.bytes + packets_.used, p, k);
        packets_.len[packets_.count++] = k;
        packets_.used += k;
    }

    ttapi::Encoder& encoder_;
    ttapi::Packetizer& packetizer_;
    Packets& packets_;
};

}  // namespace

int main()
{
    ttapi::Encoder encoder(1, 191);
    ttapi::Packetizer packetizer;  // DTT: 100-byte packets
    static Packets packets;
    LinkOutbox outbox(encoder, packetizer, packets);
    ttapi::Dispatcher dispatcher(outbox);
    ttapi::onboard::TtapiPlugin plugin;
    plugin.register_handlers(dispatcher);
    ttapi::PacketReceiver receiver;
    static std::uint8_t input[64][128];
    std::size_t sizes[64];
    std::size_t count = 0;
    std::string line;
    while (count < 64 && std::getline(std::cin, line)) {
        sizes[count] = line.size() / 2;
        for (std::size_t i = 0; i < sizes[count]; ++i) {
            input[count][i] = static_cast<std::uint8_t>(std::stoul(line.substr(2 * i, 2), nullptr, 16));
        }
        ++count;
    }
    std::size_t delivered = 0;
    const std::size_t before = allocations;
    for (std::size_t k = 0; k < count; ++k) {
        delivered += receiver.feed(input[k], sizes[k], dispatcher);
    }
    const std::size_t during = allocations - before;
    std::printf("delivered %zu allocations %zu\n", delivered, during);
    for (std::size_t i = 0, at = 0; i < packets.count; at += packets.len[i], ++i) {
        for (std::size_t k = 0; k < packets.len[i]; ++k) {
            std::printf("%02x", static_cast<unsigned>(packets.bytes[at + k]));
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


def test_the_skeleton_documents_the_packet_receiver_and_each_messages_fields(skeleton: Path) -> None:
    text = (skeleton / "cpp" / "onboard" / "ttapi_plugin.hpp").read_text()
    assert "parser.feed" not in text and "receiver.feed(packet, n, dispatcher);" in text
    assert "Outbox& out" in text and "out.send(" in text
    start = text.index("/// TT_ACTION_COMMAND (id 50005)")
    doc = text[start:text.index("void on_tt_action_command", start)]
    for field in ("target_system (uint8_t)", "command_id (uint16_t)", "action (uint8_t, enum TtAction)",
                  "time_usec (uint64_t, us)", "param (float[4])", "argument (char[48])"):
        assert field in doc, (field, doc)


def test_a_handler_replies_through_its_outbox(skeleton: Path, tmp_path: Path) -> None:
    import ttapi

    plugin = skeleton / "cpp" / "onboard" / "ttapi_plugin.hpp"
    text = plugin.read_text()
    todo = "// TODO: handle TT_ACTION_COMMAND (from system frame.sysid, component frame.compid); out.send(...) replies"
    assert todo in text
    plugin.write_text(text.replace(todo, REPLY))
    main = tmp_path / "main.cpp"
    main.write_text(MAIN)
    exe = tmp_path / "handlers"
    build = subprocess.run(["g++", *WARN, "-O1", "-I", str(skeleton / "cpp"), str(main), "-o", str(exe)],
                           capture_output=True, text=True, timeout=600)
    assert build.returncode == 0, build.stderr[-5000:]
    cmd = ttapi.TtActionCommand(target_system=1, target_component=191, command_id=4242,
                                action=ttapi.TtAction.TT_ACTION_LAND, argument="here")
    other = ttapi.Heartbeat(type=2)
    frames = ttapi.encode(other, 0, 255, 190) + ttapi.encode(cmd, 1, 255, 190)
    packets = [frames[i:i + 100] for i in range(0, len(frames), 100)]
    run = subprocess.run([str(exe)], input="".join(p.hex() + "\n" for p in packets), capture_output=True, text=True,
                         timeout=60)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert lines[0] == "delivered 2 allocations 0", lines
    replies = ttapi.Parser().feed(b"".join(bytes.fromhex(p) for p in lines[1:]))
    assert len(replies) == 1
    ack = replies[0]
    assert isinstance(ack, ttapi.TtCommandAck)
    assert (ack.command_id, ack.action, ack.progress, ack.target_system, ack.target_component) == (
        4242, ttapi.TtAction.TT_ACTION_LAND, 100, 255, 190)
    assert (ack.get_srcSystem(), ack.get_srcComponent(), ack.get_seq()) == (1, 191, 0)
