// What the Payload SDK stand-in (fake_psdk.cpp) tells a test program about itself: not part of
// DJI's SDK (whose declarations come from the real, vendored dji_low_speed_data_channel.h).
#ifndef FAKE_PSDK_HPP
#define FAKE_PSDK_HPP

#include <cstdint>

struct FakePsdkStats {
    std::uint64_t sends;  // DjiLowSpeedDataChannel_SendData calls
    std::uint64_t packets_out;  // 128-byte (or shorter) packages put on the "radio" (UDP)
    std::uint64_t buffered;  // packages that went through the 512-byte flow-control buffer
    std::uint64_t discarded;  // packages discarded because that buffer was full
    std::uint64_t busy_reports;  // GetSendDataState answers with busyState set
    std::uint64_t callbacks;  // calls of the registered receive callback
    std::uint64_t slowest_callback_us;  // the longest a callback kept the SDK's thread
    std::uint64_t refused;  // calls answered with an error code
};

FakePsdkStats fake_psdk_stats();

#endif  // FAKE_PSDK_HPP
