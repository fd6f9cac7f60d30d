// A stand-in for DJI's Payload SDK MOP channel (dji_mop_channel.h, the real header, vendored in
// tests/vendor/dji/psdk-3.13.1/), written from what the header and DJI's sample
// (test_mop_channel.c) say about the calls, so that MopLink runs end to end in tests: the
// pipeline is TCP on 127.0.0.1.
//  - Init: nothing to set up;
//  - Create: a handle (RELIABLE or UNRELIABLE; both are TCP here);
//  - Bind: the handle listens on 127.0.0.1:$TTCTL_FAKE_MOP_PORT (the channel id is not used);
//  - Accept: blocks in accept(); the new connection is a new handle;
//  - SendData / RecvData: send() / recv() of up to len bytes, realLen what moved; a closed peer
//    is DJI_ERROR_MOP_CHANNEL_MODULE_CODE_CONNECTION_CLOSE (as DJI's sample expects of RecvData);
//  - Close: shutdown() (blocked calls on the handle return); Destroy: close() and free.
// Test knobs (environment):
//   TTCTL_FAKE_MOP_PORT PORT          where Bind listens (required)
//   TTCTL_FAKE_MOP_SHORT 1            every SendData takes at most 7 bytes (realLen < len)
//   TTCTL_FAKE_MOP_FAIL 1             every call answers DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR
//   TTCTL_FAKE_MOP_STALL BYTES        once BYTES have been sent, the next SendData blocks until the
//                                     connection is closed (DjiMopChannel_Close): a send timeout
//   TTCTL_FAKE_MOP_CLOSE_AFTER A,B..  when the bytes moved (in + out, all connections) pass A,
//                                     then B, ..., the connection is closed under the caller (its
//                                     next call answers CONNECTION_CLOSE)
#include "fake_mop.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <thread>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

#include "dji_mop_channel.h"

namespace {

struct Handle {
    int fd = -1;
    std::atomic<bool> closed{false};
};

struct State {
    std::mutex m;
    FakeMopStats stats{};
    std::vector<std::uint64_t> close_after;  // thresholds not yet reached
    std::uint64_t moved = 0;
    bool fail = false;
    bool short_sends = false;
    int port = 0;
    std::uint64_t stall_at = 0;  // 0: never
    bool stalled = false;

    State()
    {
        const char* fail_env = std::getenv("TTCTL_FAKE_MOP_FAIL");
        fail = fail_env != nullptr && std::string(fail_env) == "1";
        const char* short_env = std::getenv("TTCTL_FAKE_MOP_SHORT");
        short_sends = short_env != nullptr && std::string(short_env) == "1";
        const char* port_env = std::getenv("TTCTL_FAKE_MOP_PORT");
        port = port_env != nullptr ? std::atoi(port_env) : 0;
        const char* stall = std::getenv("TTCTL_FAKE_MOP_STALL");
        stall_at = stall != nullptr ? std::strtoull(stall, nullptr, 10) : 0;
        const char* after = std::getenv("TTCTL_FAKE_MOP_CLOSE_AFTER");
        if (after != nullptr) {
            std::string s = after;
            std::size_t at = 0;
            while (at < s.size()) {
                std::size_t comma = s.find(',', at);
                if (comma == std::string::npos) {
                    comma = s.size();
                }
                close_after.push_back(std::strtoull(s.substr(at, comma - at).c_str(), nullptr, 10));
                at = comma + 1;
            }
        }
    }
};

State& state()
{
    static State s;
    return s;
}

// A failed call, counted.
T_DjiReturnCode failed(T_DjiReturnCode code)
{
    std::lock_guard<std::mutex> lock(state().m);
    ++state().stats.failed_calls;
    return code;
}

bool fail_all() { return state().fail; }

// Bytes moved on `h`: past the next threshold, the connection is shut under the caller.
void moved(Handle* h, std::uint64_t n, bool in)
{
    State& s = state();
    std::lock_guard<std::mutex> lock(s.m);
    (in ? s.stats.bytes_in : s.stats.bytes_out) += n;
    s.moved += n;
    if (!s.close_after.empty() && s.moved >= s.close_after.front()) {
        s.close_after.erase(s.close_after.begin());
        ++s.stats.forced_closes;
        ::shutdown(h->fd, SHUT_RDWR);
    }
}

}  // namespace

FakeMopStats fake_mop_stats()
{
    std::lock_guard<std::mutex> lock(state().m);
    return state().stats;
}

extern "C" {

T_DjiReturnCode DjiMopChannel_Init(void)
{
    if (fail_all()) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR);
    }
    return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
}

T_DjiReturnCode DjiMopChannel_Create(T_DjiMopChannelHandle* channelHandle, E_DjiMopChannelTransType transType)
{
    if (fail_all()) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR);
    }
    if (channelHandle == nullptr
        || (transType != DJI_MOP_CHANNEL_TRANS_RELIABLE && transType != DJI_MOP_CHANNEL_TRANS_UNRELIABLE)) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_INVALID_PARAMETER);
    }
    *channelHandle = new Handle;
    std::lock_guard<std::mutex> lock(state().m);
    ++state().stats.live_handles;
    return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
}

T_DjiReturnCode DjiMopChannel_Destroy(T_DjiMopChannelHandle channelHandle)
{
    if (fail_all()) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR);
    }
    auto* h = static_cast<Handle*>(channelHandle);
    if (h == nullptr) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_INVALID_PARAMETER);
    }
    if (h->fd >= 0) {
        ::close(h->fd);
    }
    delete h;
    std::lock_guard<std::mutex> lock(state().m);
    --state().stats.live_handles;
    return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
}

T_DjiReturnCode DjiMopChannel_Bind(T_DjiMopChannelHandle channelHandle, uint16_t /*channelId*/)
{
    if (fail_all()) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR);
    }
    auto* h = static_cast<Handle*>(channelHandle);
    if (h == nullptr || h->fd >= 0 || state().port <= 0) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_INVALID_PARAMETER);
    }
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    const int one = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(state().port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(fd, 4) != 0) {
        if (fd >= 0) {
            ::close(fd);
        }
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR);
    }
    h->fd = fd;
    return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
}

T_DjiReturnCode DjiMopChannel_Accept(T_DjiMopChannelHandle channelHandle, T_DjiMopChannelHandle* outChannelHandle)
{
    if (fail_all()) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR);
    }
    auto* h = static_cast<Handle*>(channelHandle);
    if (h == nullptr || outChannelHandle == nullptr || h->fd < 0) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_INVALID_PARAMETER);
    }
    int fd = -1;
    do {
        fd = ::accept(h->fd, nullptr, nullptr);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) {
        return failed(DJI_ERROR_MOP_CHANNEL_MODULE_CODE_CONNECTION_CLOSE);  // closed under us (Close)
    }
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    auto* out = new Handle;
    out->fd = fd;
    *outChannelHandle = out;
    std::lock_guard<std::mutex> lock(state().m);
    ++state().stats.accepts;
    ++state().stats.live_handles;
    return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
}

T_DjiReturnCode DjiMopChannel_Connect(T_DjiMopChannelHandle /*channelHandle*/, E_DjiChannelAddress /*channelAddress*/,
                                      uint16_t /*channelId*/)
{
    return failed(DJI_ERROR_SYSTEM_MODULE_CODE_NONSUPPORT);  // the onboard end only accepts here
}

T_DjiReturnCode DjiMopChannel_Close(T_DjiMopChannelHandle channelHandle)
{
    if (fail_all()) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR);
    }
    auto* h = static_cast<Handle*>(channelHandle);
    if (h == nullptr) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_INVALID_PARAMETER);
    }
    if (h->fd >= 0) {
        ::shutdown(h->fd, SHUT_RDWR);  // a blocked accept() or recv() returns
    }
    h->closed = true;
    return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
}

T_DjiReturnCode DjiMopChannel_SendData(T_DjiMopChannelHandle channelHandle, uint8_t* data, uint32_t len,
                                       uint32_t* realLen)
{
    if (realLen != nullptr) {
        *realLen = 0;
    }
    if (fail_all()) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR);
    }
    auto* h = static_cast<Handle*>(channelHandle);
    if (h == nullptr || data == nullptr || realLen == nullptr || h->fd < 0) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_INVALID_PARAMETER);
    }
    if (h->closed) {
        return failed(DJI_ERROR_MOP_CHANNEL_MODULE_CODE_CONNECTION_CLOSE);
    }
    bool stall = false;
    {
        std::lock_guard<std::mutex> lock(state().m);
        State& s = state();
        stall = s.stall_at != 0 && !s.stalled && s.stats.bytes_out >= s.stall_at;
        if (stall) {
            s.stalled = true;
            ++s.stats.stalls;
        }
    }
    while (stall && !h->closed.load()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));  // as if the link hung
    }
    if (h->closed.load()) {
        return failed(DJI_ERROR_MOP_CHANNEL_MODULE_CODE_CONNECTION_CLOSE);
    }
    std::size_t n = len;
    if (state().short_sends && n > 7) {
        std::lock_guard<std::mutex> lock(state().m);
        ++state().stats.short_sends;
        n = 7;
    }
    ssize_t r = -1;
    do {
        r = ::send(h->fd, data, n, MSG_NOSIGNAL);
    } while (r < 0 && errno == EINTR);
    if (r < 0) {
        return failed(DJI_ERROR_MOP_CHANNEL_MODULE_CODE_CONNECTION_CLOSE);
    }
    *realLen = static_cast<uint32_t>(r);
    moved(h, static_cast<std::uint64_t>(r), false);
    return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
}

T_DjiReturnCode DjiMopChannel_RecvData(T_DjiMopChannelHandle channelHandle, uint8_t* data, uint32_t len,
                                       uint32_t* realLen)
{
    if (realLen != nullptr) {
        *realLen = 0;
    }
    if (fail_all()) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR);
    }
    auto* h = static_cast<Handle*>(channelHandle);
    if (h == nullptr || data == nullptr || realLen == nullptr || h->fd < 0 || len == 0) {
        return failed(DJI_ERROR_SYSTEM_MODULE_CODE_INVALID_PARAMETER);
    }
    ssize_t r = -1;
    do {
        r = ::recv(h->fd, data, len, 0);
    } while (r < 0 && errno == EINTR);
    if (r <= 0) {
        return failed(DJI_ERROR_MOP_CHANNEL_MODULE_CODE_CONNECTION_CLOSE);  // the peer went (or Close)
    }
    *realLen = static_cast<uint32_t>(r);
    moved(h, static_cast<std::uint64_t>(r), true);
    return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
}

}  // extern "C"
