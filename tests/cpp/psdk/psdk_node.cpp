// psdk_node: the generated node on DJI's Payload SDK v3 low-speed channel (ttapi::link::PsdkLink),
// built against DJI's real, vendored dji_low_speed_data_channel.h and linked with the stand-in
// for its functions (tests/cpp/fake_psdk/), for tests/test_cpp_psdk.py:
//
//     psdk_node INBOX SERVE [MTU [RATE]]
//
// The node (1/240) takes files into INBOX, serves SERVE, accepts every command, sends MTU-byte
// packets (default 128, the channel's) paced at RATE B/s (default 3500, under DJI's 4 KB/s).
// Output: JSON lines on stdout, flushed: {"event": "ready"} once the channel is open, a
// {"event": "problem", ...} line for every SDK call that did not succeed (DJI's words), file
// events; on SIGINT/SIGTERM a last {"event": "stats", ...} line (the link's counters, the
// stand-in's, the process's peak memory) and exit 0. A channel that cannot open: its words on
// stderr, exit 1.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "fake_psdk.hpp"
#include "ttapi/psdk_link.hpp"

namespace {

std::atomic<bool> g_stop{false};

void on_signal(int /*sig*/) { g_stop.store(true); }

long peak_kib()
{
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("VmHWM:", 0) == 0) {
            return std::strtol(line.c_str() + 6, nullptr, 10);
        }
    }
    return -1;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 3 || argc > 5) {
        std::fprintf(stderr, "usage: psdk_node INBOX SERVE [MTU [RATE]]\n");
        return 2;
    }
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    ttapi::link::NodeConfig cfg;
    cfg.inbox = argv[1];
    cfg.serve = argv[2];
    cfg.mtu = argc >= 4 ? static_cast<std::size_t>(std::atoi(argv[3])) : 128;
    cfg.rate_Bps = argc >= 5 ? std::atof(argv[4]) : 3500.0;
    ttapi::link::Node node(cfg);
    node.on_command([](const ttapi::TtActionCommand&, const ttapi::Frame&, ttapi::link::NodeContext&) {
        return ttapi::link::CommandOutcome(ttapi::TtResult::TT_RESULT_ACCEPTED);
    });
    node.on_event([](const ttapi::link::NodeEvent& e) {
        if (e.kind == ttapi::link::NodeEvent::Kind::file) {
            std::printf("{\"event\": \"file\", \"what\": %d, \"size\": %llu}\n", static_cast<int>(e.file),
                        static_cast<unsigned long long>(e.size));
            std::fflush(stdout);
        }
    });
    ttapi::link::Words why;
    if (!node.start(why)) {
        std::fprintf(stderr, "%s\n", why.c_str());
        return 1;
    }
    ttapi::link::PsdkLink link(node, DJI_CHANNEL_ADDRESS_MASTER_RC_APP, [](const ttapi::link::PsdkProblem& p) {
        std::printf("{\"event\": \"problem\", \"call\": \"%s\", \"code\": \"0x%llx\", \"name\": \"%s\", "
                    "\"words\": \"%s\", \"hint\": \"%s\"}\n",
                    p.call, static_cast<unsigned long long>(p.code), p.name, p.words, p.hint);
        std::fflush(stdout);
    });
    if (!link.open(why)) {
        std::fprintf(stderr, "%s\n", why.c_str());
        return 1;
    }
    std::printf("{\"event\": \"ready\"}\n");
    std::fflush(stdout);
    link.run(&g_stop);
    node.close();
    const FakePsdkStats f = fake_psdk_stats();
    std::printf("{\"event\": \"stats\", \"received\": %llu, \"dropped\": %llu, \"sent\": %llu, \"refused\": %llu, "
                "\"busy_waits\": %llu, \"buffer_waits\": %llu, \"problems\": %llu, \"lost\": %llu, "
                "\"sdk_packets_out\": %llu, \"sdk_buffered\": %llu, \"sdk_discarded\": %llu, \"sdk_callbacks\": %llu, "
                "\"sdk_slowest_callback_us\": %llu, \"peak_kib\": %ld}\n",
                static_cast<unsigned long long>(link.received()), static_cast<unsigned long long>(link.dropped()),
                static_cast<unsigned long long>(link.sent()), static_cast<unsigned long long>(link.refused()),
                static_cast<unsigned long long>(link.busy_waits()),
                static_cast<unsigned long long>(link.buffer_waits()),
                static_cast<unsigned long long>(link.problems()), static_cast<unsigned long long>(link.lost()),
                static_cast<unsigned long long>(f.packets_out), static_cast<unsigned long long>(f.buffered),
                static_cast<unsigned long long>(f.discarded), static_cast<unsigned long long>(f.callbacks),
                static_cast<unsigned long long>(f.slowest_callback_us), peak_kib());
    std::fflush(stdout);
    return 0;
}
