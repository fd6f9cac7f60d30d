// mop_node: the generated node on DJI's Payload SDK with both paths: the low-speed channel
// (ttapi::link::PsdkLink, stand-in fake_psdk.cpp, packets over UDP) and a MOP pipeline
// (ttapi::link::MopLink, stand-in fake_mop.cpp, the stream over TCP), built against DJI's real,
// vendored dji_low_speed_data_channel.h and dji_mop_channel.h, for tests/test_cpp_mop.py:
//
//     mop_node INBOX SERVE [MTU [RATE [PIPE_RATE]]]
//
// The node (1/240) takes files into INBOX, serves SERVE, accepts every command, sends MTU-byte
// packets (default 128) at RATE B/s (default 3500) on the low-speed channel and file data at
// PIPE_RATE B/s (default 100000) on the pipeline (MOP channel id 49152) while it is open.
// Output: JSON lines on stdout, flushed: {"event": "ready"}, {"event": "pipe", "kind": ...} for
// what the pipeline reports (listening, opened, closed, problem), file events; on SIGINT/SIGTERM
// a last {"event": "stats", ...} line and exit 0. Every SDK problem is also one line on stderr in
// DJI's words ("MOP: <call>: <words> <hint>").
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "fake_mop.hpp"
#include "fake_psdk.hpp"
#include "ttapi/mop_link.hpp"

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

const char* kind_name(ttapi::link::PipeReport::Kind k)
{
    using K = ttapi::link::PipeReport::Kind;
    switch (k) {
    case K::listening:
        return "listening";
    case K::opened:
        return "opened";
    case K::closed:
        return "closed";
    case K::problem:
        return "problem";
    }
    return "?";
}

unsigned long long u(std::uint64_t v) { return static_cast<unsigned long long>(v); }

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 3 || argc > 6) {
        std::fprintf(stderr, "usage: mop_node INBOX SERVE [MTU [RATE [PIPE_RATE]]]\n");
        return 2;
    }
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    ttapi::link::NodeConfig cfg;
    cfg.inbox = argv[1];
    cfg.serve = argv[2];
    cfg.mtu = argc >= 4 ? static_cast<std::size_t>(std::atoi(argv[3])) : 128;
    cfg.rate_Bps = argc >= 5 ? std::atof(argv[4]) : 3500.0;
    cfg.pipe_rate_Bps = argc >= 6 ? std::atof(argv[5]) : 100000.0;
    ttapi::link::Node node(cfg);
    node.on_command([](const ttapi::TtActionCommand&, const ttapi::Frame&, ttapi::link::NodeContext&) {
        return ttapi::link::CommandOutcome(ttapi::TtResult::TT_RESULT_ACCEPTED);
    });
    node.on_event([](const ttapi::link::NodeEvent& e) {
        if (e.kind == ttapi::link::NodeEvent::Kind::file) {
            std::printf("{\"event\": \"file\", \"what\": %d, \"size\": %llu}\n", static_cast<int>(e.file), u(e.size));
            std::fflush(stdout);
        }
    });
    ttapi::link::Words why;
    if (!node.start(why)) {
        std::fprintf(stderr, "%s\n", why.c_str());
        return 1;
    }
    ttapi::link::PsdkLink link(node, DJI_CHANNEL_ADDRESS_MASTER_RC_APP, [](const ttapi::link::PsdkProblem& p) {
        std::printf("{\"event\": \"problem\", \"call\": \"%s\", \"code\": \"0x%llx\", \"words\": \"%s\"}\n", p.call,
                    u(p.code), p.words);
        std::fflush(stdout);
    });
    if (!link.open(why)) {
        std::fprintf(stderr, "%s\n", why.c_str());
        return 1;
    }
    ttapi::link::MopLink mop(node, 49152, [](const ttapi::link::PipeReport& r) {
        std::printf("{\"event\": \"pipe\", \"kind\": \"%s\", \"connection\": %llu, \"call\": \"%s\", "
                    "\"code\": \"0x%llx\", \"name\": \"%s\", \"words\": \"%s\"}\n",
                    kind_name(r.kind), u(r.connection), r.problem.call, u(r.problem.code), r.problem.name,
                    r.problem.words);
        std::fflush(stdout);
        if (r.kind == ttapi::link::PipeReport::Kind::problem) {
            std::fprintf(stderr, "MOP: %s: %s %s\n", r.problem.call, r.problem.words, r.problem.hint);
        }
    });
    link.attach(mop.side());
    mop.start();
    std::printf("{\"event\": \"ready\"}\n");
    std::fflush(stdout);
    link.run(&g_stop);
    mop.stop();
    node.close();
    const ttapi::link::PipeStats p = mop.stats();
    const ttapi::link::NodeStats& n = node.stats();
    const FakeMopStats f = fake_mop_stats();
    std::printf("{\"event\": \"stats\", \"problems\": %llu, \"pipe_opens\": %llu, \"pipe_closes\": %llu, "
                "\"pipe_frames_in\": %llu, \"pipe_frames_out\": %llu, \"pipe_bytes_out\": %llu, "
                "\"connections\": %llu, \"closes\": %llu, \"bytes_in\": %llu, \"bytes_out\": %llu, "
                "\"short_writes\": %llu, \"pipe_problems\": %llu, \"bad_bytes\": %llu, \"frames_in\": %llu, "
                "\"packets_in\": %llu, \"packets_out\": %llu, \"sdk_accepts\": %llu, \"sdk_bytes_in\": %llu, "
                "\"sdk_bytes_out\": %llu, \"sdk_short_sends\": %llu, \"sdk_forced_closes\": %llu, "
                "\"sdk_failed_calls\": %llu, \"sdk_live_handles\": %llu, \"sdk_stalls\": %llu, \"timeouts\": %llu, "
                "\"peak_kib\": %ld}\n",
                u(link.problems()), u(n.pipe_opens), u(n.pipe_closes), u(n.pipe_frames_in), u(n.pipe_frames_out),
                u(n.pipe_bytes_out), u(p.connections), u(p.closes), u(p.bytes_in), u(p.bytes_out),
                u(p.short_writes), u(p.problems), u(p.bad_bytes), u(p.frames_in), u(n.packets_in),
                u(n.packets_out), u(f.accepts), u(f.bytes_in), u(f.bytes_out), u(f.short_sends),
                u(f.forced_closes), u(f.failed_calls), u(f.live_handles), u(f.stalls), u(p.timeouts), peak_kib());
    std::fflush(stdout);
    return 0;
}
