// node_driver: a generated link::Node driven sans-IO, in virtual time, by a script on stdin, for
// tests/test_cpp_node_parity.py, which runs ttctl's Python Endpoint on the same input and compares what
// each sends.
//
//     node_driver INBOX SERVE RATE [INBOUND [MTU [KEY TIMESTAMP]]] < script
//
// The node is 1/240, paced at RATE B/s, shares INBOUND B/s among concurrent uploads (rate
// grants; default 0: none), sends MTU-byte packets (default 100), signs with KEY (64 hex
// digits) from TIMESTAMP on (a start ahead of the clock makes the signatures repeatable), receives into INBOX, serves SERVE ("-": nothing), sends
// no heartbeat, and accepts every command (ACCEPTED, as the Python endpoint it is compared with
// is told to). Script lines: `I ID` queues a transfer id for the node to draw (as the Python end's
// seeded random numbers give it); `R NOW HEX` a packet arrives at NOW; `P NOW` the node is
// polled at NOW until it has nothing more to send: the driver prints the packets' hex,
// space-separated, or `-`, and flushes. A MOP pipeline beside the link (paced at 20000 B/s):
// `O NOW` it opens, `C NOW` it closes, `Q NOW` the node's pipeline frames at NOW are printed as
// `P` prints packets, `S NOW HEX` a whole frame arrives on it.
#include <cstdint>
#include <cstdio>
#include <deque>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "ttapi/node.hpp"

int main(int argc, char** argv)
{
    if (argc < 4 || argc > 8 || argc == 7) {
        std::fprintf(stderr, "usage: node_driver INBOX SERVE RATE [INBOUND [MTU [KEY TIMESTAMP]]] < script\n");
        return 2;
    }
    std::deque<std::uint32_t> ids;
    ttapi::link::NodeConfig cfg;
    cfg.inbox = argv[1];
    if (std::string(argv[2]) != "-") {
        cfg.serve = argv[2];
    }
    cfg.rate_Bps = std::stod(argv[3]);
    cfg.inbound_Bps = argc >= 5 ? std::stod(argv[4]) : 0.0;
    cfg.mtu = argc >= 6 ? static_cast<std::size_t>(std::stoul(argv[5])) : 100;
    std::unique_ptr<ttapi::Signing> signing;
    if (argc == 8) {
        std::uint8_t key[32];
        const std::string hex = argv[6];
        for (std::size_t i = 0; i < 32; ++i) {
            key[i] = static_cast<std::uint8_t>(std::stoul(hex.substr(2 * i, 2), nullptr, 16));
        }
        signing.reset(new ttapi::Signing(key, 0, false, std::stoull(argv[7])));
        cfg.signing = signing.get();
    }
    cfg.heartbeat_interval = 0;
    cfg.pipe_rate_Bps = 20000.0;
    cfg.new_id = [&ids]() -> std::uint32_t {
        if (ids.empty()) {
            return 0xDEADBEEF;
        }
        const std::uint32_t n = ids.front();
        ids.pop_front();
        return n;
    };
    ttapi::link::Node node(cfg);
    node.on_command([](const ttapi::TtActionCommand&, const ttapi::Frame&, ttapi::link::NodeContext&) {
        return ttapi::link::CommandOutcome(ttapi::TtResult::TT_RESULT_ACCEPTED);
    });
    ttapi::link::Words why;
    if (!node.start(why)) {
        std::fprintf(stderr, "%s\n", why.c_str());
        return 1;
    }
    std::string line;
    std::uint8_t pkt[280];
    while (std::getline(std::cin, line)) {
        std::istringstream in(line);
        std::string op;
        in >> op;
        if (op == "I") {
            unsigned long id = 0;
            in >> id;
            ids.push_back(static_cast<std::uint32_t>(id));
            continue;
        }
        double now = 0;
        in >> now;
        if (op == "O" || op == "C") {
            node.set_pipe(op == "O", now);
            continue;
        }
        if (op == "R" || op == "S") {
            std::string hex;
            in >> hex;
            std::vector<std::uint8_t> data;
            for (std::size_t i = 0; i + 1 < hex.size(); i += 2) {
                data.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
            }
            if (op == "R") {
                node.receive(now, data.data(), data.size());
            } else {
                node.receive_pipe(now, data.data(), data.size());
            }
        } else if (op == "P" || op == "Q") {
            std::string out;
            for (std::size_t n; (n = op == "P" ? node.poll(now, pkt) : node.poll_pipe(now, pkt)) != 0;) {
                if (!out.empty()) {
                    out += ' ';
                }
                for (std::size_t i = 0; i < n; ++i) {
                    char b[3];
                    std::snprintf(b, sizeof b, "%02x", pkt[i]);
                    out += b;
                }
            }
            std::printf("%s\n", out.empty() ? "-" : out.c_str());
            std::fflush(stdout);
        }
    }
    node.close();
    return 0;
}
