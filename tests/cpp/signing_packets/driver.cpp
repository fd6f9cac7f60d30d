// Test driver of the generated C++ runtime's signing (signing.hpp) and packet receiver
// (packets.hpp), built against `ttctl gen dialects/ttapi.xml --lang cpp` (include path: the
// generated cpp/ folder):
//
//   g++ -std=c++17 -O2 -I <out>/cpp tests/cpp/signing_packets/driver.cpp -o driver
//
// Every mode reads hex lines on stdin (one item per line, blank lines are empty items) and
// writes lines on stdout; exit status 0 unless the command line or the input is malformed.
// <key> is the 32-byte secret key as 64 hex digits.
//
//   driver sign <key> <link_id> [<timestamp>]
//       each line an unsigned frame -> the signed frame, hex. Timestamps (10 us units since
//       2015-01-01 UTC) are max(now, last + 1) from <timestamp> (default: the clock), so with
//       <timestamp> T the frames get T+1, T+2, ...
//   driver verify <key> [--allow-unsigned] [--timestamp <ts>]
//       each line a whole frame -> "ok" or "refused:<reason>", one Signing for all lines (so a
//       repeated frame is refused as replayed). <reason>: unsigned, bad_signature, replayed,
//       too_old, or bad_frame (not a valid frame of the dialect: CRC, length, msgid).
//       <ts>: our starting timestamp (default: the clock).
//   driver sha256
//       each line some bytes -> their SHA-256, hex.
//   driver parse <key|-> [--allow-unsigned] [--timestamp <ts>]
//       each line a chunk for one Parser (with a Signing unless <key> is -) -> "F <frame hex>"
//       per frame; at the end "S <messages> <bad_crc> <unknown> <bad_flags> <bad_signature>
//       <skipped_bytes>".
//   driver packets <key|-> [--allow-unsigned] [--timestamp <ts>]
//       each line a packet for one PacketReceiver, or "FLUSH" -> "F <frame hex>" per frame it
//       delivers, then "E"; "RESET" (a new case: a new receiver and Signing) and the end of the
//       input -> "S <packets> <frames> <bad_frames> <carries_dropped> <rescans> <unknown>" of the case.
//   driver noalloc <key>
//       signs, verifies, parses and receives packets with operator new counting: "ok <n>" if
//       nothing allocated (not in -DTTCTL_TEST_SANITIZE builds: prints "ok skipped").
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "ttapi/ttapi.hpp"

namespace mav = ttapi;

#ifndef TTCTL_TEST_SANITIZE
static std::size_t g_allocations = 0;

void* operator new(std::size_t n)
{
    ++g_allocations;
    if (void* p = std::malloc(n != 0 ? n : 1)) {
        return p;
    }
    throw std::bad_alloc();
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#endif

namespace {

using Bytes = std::vector<std::uint8_t>;

bool unhex(const std::string& s, Bytes& out)
{
    out.clear();
    std::string t;
    for (char c : s) {
        if (c != '\r' && c != ' ') {
            t += c;
        }
    }
    if (t.size() % 2 != 0) {
        return false;
    }
    for (std::size_t i = 0; i < t.size(); i += 2) {
        unsigned v = 0;
        for (int k = 0; k < 2; ++k) {
            const char c = t[i + static_cast<std::size_t>(k)];
            v <<= 4;
            if (c >= '0' && c <= '9') {
                v |= static_cast<unsigned>(c - '0');
            } else if (c >= 'a' && c <= 'f') {
                v |= static_cast<unsigned>(c - 'a' + 10);
            } else if (c >= 'A' && c <= 'F') {
                v |= static_cast<unsigned>(c - 'A' + 10);
            } else {
                return false;
            }
        }
        out.push_back(static_cast<std::uint8_t>(v));
    }
    return true;
}

std::string hex(const std::uint8_t* p, std::size_t n)
{
    static const char digits[] = "0123456789abcdef";
    std::string s;
    s.reserve(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        s += digits[p[i] >> 4];
        s += digits[p[i] & 15];
    }
    return s;
}

int usage()
{
    std::fprintf(stderr, "usage: driver sign|verify|sha256|parse|packets|noalloc ... (see the source)\n");
    return 2;
}

bool read_key(const char* arg, Bytes& key)
{
    return unhex(arg, key) && key.size() == mav::Signing::KEY_LENGTH;
}

// Options after the key: --allow-unsigned, --timestamp <ts>.
bool options(int argc, char** argv, int from, bool& allow_unsigned, std::uint64_t& ts)
{
    for (int i = from; i < argc; ++i) {
        if (std::strcmp(argv[i], "--allow-unsigned") == 0) {
            allow_unsigned = true;
        } else if (std::strcmp(argv[i], "--timestamp") == 0 && i + 1 < argc) {
            ts = std::strtoull(argv[++i], nullptr, 10);
        } else {
            return false;
        }
    }
    return true;
}

int bad_input(const std::string& line)
{
    std::fprintf(stderr, "not hex: %s\n", line.c_str());
    return 2;
}

int cmd_sign(int argc, char** argv)
{
    Bytes key;
    if (argc < 4 || argc > 5 || !read_key(argv[2], key)) {
        return usage();
    }
    const auto link = static_cast<std::uint8_t>(std::strtoul(argv[3], nullptr, 10));
    const std::uint64_t start = argc == 5 ? std::strtoull(argv[4], nullptr, 10) : 0;
    mav::Signing signing(key.data(), link, false, start);
    std::string line;
    Bytes frame;
    while (std::getline(std::cin, line)) {
        if (!unhex(line, frame)) {
            return bad_input(line);
        }
        const std::size_t n = frame.size();
        frame.resize(n + mav::SIGNATURE_LENGTH);
        const std::size_t m = signing.sign(frame.data(), n, frame.size(), argc == 5 ? 0 : mav::Signing::now());
        std::printf("%s\n", m == 0 ? "error" : hex(frame.data(), m).c_str());
    }
    return 0;
}

int cmd_verify(int argc, char** argv)
{
    Bytes key;
    bool allow = false;
    std::uint64_t ts = 0;
    if (argc < 3 || !read_key(argv[2], key) || !options(argc, argv, 3, allow, ts)) {
        return usage();
    }
    mav::Signing signing(key.data(), 0, allow, ts);
    std::string line;
    Bytes frame;
    while (std::getline(std::cin, line)) {
        if (!unhex(line, frame)) {
            return bad_input(line);
        }
        mav::Frame f;
        mav::SignatureCheck why = mav::SignatureCheck::ok;
        const mav::DecodeStatus st = mav::decode_frame(frame.data(), frame.size(), f, &signing, &why);
        if (st == mav::DecodeStatus::ok) {
            std::printf("ok\n");
        } else if (st == mav::DecodeStatus::bad_signature) {
            std::printf("refused:%s\n", mav::to_string(why));
        } else {
            std::printf("refused:bad_frame\n");
        }
    }
    return 0;
}

int cmd_sha256()
{
    std::string line;
    Bytes data;
    while (std::getline(std::cin, line)) {
        if (!unhex(line, data)) {
            return bad_input(line);
        }
        std::uint8_t d[32];
        mav::sha256(data.data(), data.size(), d);
        // and incrementally, in uneven pieces
        mav::Sha256 h;
        std::size_t at = 0;
        for (std::size_t step = 1; at < data.size(); step = step * 3 + 1) {
            const std::size_t k = std::min(step, data.size() - at);
            h.update(data.data() + at, k);
            at += k;
        }
        std::uint8_t e[32];
        h.final(e);
        std::printf("%s%s\n", hex(d, 32).c_str(), std::memcmp(d, e, 32) == 0 ? "" : " incremental-differs");
    }
    return 0;
}

struct Printer {
    void operator()(const mav::Frame& f) const { std::printf("F %s\n", hex(f.bytes, f.size).c_str()); }
};

int cmd_parse(int argc, char** argv)
{
    Bytes key;
    bool allow = false;
    std::uint64_t ts = 0;
    const bool keyed = argc >= 3 && std::strcmp(argv[2], "-") != 0;
    if (argc < 3 || (keyed && !read_key(argv[2], key)) || !options(argc, argv, 3, allow, ts)) {
        return usage();
    }
    key.resize(mav::Signing::KEY_LENGTH);
    mav::Signing signing(key.data(), 0, allow, ts);
    mav::Parser parser(keyed ? &signing : nullptr);
    std::string line;
    Bytes chunk;
    while (std::getline(std::cin, line)) {
        if (!unhex(line, chunk)) {
            return bad_input(line);
        }
        parser.feed(chunk.data(), chunk.size(), Printer{});
    }
    parser.flush(Printer{});
    const mav::ParserStats& s = parser.stats();
    std::printf("S %llu %llu %llu %llu %llu %llu\n", static_cast<unsigned long long>(s.messages),
                static_cast<unsigned long long>(s.bad_crc), static_cast<unsigned long long>(s.unknown),
                static_cast<unsigned long long>(s.bad_flags), static_cast<unsigned long long>(s.bad_signature),
                static_cast<unsigned long long>(s.skipped_bytes));
    return 0;
}

int cmd_packets(int argc, char** argv)
{
    Bytes key;
    bool allow = false;
    std::uint64_t ts = 0;
    const bool keyed = argc >= 3 && std::strcmp(argv[2], "-") != 0;
    if (argc < 3 || (keyed && !read_key(argv[2], key)) || !options(argc, argv, 3, allow, ts)) {
        return usage();
    }
    key.resize(mav::Signing::KEY_LENGTH);
    mav::Signing signing(key.data(), 0, allow, ts);
    mav::PacketReceiver rx(keyed ? &signing : nullptr);
    auto stats = [&rx]() {
        const mav::ReceiverStats& s = rx.stats();
        std::printf("S %llu %llu %llu %llu %llu %llu\n", static_cast<unsigned long long>(s.packets),
                    static_cast<unsigned long long>(s.frames), static_cast<unsigned long long>(s.bad_frames),
                    static_cast<unsigned long long>(s.carries_dropped), static_cast<unsigned long long>(s.rescans),
                    static_cast<unsigned long long>(s.unknown));
    };
    std::string line;
    Bytes packet;
    while (std::getline(std::cin, line)) {
        if (line == "RESET") {
            stats();
            signing = mav::Signing(key.data(), 0, allow, ts);
            rx = mav::PacketReceiver(keyed ? &signing : nullptr);
            continue;
        }
        if (line == "FLUSH") {
            rx.flush(Printer{});
        } else {
            if (!unhex(line, packet)) {
                return bad_input(line);
            }
            rx.feed(packet.data(), packet.size(), Printer{});
        }
        std::printf("E\n");
    }
    stats();
    return 0;
}

int cmd_noalloc(int argc, char** argv)
{
    Bytes key;
    if (argc != 3 || !read_key(argv[2], key)) {
        return usage();
    }
#ifdef TTCTL_TEST_SANITIZE
    std::printf("ok skipped\n");
    return 0;
#else
    static std::uint8_t stream[64 * mav::MAX_FRAME];
    std::size_t n = 0;
    mav::Signing tx(key.data(), 7, false, 1000);
    mav::Encoder enc(1, 240, &tx);
    const std::size_t before = g_allocations;
    bool signed_ok = true;
    mav::TtFileDataWide wide{};
    wide.offset = 5;
    for (int i = 0; i < 20; ++i) {
        wide.data[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i + 1);
        n += enc.encode(wide, stream + n, sizeof stream - n);
        n += enc.encode(mav::Heartbeat{}, stream + n, sizeof stream - n);
        std::uint8_t buf[mav::MAX_FRAME];
        const std::size_t m = mav::Heartbeat{}.encode(buf, sizeof buf, 3, 1, 240);
        signed_ok = signed_ok && tx.sign(buf, m, sizeof buf, mav::Signing::now()) == m + mav::SIGNATURE_LENGTH;
    }
    mav::Signing rx_signing(key.data(), 0, false, 1000);
    mav::Parser parser(&rx_signing);
    std::size_t frames = 0;
    auto count = [&frames](const mav::Frame&) { ++frames; };
    parser.feed(stream, n, count);
    parser.flush(count);
    mav::Signing rx2(key.data(), 0, false, 1000);
    mav::PacketReceiver receiver(&rx2);
    mav::Packetizer packetizer(100);
    auto to_receiver = [&](const std::uint8_t* p, std::size_t k) { receiver.feed(p, k, count); };
    for (std::size_t at = 0; at < n;) {
        const std::size_t size =
            mav::HEADER_LENGTH + stream[at + 1] + mav::CHECKSUM_LENGTH + mav::SIGNATURE_LENGTH;
        packetizer.add(stream + at, size, to_receiver);
        at += size;
    }
    packetizer.flush(to_receiver);
    receiver.flush(count);
    const std::size_t used = g_allocations - before;
    if (used != 0 || frames != 80 || !signed_ok || parser.stats().bad_signature != 0
        || receiver.stats().bad_frames != 0) {
        std::printf("FAIL allocations=%zu frames=%zu\n", used, frames);
        return 1;
    }
    std::printf("ok %zu\n", frames);
    return 0;
#endif
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        return usage();
    }
    const std::string mode = argv[1];
    if (mode == "sign") {
        return cmd_sign(argc, argv);
    }
    if (mode == "verify") {
        return cmd_verify(argc, argv);
    }
    if (mode == "sha256") {
        return cmd_sha256();
    }
    if (mode == "parse") {
        return cmd_parse(argc, argv);
    }
    if (mode == "packets") {
        return cmd_packets(argc, argv);
    }
    if (mode == "noalloc") {
        return cmd_noalloc(argc, argv);
    }
    return usage();
}
