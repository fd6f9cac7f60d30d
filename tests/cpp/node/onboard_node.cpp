// onboard_node: the generated C++ onboard end (ttapi::link::Node on UDP) as a command-line
// program, for tests that put it against ttctl's Python ends and the Java tablet.
//
// Built from the generated skeleton cpp/onboard/ttapi_plugin.hpp as a user would edit it (the
// test fills in on_command() and the DJI_POSE_STAMPED handler, which answers set-points with
// ctx.setpoint(): EDITS in tests/cpp_node_lib.py):
//
//     g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror -I OUT/cpp -I SKELETON_DIR onboard_node.cpp -o onboard_node
//
// Usage:
//     onboard_node (--listen udpin:HOST:PORT | --to udpout:HOST:PORT)
//                  [--inbox DIR] [--serve DIR] [--key FILE [--accept-unsigned]] [--rate B/s] [--inbound B/s]
//                  [--sysid N] [--compid N] [--max-file BYTES] [--max-dir BYTES] [--overwrite]
//                  [--heartbeat S] [--send FILE --send-to SYS/COMP [--send-name NAME]]
//
//   --listen/--to  the UDP endpoint (ttctl's spelling); a listening node answers every address
//                  that sent it a valid frame
//   --inbox DIR    receive files into DIR (a jail; partial files in DIR/.ttctl-partial)
//   --serve DIR    files a peer may fetch (ttctl send-file --from, the tablet's `fetch`)
//   --key FILE     MAVLink 2 signing: 64 hex digits or a passphrase (as ttctl --key)
//   --rate B/s     the pace of what it sends (default 6700: the M100's downlink); 0: unpaced
//   --inbound B/s  what it can take (the uplink's capacity, the M100's: 500), shared out among the
//                  files it receives at once by rate grants (default 0: no grants)
//   --max-file     per-file quota of the inbox (default 1 GiB)
//   --send FILE    upload FILE to SYS/COMP once started (ttctl recv-file takes it)
//   --mtu BYTES    the link's packet size (default 100: DJI's DTT; 128: the PSDK channel)
//   --print-geometry  print the frame geometry for every packet size 1..300, unsigned and signed
//                  ("MTU SIGNED FIT NARROW_CAP NARROW_FRAME WIDE_FRAME SURVIVAL(0.1)", or
//                  "MTU SIGNED -" when refused) and exit
//   --print-name-rules  print the code points a file name may not hold (ranges "lo hi", hex) and
//                  exit: the name rules' character table, for comparing with Python's unicodedata
//
// Output: one JSON object per line on stdout, flushed: {"event": "ready", "port": N} first,
// then file events (accepted, busy, refused, complete, failed), serving/served/serve-failed,
// request-refused, command (each execution and each repeated ack), link-refused, sent (the
// upload's result, with its highest rate grant and its data frames' bytes and time). SIGINT or SIGTERM: a last {"event": "stats", ...} line, exit 0.
// Malformed options: one line on stderr, exit 2.
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include "ttapi/udp_link.hpp"
#include "ttapi_plugin.hpp"

namespace {

std::atomic<bool> g_stop{false};

void on_signal(int /*sig*/) { g_stop.store(true); }

// JSON string of bytes that may not be UTF-8 (a byte of a bad sequence as \u00XX).
std::string json(std::string_view s)
{
    std::string out = "\"";
    const auto* p = reinterpret_cast<const std::uint8_t*>(s.data());
    for (std::size_t i = 0; i < s.size();) {
        std::uint32_t cp = 0;
        const std::size_t k = ttapi::link::impl::utf8_char(p, s.size(), i, cp);
        char buf[8];
        if (k == 0 || cp < 0x20 || cp == 0x7F) {
            std::snprintf(buf, sizeof buf, "\\u%04x", k == 0 ? static_cast<unsigned>(p[i]) : static_cast<unsigned>(cp));
            out += buf;
            i += k == 0 ? 1 : k;
            continue;
        }
        if (cp == '"' || cp == '\\') {
            out += '\\';
        }
        out.append(s.data() + i, k);
        i += k;
    }
    out += '"';
    return out;
}

bool read_key(const char* path, std::uint8_t key[32])
{
    FILE* f = std::fopen(path, "rb");
    if (f == nullptr) {
        return false;
    }
    char buf[4097];
    const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
    std::fclose(f);
    std::string text(buf, n);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
        text.pop_back();
    }
    std::size_t start = 0;
    while (start < text.size() && std::isspace(static_cast<unsigned char>(text[start]))) {
        ++start;
    }
    text = text.substr(start);
    if (text.empty()) {
        return false;
    }
    bool hex = text.size() == 64;
    for (char c : text) {
        hex = hex && std::isxdigit(static_cast<unsigned char>(c));
    }
    if (hex) {
        for (int i = 0; i < 32; ++i) {
            key[i] = static_cast<std::uint8_t>(std::stoul(text.substr(2 * static_cast<std::size_t>(i), 2), nullptr, 16));
        }
    } else {
        ttapi::sha256(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), key);
    }
    return true;
}

[[noreturn]] void usage(const std::string& why)
{
    std::fprintf(stderr, "onboard_node: %s\n", why.c_str());
    std::exit(2);
}

const char* file_event_name(ttapi::link::FileEvent e)
{
    return ttapi::link::to_string(e);
}

}  // namespace

int main(int argc, char** argv)
{
    ttapi::link::NodeConfig cfg;
    std::string endpoint;
    std::string key_file;
    bool accept_unsigned = false;
    std::string send_path;
    std::string send_name;
    int send_sys = -1;
    int send_comp = -1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                usage(a + " needs a value");
            }
            return argv[++i];
        };
        auto number = [&]() -> double {
            const std::string v = value();
            char* end = nullptr;
            const double x = std::strtod(v.c_str(), &end);
            if (end == v.c_str() || *end != '\0' || x < 0) {
                usage(a + ": not a non-negative number: " + v);
            }
            return x;
        };
        if (a == "--listen" || a == "--to") {
            endpoint = value();
        } else if (a == "--inbox") {
            cfg.inbox = value();
        } else if (a == "--serve") {
            cfg.serve = value();
        } else if (a == "--key") {
            key_file = value();
        } else if (a == "--accept-unsigned") {
            accept_unsigned = true;
        } else if (a == "--rate") {
            cfg.rate_Bps = number();
        } else if (a == "--inbound") {
            cfg.inbound_Bps = number();
        } else if (a == "--sysid") {
            cfg.sysid = static_cast<std::uint8_t>(number());
        } else if (a == "--compid") {
            cfg.compid = static_cast<std::uint8_t>(number());
        } else if (a == "--max-file") {
            cfg.quota.max_file_bytes = static_cast<std::uint64_t>(number());
        } else if (a == "--max-dir") {
            cfg.quota.max_dir_bytes = static_cast<std::uint64_t>(number());
        } else if (a == "--overwrite") {
            cfg.quota.overwrite = true;
        } else if (a == "--heartbeat") {
            cfg.heartbeat_interval = number();
        } else if (a == "--mtu") {
            cfg.mtu = static_cast<std::size_t>(number());
        } else if (a == "--print-geometry") {
            for (std::size_t mtu = 1; mtu <= 300; ++mtu) {
                for (int sig = 0; sig < 2; ++sig) {
                    ttapi::link::Geometry g;
                    if (!ttapi::link::Geometry::make(mtu, sig != 0, g)) {
                        std::printf("%zu %d -\n", mtu, sig);
                        continue;
                    }
                    std::printf("%zu %d %d %zu %zu %zu %.12f %.12f\n", mtu, sig, g.fit ? 1 : 0, g.narrow_cap,
                                g.narrow_frame, g.wide_frame, g.survival_wide(0.1), g.packet_loss_from_wide(0.3));
                }
            }
            return 0;
        } else if (a == "--print-name-rules") {
            std::uint32_t lo = 0;
            bool in = false;
            for (std::uint32_t cp = 1; cp <= 0x110000; ++cp) {
                bool refused = false;
                if (cp < 0x110000 && (cp < 0xD800 || cp > 0xDFFF)) {
                    std::uint8_t raw[5] = {'x'};
                    std::size_t n = 1;
                    if (cp < 0x80) {
                        raw[n++] = static_cast<std::uint8_t>(cp);
                    } else if (cp < 0x800) {
                        raw[n++] = static_cast<std::uint8_t>(0xC0 | (cp >> 6));
                        raw[n++] = static_cast<std::uint8_t>(0x80 | (cp & 0x3F));
                    } else if (cp < 0x10000) {
                        raw[n++] = static_cast<std::uint8_t>(0xE0 | (cp >> 12));
                        raw[n++] = static_cast<std::uint8_t>(0x80 | ((cp >> 6) & 0x3F));
                        raw[n++] = static_cast<std::uint8_t>(0x80 | (cp & 0x3F));
                    } else {
                        raw[n++] = static_cast<std::uint8_t>(0xF0 | (cp >> 18));
                        raw[n++] = static_cast<std::uint8_t>(0x80 | ((cp >> 12) & 0x3F));
                        raw[n++] = static_cast<std::uint8_t>(0x80 | ((cp >> 6) & 0x3F));
                        raw[n++] = static_cast<std::uint8_t>(0x80 | (cp & 0x3F));
                    }
                    ttapi::link::Words why;
                    refused = ttapi::link::name_problem(raw, n, why)
                              && why.view() == "the name contains control or undecodable characters";
                }
                if (refused && !in) {
                    lo = cp;
                    in = true;
                } else if (!refused && in) {
                    std::printf("%x %x\n", lo, cp - 1);
                    in = false;
                }
            }
            return 0;
        } else if (a == "--send") {
            send_path = value();
        } else if (a == "--send-name") {
            send_name = value();
        } else if (a == "--send-to") {
            const std::string v = value();
            if (std::sscanf(v.c_str(), "%d/%d", &send_sys, &send_comp) != 2) {
                usage("--send-to: SYS/COMP, not " + v);
            }
        } else {
            usage("unknown option " + a);
        }
    }
    if (endpoint.empty()) {
        usage("--listen udpin:HOST:PORT or --to udpout:HOST:PORT is needed");
    }
    std::uint8_t key[32] = {};
    std::unique_ptr<ttapi::Signing> signing;
    if (!key_file.empty()) {
        if (!read_key(key_file.c_str(), key)) {
            usage("--key " + key_file + ": cannot read a key from it");
        }
        signing.reset(new ttapi::Signing(key, 0, accept_unsigned));
        cfg.signing = signing.get();
    }

    ttapi::link::Node node(cfg);
    ttapi::onboard::TtapiPlugin plugin;
    node.add(plugin);
    node.on_event([&](const ttapi::link::NodeEvent& e) {
        using K = ttapi::link::NodeEvent::Kind;
        std::string line;
        const std::string peer = std::to_string(e.sysid) + "/" + std::to_string(e.compid);
        switch (e.kind) {
        case K::file:
            line = std::string("{\"event\": \"") + file_event_name(e.file) + "\", \"name\": " + json(e.name)
                   + ", \"transfer_id\": " + std::to_string(e.transfer != nullptr ? e.transfer->id : 0)
                   + ", \"bytes\": " + std::to_string(e.size) + ", \"peer\": \"" + peer + "\", \"reason\": "
                   + json(e.reason) + ", \"resumed_bytes\": " + std::to_string(e.resumed_bytes)
                   + ", \"identical\": " + (e.identical ? "true" : "false") + ", \"seconds\": "
                   + std::to_string(e.seconds) + ", \"path\": " + json(e.path != nullptr ? e.path : "") + "}";
            break;
        case K::serving:
        case K::served:
        case K::serve_failed:
            line = std::string("{\"event\": \"")
                   + (e.kind == K::serving ? "serving" : (e.kind == K::served ? "served" : "serve-failed"))
                   + "\", \"name\": " + json(e.name) + ", \"bytes\": " + std::to_string(e.size) + ", \"peer\": \""
                   + peer + "\", \"seconds\": " + std::to_string(e.seconds) + ", \"reason\": " + json(e.reason)
                   + "}";
            break;
        case K::request_refused:
            line = "{\"event\": \"request-refused\", \"name\": " + json(e.name) + ", \"result\": "
                   + std::to_string(e.result) + ", \"reason\": " + json(e.reason) + ", \"peer\": \"" + peer + "\"}";
            break;
        case K::command:
            line = "{\"event\": \"command\", \"command_id\": " + std::to_string(e.command_id) + ", \"action\": "
                   + std::to_string(e.action) + ", \"result\": " + std::to_string(e.result) + ", \"repeated\": "
                   + (e.repeated ? "true" : "false") + ", \"words\": " + json(e.reason) + ", \"peer\": \"" + peer
                   + "\"}";
            break;
        case K::link_refused:
            line = "{\"event\": \"link-refused\", \"source\": " + std::to_string(e.source) + "}";
            break;
        }
        std::printf("%s\n", line.c_str());
        std::fflush(stdout);
    });

    ttapi::link::Words why;
    ttapi::link::UdpLink udp(node);
    if (!node.start(why) || !udp.open(endpoint, why)) {
        std::fprintf(stderr, "onboard_node: %s\n", why.c_str());
        return 1;
    }
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    std::printf("{\"event\": \"ready\", \"port\": %u}\n", static_cast<unsigned>(udp.local_port()));
    std::fflush(stdout);

    bool sent_started = false;
    bool sent_reported = false;
    unsigned grant_max = 0;  // the upload's highest rate grant from its receiver (0: none)
    while (!g_stop.load()) {
        udp.run_once(0.1);
        if (!send_path.empty() && !sent_started) {
            sent_started = true;
            const std::string name = send_name.empty() ? send_path.substr(send_path.rfind('/') + 1) : send_name;
            if (!node.send_file(send_path.c_str(), name, static_cast<std::uint8_t>(send_sys),
                                static_cast<std::uint8_t>(send_comp), false, why)) {
                std::printf("{\"event\": \"sent\", \"ok\": false, \"code\": \"LOCAL\", \"message\": %s}\n",
                            json(why.view()).c_str());
                std::fflush(stdout);
                sent_reported = true;
            }
        }
        if (sent_started && !sent_reported) {
            node.each_sender([&](const ttapi::link::FileSender& s) {
                if (s.request_id() == 0 && !s.done()) {
                    grant_max = std::max<unsigned>(grant_max, s.grant());
                }
                if (s.request_id() == 0 && s.done() && !sent_reported) {
                    const ttapi::link::TransferResult& r = s.result();
                    const ttapi::link::TransferStats& st = s.stats();
                    std::printf("{\"event\": \"sent\", \"ok\": %s, \"code\": \"%s\", \"message\": %s, \"seconds\": %.3f, "
                                "\"bytes_sent\": %llu, \"retransmitted\": %llu, \"resumed_bytes\": %llu, "
                                "\"deflated_bytes\": %llu, \"deflate_fallback\": %s, \"grant_max\": %u, "
                                "\"data_seconds\": %.3f, \"wire_bytes\": %llu}\n",
                                r.ok ? "true" : "false", r.code, json(r.message.view()).c_str(), r.seconds,
                                static_cast<unsigned long long>(st.bytes_sent),
                                static_cast<unsigned long long>(st.bytes_retransmitted),
                                static_cast<unsigned long long>(st.resumed_bytes),
                                static_cast<unsigned long long>(r.deflated_bytes),
                                r.fell_back ? json(r.fallback.view()).c_str() : "null", grant_max,
                                st.data_started >= 0 ? st.finished - st.data_started : 0.0,
                                static_cast<unsigned long long>(100 * st.narrow_frames + 267 * st.wide_frames));
                    std::fflush(stdout);
                    sent_reported = true;
                }
            });
        }
    }
    node.close();
    const ttapi::link::NodeStats& s = node.stats();
    const ttapi::link::CommandStats& c = node.command_stats();
    std::printf("{\"event\": \"stats\", \"packets_in\": %llu, \"packets_out\": %llu, \"frames_in\": %llu, "
                "\"bad_frames\": %llu, \"refused_signature\": %llu, \"ignored\": %llu, \"echoes\": %llu, "
                "\"executed\": %llu, \"duplicates\": %llu, \"plugin_executed\": %llu, \"plugin_flown\": %llu, "
                "\"setpoints_flown\": %llu, \"setpoints_refused\": %llu, \"setpoints_repeated\": %llu, "
                "\"setpoints_forgotten\": %llu, "
                "\"files_received\": %llu, "
                "\"files_refused\": %llu, \"files_served\": %llu, \"oversize\": %llu, \"requests_forgotten\": %llu, "
                "\"sources_forgotten\": %llu, \"commands_forgotten\": %llu, \"dropped_control\": %llu, "
                "\"vr_confirmed\": %llu, \"plugin_vr_messages\": %llu, \"plugin_vr_changes\": %llu, \"unknown\": %llu}\n",
                static_cast<unsigned long long>(s.packets_in), static_cast<unsigned long long>(s.packets_out),
                static_cast<unsigned long long>(s.frames_in), static_cast<unsigned long long>(s.bad_frames),
                static_cast<unsigned long long>(s.refused_signature), static_cast<unsigned long long>(s.ignored),
                static_cast<unsigned long long>(s.echoes), static_cast<unsigned long long>(c.executed),
                static_cast<unsigned long long>(c.duplicates), static_cast<unsigned long long>(plugin.executed),
                static_cast<unsigned long long>(plugin.flown),
                static_cast<unsigned long long>(node.setpoint_stats().flown),
                static_cast<unsigned long long>(node.setpoint_stats().refused),
                static_cast<unsigned long long>(node.setpoint_stats().repeats),
                static_cast<unsigned long long>(node.setpoint_stats().forgotten),
                static_cast<unsigned long long>(s.files_received), static_cast<unsigned long long>(s.files_refused),
                static_cast<unsigned long long>(s.files_served), static_cast<unsigned long long>(udp.oversize()),
                static_cast<unsigned long long>(s.requests_forgotten),
                static_cast<unsigned long long>(s.sources_forgotten), static_cast<unsigned long long>(c.forgotten),
                static_cast<unsigned long long>(node.scheduler_stats().dropped_control),
                static_cast<unsigned long long>(s.vr_confirmed), static_cast<unsigned long long>(plugin.vr_messages),
                static_cast<unsigned long long>(plugin.vr_changes), static_cast<unsigned long long>(s.unknown));
    std::fflush(stdout);
    return 0;
}
