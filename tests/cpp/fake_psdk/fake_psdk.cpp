// A stand-in for the four functions of DJI's Payload SDK v3 low-speed data channel that PsdkLink
// calls, written from what DJI's header (the real one, tests/vendor/dji/psdk-*/, compiled in
// here) documents about them, so that the generated node runs end to end in tests:
//  - SendData: "Max size of data package sent ... on a physical link of command channel is 128. If
//    the length of data to be sent is greater than 128, data to be sent will be divided into
//    multiple packages" (each a datagram here); within the bandwidth limit a package goes at once;
//    beyond it, it is "stored to buffer of the flow controller and be sent to endpoint after a
//    period (an integer multiple of 1s ...). If the buffer is full, data will be discarded. The
//    capacity of flow controller buffer is 512 bytes";
//  - GetSendDataState: the limit, the bandwidth before and after the flow controller (over the
//    last second), busyState while "data can not be sent to the endpoint directly, instead be
//    sent to buffer of flow controller or discarded";
//  - RegRecvDataCallback: the callback is called "when system receive data", here on a thread of
//    the SDK's own, one datagram (from FAKE_PSDK_LISTEN, where `ttctl link relay --to` sends) a
//    call; its time on that thread is measured (the callback must not block);
//  - Init.
// The "app" is whoever sent the last datagram. Test knobs (environment):
//   FAKE_PSDK_LISTEN HOST:PORT   where the app's packets arrive (default 127.0.0.1:14570)
//   FAKE_PSDK_RATE B/s           the channel's bandwidth limit (default 4000, DJI's figure)
//   FAKE_PSDK_FAIL all           every call answers DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR
//   FAKE_PSDK_REFUSE_EVERY N     every Nth SendData answers DJI_ERROR_SYSTEM_MODULE_CODE_BUSY, sending nothing
//   FAKE_PSDK_FLOOD N            after the first datagram, N more calls of the callback at once, with
//                                128 bytes of noise each, as fast as the thread can make them
#include "fake_psdk.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "dji_low_speed_data_channel.h"

namespace {

constexpr std::size_t PACKAGE = 128;
constexpr std::size_t BUFFER = 512;

double now_s()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

class Channel {
public:
    Channel()
    {
        const char* where = std::getenv("FAKE_PSDK_LISTEN");
        const std::string spec = where != nullptr ? where : "127.0.0.1:14570";
        const std::size_t colon = spec.rfind(':');
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_port = htons(static_cast<std::uint16_t>(std::atoi(spec.c_str() + colon + 1)));
        ::inet_pton(AF_INET, spec.substr(0, colon).c_str(), &a.sin_addr);
        fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
        if (fd_ < 0 || ::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
            std::perror("fake PSDK: bind");
            std::exit(3);
        }
        timeval tv{0, 50000};
        ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
        const char* rate = std::getenv("FAKE_PSDK_RATE");
        limit_ = rate != nullptr ? std::atoi(rate) : 4000;
        const char* fail = std::getenv("FAKE_PSDK_FAIL");
        fail_all_ = fail != nullptr && std::string(fail) == "all";
        const char* every = std::getenv("FAKE_PSDK_REFUSE_EVERY");
        refuse_every_ = every != nullptr ? std::strtoull(every, nullptr, 10) : 0;
        const char* flood = std::getenv("FAKE_PSDK_FLOOD");
        flood_ = flood != nullptr ? std::strtoull(flood, nullptr, 10) : 0;
        window_ = now_s();
        receiver_ = std::thread([this] { receive(); });
        releaser_ = std::thread([this] { release(); });
    }

    ~Channel()
    {
        running_ = false;
        receiver_.join();
        releaser_.join();
        ::close(fd_);
    }

    bool fail_all() const { return fail_all_; }

    T_DjiReturnCode send(E_DjiChannelAddress to, const uint8_t* data, uint8_t len)
    {
        std::lock_guard<std::mutex> lock(m_);
        ++stats_.sends;
        if (fail_all_ || (refuse_every_ != 0 && stats_.sends % refuse_every_ == 0)) {
            ++stats_.refused;
            return fail_all_ ? DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR : DJI_ERROR_SYSTEM_MODULE_CODE_BUSY;
        }
        if (to != DJI_CHANNEL_ADDRESS_MASTER_RC_APP) {
            ++stats_.refused;
            return DJI_ERROR_SYSTEM_MODULE_CODE_NONSUPPORT;  // the stand-in has only the app
        }
        if (data == nullptr || len == 0) {
            ++stats_.refused;
            return DJI_ERROR_SYSTEM_MODULE_CODE_INVALID_PARAMETER;
        }
        roll(now_s());
        for (std::size_t at = 0; at < len; at += PACKAGE) {
            const std::size_t n = std::min<std::size_t>(PACKAGE, len - at);
            before_ += n;
            if (queued_bytes_ == 0 && sent_in_window_ + n <= static_cast<std::size_t>(limit_)) {
                put(data + at, n);
            } else if (queued_bytes_ + n <= BUFFER) {
                queue_.emplace_back(data + at, data + at + n);
                queued_bytes_ += n;
                ++stats_.buffered;
                busy_since_ = now_s();
            } else {
                ++stats_.discarded;  // "If the buffer is full, data will be discarded."
                busy_since_ = now_s();
            }
        }
        return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
    }

    T_DjiReturnCode state(T_DjiDataChannelState* s)
    {
        std::lock_guard<std::mutex> lock(m_);
        if (fail_all_) {
            ++stats_.refused;
            return DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR;
        }
        if (s == nullptr) {
            ++stats_.refused;
            return DJI_ERROR_SYSTEM_MODULE_CODE_INVALID_PARAMETER;
        }
        roll(now_s());
        s->realtimeBandwidthLimit = limit_;
        s->realtimeBandwidthBeforeFlowController = static_cast<int32_t>(last_before_);
        s->realtimeBandwidthAfterFlowController = static_cast<int32_t>(last_after_);
        s->busyState = queued_bytes_ != 0 || now_s() - busy_since_ < 1.0;
        if (s->busyState) {
            ++stats_.busy_reports;
        }
        return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
    }

    T_DjiReturnCode reg(DjiLowSpeedDataChannelRecvDataCallback cb)
    {
        std::lock_guard<std::mutex> lock(m_);
        if (fail_all_) {
            ++stats_.refused;
            return DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR;
        }
        callback_ = cb;
        return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
    }

    FakePsdkStats stats()
    {
        std::lock_guard<std::mutex> lock(m_);
        return stats_;
    }

private:
    // A new one-second window: the flow controller releases what it holds, within the limit.
    void roll(double t)
    {
        if (t - window_ < 1.0) {
            return;
        }
        window_ += std::floor(t - window_);
        last_before_ = before_;
        last_after_ = sent_in_window_;
        before_ = 0;
        sent_in_window_ = 0;
        while (!queue_.empty() && sent_in_window_ + queue_.front().size() <= static_cast<std::size_t>(limit_)) {
            const std::vector<std::uint8_t> p = std::move(queue_.front());
            queue_.pop_front();
            queued_bytes_ -= p.size();
            put(p.data(), p.size());
        }
    }

    void put(const std::uint8_t* p, std::size_t n)
    {
        sent_in_window_ += n;
        ++stats_.packets_out;
        if (have_peer_) {
            ::sendto(fd_, p, n, 0, reinterpret_cast<sockaddr*>(&peer_), sizeof peer_);
        }
    }

    void release()
    {
        while (running_) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            std::lock_guard<std::mutex> lock(m_);
            roll(now_s());
        }
    }

    void call(DjiLowSpeedDataChannelRecvDataCallback cb, const std::uint8_t* p, std::size_t n)
    {
        const double t0 = now_s();
        cb(p, static_cast<uint16_t>(n));
        const auto us = static_cast<std::uint64_t>((now_s() - t0) * 1e6);
        std::lock_guard<std::mutex> lock(m_);
        ++stats_.callbacks;
        stats_.slowest_callback_us = std::max(stats_.slowest_callback_us, us);
    }

    void receive()
    {
        bool flooded = false;
        while (running_) {
            std::uint8_t buf[2048];
            sockaddr_in from{};
            socklen_t len = sizeof from;
            const ssize_t n = ::recvfrom(fd_, buf, sizeof buf, 0, reinterpret_cast<sockaddr*>(&from), &len);
            if (n <= 0) {
                continue;
            }
            DjiLowSpeedDataChannelRecvDataCallback cb = nullptr;
            {
                std::lock_guard<std::mutex> lock(m_);
                peer_ = from;
                have_peer_ = true;
                cb = callback_;
            }
            if (cb == nullptr) {
                continue;
            }
            for (std::size_t at = 0; at < static_cast<std::size_t>(n); at += PACKAGE) {
                call(cb, buf + at, std::min<std::size_t>(PACKAGE, static_cast<std::size_t>(n) - at));
            }
            if (flood_ != 0 && !flooded) {
                flooded = true;
                std::uint8_t noise[PACKAGE];
                std::uint32_t x = 12345;
                for (std::uint64_t i = 0; i < flood_; ++i) {
                    for (std::uint8_t& b : noise) {
                        x = x * 1103515245u + 12345u;
                        b = static_cast<std::uint8_t>(x >> 24);
                    }
                    call(cb, noise, sizeof noise);
                }
            }
        }
    }

    int fd_ = -1;
    int limit_ = 4000;
    bool fail_all_ = false;
    std::uint64_t refuse_every_ = 0;
    std::uint64_t flood_ = 0;
    std::mutex m_;
    sockaddr_in peer_{};
    bool have_peer_ = false;
    DjiLowSpeedDataChannelRecvDataCallback callback_ = nullptr;
    std::deque<std::vector<std::uint8_t>> queue_;
    std::size_t queued_bytes_ = 0;
    double window_ = 0.0;
    std::size_t sent_in_window_ = 0;
    std::size_t before_ = 0;
    std::size_t last_before_ = 0;
    std::size_t last_after_ = 0;
    double busy_since_ = -10.0;
    FakePsdkStats stats_{};
    std::atomic<bool> running_{true};
    std::thread receiver_;
    std::thread releaser_;
};

Channel* g_channel = nullptr;
std::mutex g_init;

}  // namespace

FakePsdkStats fake_psdk_stats()
{
    std::lock_guard<std::mutex> lock(g_init);
    return g_channel != nullptr ? g_channel->stats() : FakePsdkStats{};
}

extern "C" {

T_DjiReturnCode DjiLowSpeedDataChannel_Init(void)
{
    std::lock_guard<std::mutex> lock(g_init);
    if (g_channel == nullptr) {
        g_channel = new Channel;  // lives as long as the process, as the SDK's module does
    }
    return g_channel->fail_all() ? DJI_ERROR_SYSTEM_MODULE_CODE_SYSTEM_ERROR : DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS;
}

T_DjiReturnCode DjiLowSpeedDataChannel_DeInit(void) { return DJI_ERROR_SYSTEM_MODULE_CODE_SUCCESS; }

T_DjiReturnCode DjiLowSpeedDataChannel_SendData(E_DjiChannelAddress channelAddress, const uint8_t* data, uint8_t len)
{
    if (g_channel == nullptr) {
        return DJI_ERROR_SYSTEM_MODULE_CODE_NONSUPPORT_IN_CURRENT_STATE;  // not initialised
    }
    return g_channel->send(channelAddress, data, len);
}

T_DjiReturnCode DjiLowSpeedDataChannel_GetSendDataState(E_DjiChannelAddress channelAddress,
                                                        T_DjiDataChannelState* state)
{
    (void)channelAddress;
    if (g_channel == nullptr) {
        return DJI_ERROR_SYSTEM_MODULE_CODE_NONSUPPORT_IN_CURRENT_STATE;
    }
    return g_channel->state(state);
}

T_DjiReturnCode DjiLowSpeedDataChannel_RegRecvDataCallback(E_DjiChannelAddress channelAddress,
                                                           DjiLowSpeedDataChannelRecvDataCallback callback)
{
    (void)channelAddress;
    if (g_channel == nullptr) {
        return DJI_ERROR_SYSTEM_MODULE_CODE_NONSUPPORT_IN_CURRENT_STATE;
    }
    return g_channel->reg(callback);
}

}  // extern "C"
