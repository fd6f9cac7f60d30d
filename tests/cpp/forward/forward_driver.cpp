// The onboard side of a real-link measurement, with the Onboard SDK replaced by a UDP socket
// that `ttctl link relay` (the emulated radio) sends to: what arrives there is "data from
// mobile" for UdpForward::from_link, and UdpForward's to_link sends back to the relay.
// Usage: forward_driver RADIO_PORT SERVE_PORT; prints "ready", runs until stdin closes.
#include <poll.h>

#include <cstdio>
#include <cstdlib>

#include "ttapi/udp_forward.hpp"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: forward_driver RADIO_PORT SERVE_PORT\n");
        return 2;
    }
    const int radio = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in me{};
    me.sin_family = AF_INET;
    me.sin_port = htons(static_cast<std::uint16_t>(std::atoi(argv[1])));
    me.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (radio < 0 || ::bind(radio, reinterpret_cast<sockaddr*>(&me), sizeof me) != 0) {
        std::perror("bind");
        return 1;
    }
    sockaddr_storage relay{};
    socklen_t relay_len = 0;
    ttapi::UdpForward fwd("127.0.0.1", static_cast<std::uint16_t>(std::atoi(argv[2])),
                          [&](const std::uint8_t* data, std::size_t n) {
                              if (relay_len != 0) {
                                  ::sendto(radio, data, n, 0, reinterpret_cast<sockaddr*>(&relay), relay_len);
                              }
                          });
    std::printf("ready\n");
    std::fflush(stdout);
    pollfd fds[3] = {{radio, POLLIN, 0}, {fwd.fd(), POLLIN, 0}, {0, POLLIN, 0}};
    std::uint8_t buf[2048];
    for (;;) {
        if (::poll(fds, 3, 1000) < 0) {
            continue;
        }
        if (fds[0].revents & POLLIN) {
            relay_len = sizeof relay;
            const ssize_t n = ::recvfrom(radio, buf, sizeof buf, 0, reinterpret_cast<sockaddr*>(&relay), &relay_len);
            if (n > 0) {
                fwd.from_link(buf, static_cast<std::size_t>(n));
            }
        }
        if (fds[1].revents & (POLLIN | POLLERR)) {
            fwd.poll();
        }
        if (fds[2].revents & (POLLIN | POLLHUP)) {
            if (::read(0, buf, sizeof buf) <= 0) {
                break;
            }
        }
    }
    std::printf("up %llu down %llu dropped %llu\n", static_cast<unsigned long long>(fwd.forwarded_up()),
                static_cast<unsigned long long>(fwd.forwarded_down()), static_cast<unsigned long long>(fwd.dropped()));
    ::close(radio);
    return 0;
}
