// Tests of the generated C++ runtime of ttapi (Parser, Dispatcher, Packetizer, Encoder, message
// structs), driven by tests/test_gen_cpp.py.
//
//   runtime_test selftest        internal checks; prints "ok <checks>" or the failures (exit 1)
//   runtime_test parse           stdin: one hex chunk per line, fed in order to one Parser
//                                (flushed at the end); stdout: "F <hex>" per frame, then
//                                "S <messages> <bad_crc> <unknown> <bad_flags> <skipped> <pending>"
//   runtime_test packetize MTU   stdin: one hex frame per line, added to a Packetizer (flushed at
//                                the end); stdout: "P <hex>" per packet
//
// Built with -DTTCTL_TEST_SANITIZE for the sanitizer build: then operator new is not replaced.
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "ttapi/ttapi.hpp"

// --- counting allocations -------------------------------------------------------------------

static std::atomic<long> g_allocations{0};

#ifndef TTCTL_TEST_SANITIZE
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"  // malloc/free behind replaced new/delete
#endif

void* operator new(std::size_t n)
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(n == 0 ? 1 : n)) {
        return p;
    }
    throw std::bad_alloc();
}

void* operator new[](std::size_t n)
{
    return operator new(n);
}

void* operator new(std::size_t n, const std::nothrow_t&) noexcept
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(n == 0 ? 1 : n);
}

void* operator new[](std::size_t n, const std::nothrow_t& tag) noexcept
{
    return operator new(n, tag);
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#endif

namespace {

namespace mav = ttapi;

int g_checks = 0;
int g_failures = 0;

#define CHECK(cond)                                                                 \
    do {                                                                            \
        ++g_checks;                                                                 \
        if (!(cond)) {                                                              \
            ++g_failures;                                                           \
            std::fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
        }                                                                           \
    } while (0)

std::string to_hex(const std::uint8_t* p, std::size_t n)
{
    static const char HEX[] = "0123456789abcdef";
    std::string s;
    s.reserve(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        s += HEX[p[i] >> 4];
        s += HEX[p[i] & 0xF];
    }
    return s;
}

bool from_hex(const std::string& s, std::vector<std::uint8_t>& out)
{
    auto nibble = [](char c) -> int {
        if (c >= '0' && c <= '9') {
            return c - '0';
        }
        if (c >= 'a' && c <= 'f') {
            return c - 'a' + 10;
        }
        return -1;
    };
    out.clear();
    if (s.size() % 2 != 0) {
        return false;
    }
    for (std::size_t i = 0; i < s.size(); i += 2) {
        const int hi = nibble(s[i]);
        const int lo = nibble(s[i + 1]);
        if (hi < 0 || lo < 0) {
            return false;
        }
        out.push_back(static_cast<std::uint8_t>(hi << 4 | lo));
    }
    return true;
}

// --- modes driven by the Python test --------------------------------------------------------

int run_parse()
{
    mav::Parser parser;
    std::string line;
    std::vector<std::uint8_t> chunk;
    std::string out;
    auto emit = [&out](const mav::Frame& f) {
        out += "F ";
        out += to_hex(f.bytes, f.size);
        out += '\n';
    };
    while (std::getline(std::cin, line)) {
        if (!from_hex(line, chunk)) {
            std::fprintf(stderr, "bad hex line\n");
            return 2;
        }
        parser.feed(chunk.data(), chunk.size(), emit);
    }
    parser.flush(emit);
    const mav::ParserStats& s = parser.stats();
    std::fputs(out.c_str(), stdout);
    std::printf("S %llu %llu %llu %llu %llu %zu\n", static_cast<unsigned long long>(s.messages),
                static_cast<unsigned long long>(s.bad_crc), static_cast<unsigned long long>(s.unknown),
                static_cast<unsigned long long>(s.bad_flags), static_cast<unsigned long long>(s.skipped_bytes),
                parser.pending());
    return 0;
}

int run_packetize(std::size_t mtu)
{
    mav::Packetizer packetizer(mtu);
    std::string line;
    std::vector<std::uint8_t> frame;
    auto emit = [](const std::uint8_t* p, std::size_t n) { std::printf("P %s\n", to_hex(p, n).c_str()); };
    while (std::getline(std::cin, line)) {
        if (!from_hex(line, frame)) {
            std::fprintf(stderr, "bad hex line\n");
            return 2;
        }
        packetizer.add(frame.data(), frame.size(), emit);
    }
    packetizer.flush(emit);
    return 0;
}

// --- selftest (common.xml messages only: ttapi's own may still change) -----------------------

mav::ParamSet sample_param_set()
{
    mav::ParamSet c;
    c.target_system = 1;
    c.target_component = 240;
    std::memcpy(c.param_id.data(), "RATE_HZ", 7);
    c.param_value = -2.25f;
    c.param_type = 0;  // the last field on the wire: a zero tail to truncate
    return c;
}

bool same(const mav::ParamSet& a, const mav::ParamSet& b)
{
    return a.target_system == b.target_system && a.target_component == b.target_component && a.param_id == b.param_id
           && a.param_value == b.param_value && a.param_type == b.param_type;
}

void test_constants_and_tables()
{
    static_assert(mav::Heartbeat::MSG_ID == 0);
    static_assert(mav::Heartbeat::PAYLOAD_LENGTH == 9 && mav::Heartbeat::CRC_EXTRA == 50);
    static_assert(mav::ParamSet::PAYLOAD_LENGTH == 23 && mav::ParamSet::CRC_EXTRA == 168);
    static_assert(mav::MAX_FRAME == 280);
    CHECK(mav::message_info(std::uint32_t{0}) != nullptr);
    CHECK(mav::message_info(std::uint32_t{0xFFFFFF}) == nullptr);
    static_assert(std::is_same_v<std::underlying_type_t<mav::MavModeFlag>, std::uint8_t>);
    static_assert(std::is_same_v<std::underlying_type_t<mav::MavSysStatusSensor>, std::uint32_t>);
    static_assert(std::is_same_v<std::underlying_type_t<mav::MavCmd>, std::uint16_t>);
    static_assert((mav::MavModeFlag::MAV_MODE_FLAG_SAFETY_ARMED | mav::MavModeFlag::MAV_MODE_FLAG_CUSTOM_MODE_ENABLED)
                  == static_cast<mav::MavModeFlag>(129));
    static_assert(mav::has_flag(std::uint8_t{129}, mav::MavModeFlag::MAV_MODE_FLAG_SAFETY_ARMED));
    static_assert(mav::crc16_accumulate(0x00, 0xFFFF) == 0x0F87);
    for (std::size_t i = 1; i < mav::MESSAGE_INFO.size(); ++i) {
        CHECK(mav::MESSAGE_INFO[i - 1].msgid < mav::MESSAGE_INFO[i].msgid);
    }
    for (const mav::MessageInfo& info : mav::MESSAGE_INFO) {
        CHECK(mav::message_info(info.msgid) == &info);
        CHECK(mav::message_info(std::string_view(info.name)) == &info);
    }
    const mav::ParamSet defaults;
    CHECK(defaults.param_value == 0.0f && defaults.param_id[15] == '\0');
    CHECK(mav::Heartbeat{}.mavlink_version == mav::DIALECT_VERSION);
}

void test_encode_decode()
{
    std::uint8_t buf[mav::MAX_FRAME];
    const mav::ParamSet c = sample_param_set();
    const std::size_t n = c.encode(buf, sizeof buf, 7, 255, 190);
    CHECK(n == 12 + 4 + 2 + 7);  // param_id's zero tail and param_type truncated
    mav::Frame f;
    CHECK(mav::decode_frame(buf, n, f) == mav::DecodeStatus::ok);
    CHECK(f.msgid == mav::ParamSet::MSG_ID && f.seq == 7 && f.sysid == 255 && f.compid == 190 && f.size == n);
    CHECK(std::strcmp(f.name(), "PARAM_SET") == 0 && !f.is_signed() && f.payload_length == n - 12);
    mav::ParamSet back;
    CHECK(f.decode(back) && same(back, c));
    mav::Heartbeat hb;
    CHECK(!f.decode(hb));
    // every wrong length and a flipped bit in each byte are refused
    for (std::size_t k = 0; k < n; ++k) {
        mav::Frame g;
        CHECK(mav::decode_frame(buf, k, g) != mav::DecodeStatus::ok);
        buf[k] ^= 0x10;
        CHECK(mav::decode_frame(buf, n, g) != mav::DecodeStatus::ok);
        buf[k] ^= 0x10;
    }
    // too small a buffer: 0; exactly the truncated size: works (through the stack copy)
    std::uint8_t small[mav::MAX_FRAME];
    CHECK(c.encode(small, n - 1) == 0);
    CHECK(c.encode(small, n, 7, 255, 190) == n && std::memcmp(small, buf, n) == 0);
    // all-zero payload: one byte kept
    CHECK(mav::Heartbeat{}.encode(small, sizeof small) == 12 + 9);  // mavlink_version is not zero
    CHECK(mav::ParamSet{}.encode(small, sizeof small) == 12 + 1);
    // unpack_payload: truncated is zero-extended, longer is clamped
    std::uint8_t payload[mav::ParamSet::PAYLOAD_LENGTH + 8];
    std::memset(payload, 0xAB, sizeof payload);
    const std::size_t plen = c.pack_payload(payload);
    CHECK(plen == n - 12);
    std::memset(payload + plen, 0xAB, sizeof payload - plen);  // garbage after the truncated payload
    CHECK(same(mav::ParamSet::unpack_payload(payload, plen), c));
    const mav::ParamSet longer = mav::ParamSet::unpack_payload(payload, sizeof payload);
    CHECK(longer.param_type == 0xAB && longer.param_id[15] == '\xAB');
    const mav::ParamSet head = mav::ParamSet::unpack_payload(payload, 5);
    CHECK(head.param_value == c.param_value && head.target_system == 1 && head.target_component == 0);
    CHECK(mav::ParamSet::unpack_payload(nullptr, 0).param_value == 0.0f);
    // little-endian helpers
    std::uint8_t le[8];
    mav::put_le(le, std::uint32_t{0x11223344});
    CHECK(le[0] == 0x44 && le[3] == 0x11);
    double d = 0;
    mav::put_le(le, -2.5);
    mav::get_le(le, d);
    CHECK(d == -2.5);
    mav::SystemTime t;
    t.time_unix_usec = 0x0123456789ABCDEFull;
    CHECK(t.encode(small, sizeof small) > 12 && small[10] == 0xEF && small[17] == 0x01);
    // Encoder numbers its frames
    mav::Encoder enc(1, 240);
    CHECK(enc.encode(c, small, sizeof small) == n && small[4] == 0 && small[5] == 1 && small[6] == 240);
    CHECK(enc.encode(c, small, sizeof small) == n && small[4] == 1);
    CHECK(enc.encode(c, small, 3) == 0 && enc.next_seq() == 2);
    // signed frames: the 13-byte signature is accepted and skipped
    std::uint8_t signed_frame[mav::MAX_FRAME];
    const std::size_t sn = mav::Heartbeat{}.encode(signed_frame, sizeof signed_frame);
    signed_frame[2] = mav::INCOMPAT_SIGNED;
    const std::uint16_t crc = mav::crc16_accumulate(mav::Heartbeat::CRC_EXTRA, mav::crc16(signed_frame + 1, sn - 3));
    signed_frame[sn - 2] = static_cast<std::uint8_t>(crc);
    signed_frame[sn - 1] = static_cast<std::uint8_t>(crc >> 8);
    std::memset(signed_frame + sn, 0x5A, mav::SIGNATURE_LENGTH);
    CHECK(mav::decode_frame(signed_frame, sn, f) == mav::DecodeStatus::truncated);
    CHECK(mav::decode_frame(signed_frame, sn + 13, f) == mav::DecodeStatus::ok && f.is_signed() && f.size == sn + 13);
}

struct Calls {
    int typed_with_frame = 0;
    int typed = 0;
    int raw = 0;
    int unhandled = 0;
    int order[8] = {};
    int n = 0;
    float last_value = 0;
};

void test_dispatcher_and_no_heap()
{
    Calls calls;
    mav::Dispatcher dispatcher;
    dispatcher.on<mav::ParamSet>([&calls](const mav::ParamSet& msg, const mav::Frame& frame) {
        ++calls.typed_with_frame;
        calls.last_value = msg.param_value;
        if (calls.n < 8) {
            calls.order[calls.n++] = 1;
        }
        (void)frame;
    });
    dispatcher.on<mav::ParamSet>([&calls](const mav::ParamSet& msg) {
        ++calls.typed;
        if (calls.n < 8) {
            calls.order[calls.n++] = 2;
        }
        (void)msg;
    });
    dispatcher.on(mav::Heartbeat::MSG_ID, [&calls](const mav::Frame&) { ++calls.raw; });
    dispatcher.on_unhandled([&calls](const mav::Frame&) { ++calls.unhandled; });
    CHECK(dispatcher.handler_count(mav::ParamSet::MSG_ID) == 2);

    mav::Parser parser;
    mav::Packetizer packetizer;
    std::uint8_t stream[4 * mav::MAX_FRAME];
    std::size_t packets_bytes = 0;
    auto count_packet = [&packets_bytes](const std::uint8_t*, std::size_t n) { packets_bytes += n; };

    // the counter itself works
    const long before_sanity = g_allocations.load();
    {
        std::vector<int>* volatile v = new std::vector<int>(100);
        delete v;
    }
#ifndef TTCTL_TEST_SANITIZE
    CHECK(g_allocations.load() > before_sanity);
#else
    (void)before_sanity;
#endif

    const long before = g_allocations.load();
    std::size_t n = 0;
    const mav::ParamSet cmd = sample_param_set();
    n += cmd.encode(stream + n, sizeof stream - n, 1, 255, 190);
    n += mav::Heartbeat{}.encode(stream + n, sizeof stream - n, 2, 1, 1);
    mav::Statustext text;
    text.severity = 6;
    std::memcpy(text.text.data(), "hello", 5);
    n += text.encode(stream + n, sizeof stream - n, 3, 1, 1);
    mav::FileTransferProtocol ftp;  // a 266-byte frame, longer than a packet
    ftp.target_network = 1;
    ftp.payload.fill(0xFD);
    n += ftp.encode(stream + n, sizeof stream - n, 4, 1, 1);
    for (std::size_t i = 0; i < n; ++i) {
        parser.feed(stream + i, 1, dispatcher);  // byte by byte: the buffered path
    }
    parser.feed(stream, n, dispatcher);  // whole: the direct path
    parser.flush(dispatcher);
    std::size_t offset = 0;
    while (offset < n) {
        mav::Frame f;
        std::size_t size = 12;
        while (offset + size <= n && mav::decode_frame(stream + offset, size, f) != mav::DecodeStatus::ok) {
            ++size;
        }
        if (offset + size > n) {
            break;
        }
        mav::FileTransferProtocol back;
        if (f.decode(back)) {
            CHECK(back.target_network == 1 && back.payload[250] == 0xFD);
        }
        packetizer.add(f.bytes, f.size, count_packet);
        offset += size;
    }
    packetizer.flush(count_packet);
    const long during = g_allocations.load() - before;
    CHECK(during == 0);
    if (during != 0) {
        std::fprintf(stderr, "%ld allocation(s) on the encode/decode/parse/dispatch path\n", during);
    }

    CHECK(offset == n && packets_bytes == n);
    CHECK(parser.stats().messages == 8 && parser.stats().bad_crc == 0 && parser.pending() == 0);
    CHECK(calls.typed_with_frame == 2 && calls.typed == 2 && calls.raw == 2 && calls.unhandled == 4);
    CHECK(calls.order[0] == 1 && calls.order[1] == 2 && calls.order[2] == 1 && calls.order[3] == 2);
    CHECK(calls.last_value == -2.25f);
}

void test_parser_flush()
{
    // a stale magic claiming a long frame holds the frames behind it until flush()
    std::uint8_t stream[2 * mav::MAX_FRAME];
    const std::uint8_t stale[] = {0xFD, 200, 0, 0, 0, 1, 1, 0x6E, 0, 0, 0, 0};  // FILE_TRANSFER_PROTOCOL, 200 B
    std::memcpy(stream, stale, sizeof stale);
    std::size_t n = sizeof stale;
    n += mav::Heartbeat{}.encode(stream + n, sizeof stream - n, 9, 1, 1);
    mav::Parser parser;
    int frames = 0;
    auto count = [&frames](const mav::Frame&) { ++frames; };
    CHECK(parser.feed(stream, n, count) == 0 && parser.pending() == n);
    CHECK(parser.flush(count) == 1 && frames == 1 && parser.pending() == 0);
    CHECK(parser.flush(count) == 0);
    CHECK(parser.feed(nullptr, 0, count) == 0);
}

void test_packetizer_edges()
{
    std::vector<std::size_t> sizes;
    auto record = [&sizes](const std::uint8_t*, std::size_t n) { sizes.push_back(n); };
    std::uint8_t frame[600] = {};
    mav::Packetizer p(100);
    CHECK(p.add(frame, 60, record) == 0 && p.pending() == 60);
    CHECK(p.add(frame, 40, record) == 1 && p.pending() == 0);  // full: emitted at once
    CHECK(p.add(frame, 30, record) == 0 && p.add(frame, 80, record) == 1 && p.pending() == 80);
    CHECK(p.add(frame, 220, record) == 3 && p.pending() == 0);  // 80+20 | 100 | 100
    CHECK(p.add(frame, 250, record) == 2 && p.pending() == 50);  // 100 | 100 | 50 kept
    CHECK(p.flush(record) == 1 && p.flush(record) == 0 && p.pending() == 0);
    const std::vector<std::size_t> want = {100, 30, 100, 100, 100, 100, 100, 50};
    CHECK(sizes == want);
    mav::BasicPacketizer<16> tiny(1000);
    CHECK(tiny.mtu() == 16);
    CHECK(mav::Packetizer(0).mtu() == 13);
}

int run_selftest()
{
    test_constants_and_tables();
    test_encode_decode();
    test_dispatcher_and_no_heap();
    test_parser_flush();
    test_packetizer_edges();
    if (g_failures != 0) {
        std::printf("FAILED %d of %d checks\n", g_failures, g_checks);
        return 1;
    }
    std::printf("ok %d\n", g_checks);
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "selftest") {
        return run_selftest();
    }
    if (mode == "parse") {
        return run_parse();
    }
    if (mode == "packetize" && argc > 2) {
        return run_packetize(static_cast<std::size_t>(std::strtoul(argv[2], nullptr, 10)));
    }
    std::fprintf(stderr, "usage: %s selftest | parse | packetize MTU\n", argv[0]);
    return 2;
}
