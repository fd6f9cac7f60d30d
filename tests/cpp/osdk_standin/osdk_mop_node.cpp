// osdk_mop_node: the generated node on the Onboard SDK 4.1 with both paths: OsdkLink on DTT
// (fake_osdk.cpp, packets over UDP on FAKE_OSDK_LISTEN) and OsdkMopLink on the MOP server
// (fake_osdk_mop.cpp, the pipeline over TCP on TTCTL_FAKE_MOP_PORT), built against DJI's real,
// vendored OSDK 4.1 headers, for tests/test_cpp_mop.py. Files land in ./inbox. Output: one JSON
// line per PipeReport ({"kind": 0 listening, 1 opened, 2 closed, 3 problem, ...}), and on SIGINT
// a {"stats": ...} line. The Onboard SDK cannot interrupt MopServer::accept: after SIGINT the
// program ends when accept returns (a connection, or the next one).
#include <atomic>
#include <csignal>
#include <cstdio>

#include "dji_linux_helpers.hpp"
#include "ttapi/osdk_link.hpp"
#include "ttapi/osdk_mop_link.hpp"

namespace {
std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }
unsigned long long u(std::uint64_t v) { return static_cast<unsigned long long>(v); }
}  // namespace

int main(int argc, char** argv)
{
    std::signal(SIGINT, on_signal);
    LinuxSetup setup(argc, argv);
    DJI::OSDK::Vehicle* vehicle = setup.getVehicle();
    ttapi::link::NodeConfig cfg;  // DTT: 100-byte packets
    cfg.inbox = "inbox";
    cfg.serve = "outbox";
    ttapi::link::Node node(cfg);
    ttapi::link::OsdkLink link(node, vehicle);
    ttapi::link::OsdkMopLink mop(node, vehicle, 49152, [](const ttapi::link::PipeReport& r) {
        std::printf("{\"kind\": %d, \"connection\": %llu, \"call\": \"%s\", \"words\": \"%s\"}\n",
                    static_cast<int>(r.kind), u(r.connection), r.problem.call, r.problem.words);
        std::fflush(stdout);
    });
    ttapi::link::Words why;
    if (!node.start(why) || !link.open(why)) {
        std::fprintf(stderr, "%s\n", why.c_str());
        return 1;
    }
    link.attach(mop.side());
    mop.start();
    link.run(&g_stop);
    mop.stop();
    const ttapi::link::PipeStats s = mop.stats();
    std::printf("{\"stats\": 1, \"connections\": %llu, \"bytes_in\": %llu, \"pipe_frames_in\": %llu}\n",
                u(s.connections), u(s.bytes_in), u(node.stats().pipe_frames_in));
    std::fflush(stdout);
    return 0;
}
