// scheduler_driver: the generated link::Scheduler (scheduler.hpp) driven by a script on stdin,
// for tests/test_cpp_node_parity.py, which runs ttctl's Python Scheduler (proto/scheduler.py) on the
// same script and compares the packets.
//
//     scheduler_driver MTU RATE < script
//
// Script lines: `C HEX KEY` / `T HEX KEY` queue a frame at control / telemetry priority (KEY 0:
// none); `S ID` adds a bulk source, `R ID` removes it, `B ID HEX` gives source ID a frame to hand
// out (a 100-byte frame only into a packet with 100 bytes free, as a narrow data frame);
// `P NOW` asks for a packet: the driver prints its hex, or `-`.
#include <cstdint>
#include <cstdio>
#include <deque>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ttapi/scheduler.hpp"

namespace {

std::vector<std::uint8_t> unhex(const std::string& s)
{
    std::vector<std::uint8_t> out;
    for (std::size_t i = 0; i + 1 < s.size(); i += 2) {
        out.push_back(static_cast<std::uint8_t>(std::stoul(s.substr(i, 2), nullptr, 16)));
    }
    return out;
}

class Source : public ttapi::link::BulkSource {
public:
    std::deque<std::vector<std::uint8_t>> frames;

    std::size_t pull(double /*now*/, std::size_t space, std::uint8_t* out) override
    {
        if (frames.empty() || (frames.front().size() == 100 && space < 100)) {
            return 0;
        }
        const std::vector<std::uint8_t> f = frames.front();
        frames.pop_front();
        std::copy(f.begin(), f.end(), out);
        return f.size();
    }
};

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: scheduler_driver MTU RATE < script\n");
        return 2;
    }
    ttapi::link::Scheduler sched(std::stoul(argv[1]), std::stod(argv[2]));
    std::map<int, Source> sources;
    std::string line;
    std::uint8_t pkt[280];
    while (std::getline(std::cin, line)) {
        std::istringstream in(line);
        std::string op;
        in >> op;
        if (op == "C" || op == "T") {
            std::string hex;
            unsigned long long key = 0;
            in >> hex >> key;
            const std::vector<std::uint8_t> f = unhex(hex);
            sched.send(f.data(), f.size(), op == "C" ? ttapi::link::Priority::control : ttapi::link::Priority::telemetry,
                       key);
        } else if (op == "S") {
            int id = 0;
            in >> id;
            sources[id].frames.clear();  // a new source under an id used before
            sched.add_source(&sources[id]);
        } else if (op == "R") {
            int id = 0;
            in >> id;
            sched.remove_source(&sources[id]);
        } else if (op == "B") {
            int id = 0;
            std::string hex;
            in >> id >> hex;
            sources[id].frames.push_back(unhex(hex));
        } else if (op == "P") {
            double now = 0;
            in >> now;
            const std::size_t n = sched.next_packet(now, pkt);
            if (n == 0) {
                std::printf("-\n");
            } else {
                for (std::size_t i = 0; i < n; ++i) {
                    std::printf("%02x", pkt[i]);
                }
                std::printf("\n");
            }
        }
    }
    return 0;
}
