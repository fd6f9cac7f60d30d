// What the MOP channel stand-in (fake_mop.cpp) tells a test program about itself: not part of
// DJI's SDK (whose declarations come from the real, vendored dji_mop_channel.h).
#ifndef FAKE_MOP_HPP
#define FAKE_MOP_HPP

#include <cstdint>

struct FakeMopStats {
    std::uint64_t accepts;  // connections accepted
    std::uint64_t bytes_in;  // bytes DjiMopChannel_RecvData gave
    std::uint64_t bytes_out;  // bytes DjiMopChannel_SendData took
    std::uint64_t short_sends;  // sends cut short (TTCTL_FAKE_MOP_SHORT)
    std::uint64_t forced_closes;  // connections closed by TTCTL_FAKE_MOP_CLOSE_AFTER
    std::uint64_t failed_calls;  // calls answered with an error code
    std::uint64_t live_handles;  // handles created and not yet destroyed
    std::uint64_t stalls;  // sends held until the connection was closed (TTCTL_FAKE_MOP_STALL)
};

FakeMopStats fake_mop_stats();

#endif  // FAKE_MOP_HPP
