// A stand-in for DJI's Onboard SDK 4 (dji_vehicle.hpp), enough of it for the README's program to
// compile and run unchanged in tests/test_readme_cpp.py: the names and types the program uses
// (Vehicle::mobileDevice, MobileDevice::sendDataToMSDK and setFromMSDKCallback, RecvContainer's
// recvInfo.len and recvData.raw_ack_array, OpenProtocol::PackageMin, UserData, VehicleCallBack)
// as OSDK 4 declares them. The "radio" is UDP: packets from the mobile device are datagrams that
// arrive on FAKE_OSDK_LISTEN (HOST:PORT, where `ttctl link relay --to` sends), delivered to the
// callback on a thread of the SDK's own, with recvInfo.len = data + PackageMin as OSDK 4's
// legacy linker reports it; sendDataToMSDK sends a datagram back to whoever sent last.
#ifndef FAKE_OSDK_DJI_VEHICLE_HPP
#define FAKE_OSDK_DJI_VEHICLE_HPP

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>

namespace DJI {
namespace OSDK {

typedef void* UserData;

class OpenProtocol {
public:
    static const int PackageMin = 16;  // header and CRC of DJI's open protocol frame
};

struct RecvInfo {
    std::uint8_t cmd_set;
    std::uint8_t cmd_id;
    std::uint16_t len;
    std::uint16_t seqNumber;
};

union RecvData {
    std::uint8_t raw_ack_array[1024];
};

struct RecvContainer {
    RecvInfo recvInfo;
    RecvData recvData;
};

class Vehicle;
typedef void (*VehicleCallBack)(Vehicle* vehicle, RecvContainer recvFrame, UserData userData);

class MobileDevice {
public:
    explicit MobileDevice(Vehicle* vehicle) : vehicle_(vehicle)
    {
        const char* where = std::getenv("FAKE_OSDK_LISTEN");
        std::string spec = where != nullptr ? where : "127.0.0.1:14560";
        const std::size_t colon = spec.rfind(':');
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_port = htons(static_cast<std::uint16_t>(std::atoi(spec.c_str() + colon + 1)));
        ::inet_pton(AF_INET, spec.substr(0, colon).c_str(), &a.sin_addr);
        fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
        if (fd_ < 0 || ::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
            std::perror("fake OSDK: bind");
            std::exit(3);
        }
        timeval tv{0, 100000};
        ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
        thread_ = std::thread([this] { receive(); });
    }

    ~MobileDevice()
    {
        running_ = false;
        thread_.join();
        ::close(fd_);
    }

    void sendDataToMSDK(std::uint8_t* data, std::uint8_t len)
    {
        if (len > 100) {
            return;  // "Too much data to send": the real SDK says so and drops it
        }
        std::lock_guard<std::mutex> lock(m_);
        if (have_peer_) {
            ::sendto(fd_, data, len, 0, reinterpret_cast<sockaddr*>(&peer_), sizeof peer_);
        }
    }

    void setFromMSDKCallback(VehicleCallBack callback, UserData userData = 0)
    {
        std::lock_guard<std::mutex> lock(m_);
        callback_ = callback;
        user_ = userData;
    }

private:
    void receive()
    {
        while (running_) {
            std::uint8_t buf[2048];
            sockaddr_in from{};
            socklen_t len = sizeof from;
            const ssize_t n = ::recvfrom(fd_, buf, sizeof buf, 0, reinterpret_cast<sockaddr*>(&from), &len);
            if (n <= 0 || n > 100) {
                continue;
            }
            VehicleCallBack cb = nullptr;
            UserData user = nullptr;
            {
                std::lock_guard<std::mutex> lock(m_);
                peer_ = from;
                have_peer_ = true;
                cb = callback_;
                user = user_;
            }
            if (cb != nullptr) {
                RecvContainer rc{};
                std::memcpy(rc.recvData.raw_ack_array, buf, static_cast<std::size_t>(n));
                rc.recvInfo.len = static_cast<std::uint16_t>(n + OpenProtocol::PackageMin);
                cb(vehicle_, rc, user);
            }
        }
    }

    Vehicle* vehicle_;
    int fd_ = -1;
    std::mutex m_;
    sockaddr_in peer_{};
    bool have_peer_ = false;
    VehicleCallBack callback_ = nullptr;
    UserData user_ = nullptr;
    std::atomic<bool> running_{true};
    std::thread thread_;
};

class Vehicle {
public:
    Vehicle() : mobileDevice(new MobileDevice(this)) {}
    ~Vehicle() { delete mobileDevice; }
    MobileDevice* mobileDevice;
};

}  // namespace OSDK
}  // namespace DJI

#endif  // FAKE_OSDK_DJI_VEHICLE_HPP
