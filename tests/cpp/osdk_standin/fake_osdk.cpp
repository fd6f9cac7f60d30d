// A stand-in for the functions of DJI's Onboard SDK that a program using OsdkLink and DJI's Linux
// sample helper calls, compiled against the SDK's real headers (tests/vendor/dji/osdk-3.9.0/ or
// osdk-4.1.0/) with -DFAKE_OSDK_VERSION=39 or 41 (what the SDK would be, told by the test, not
// guessed from the headers as OsdkLink does). It defines only functions the headers declare:
// LinuxSetup's (and, on 4.1, Setup's) constructor, destructor and initVehicle, Vehicle's
// constructor and destructor, MobileDevice's constructor, destructor, getVehicle, sendDataToMSDK
// and setFromMSDKCallback, and Version::FW and Log's constructor and destructor (which the
// headers' static initialisers call, with print, its one virtual function). The "radio" is UDP: packets from the mobile device arrive on
// FAKE_OSDK_LISTEN (HOST:PORT, where `ttctl link relay --to` sends) and go to the callback on a
// thread of the SDK's own, in a RecvContainer as each SDK fills it: the data at
// recvData.raw_ack_array, recvInfo.len = data + OpenProtocol::PackageMin on 4.1
// (dji_legacy_linker.cpp), the open protocol frame's length, PackageMin + 2 + data, on 3.9
// (dji_open_protocol.cpp, recvReqData). sendDataToMSDK drops more than 100 bytes as the SDK does
// ("Too much data to send") and sends a datagram to whoever sent last.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>

#include "dji_linux_helpers.hpp"

#if FAKE_OSDK_VERSION != 39 && FAKE_OSDK_VERSION != 41
#error "build with -DFAKE_OSDK_VERSION=39 or 41"
#endif

using DJI::OSDK::MobileDevice;
using DJI::OSDK::OpenProtocol;
using DJI::OSDK::RecvContainer;
using DJI::OSDK::UserData;
using DJI::OSDK::Vehicle;
using DJI::OSDK::VehicleCallBack;

namespace {

// The radio of the one mobile device (the SDK's MobileDevice has no room for it).
class Radio {
public:
    explicit Radio(MobileDevice* device) : device_(device)
    {
        const char* where = std::getenv("FAKE_OSDK_LISTEN");
        const std::string spec = where != nullptr ? where : "127.0.0.1:14560";
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

    ~Radio()
    {
        running_ = false;
        thread_.join();
        ::close(fd_);
    }

    void send(const std::uint8_t* data, std::uint8_t len)
    {
        std::lock_guard<std::mutex> lock(m_);
        if (have_peer_) {
            ::sendto(fd_, data, len, 0, reinterpret_cast<sockaddr*>(&peer_), sizeof peer_);
        }
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
                continue;  // DTT carries at most 100 bytes a packet
            }
            {
                std::lock_guard<std::mutex> lock(m_);
                peer_ = from;
                have_peer_ = true;
            }
            const DJI::OSDK::VehicleCallBackHandler h = device_->fromMSDKHandler;
            if (h.callback == nullptr) {
                continue;
            }
            RecvContainer rc;
            std::memset(&rc, 0, sizeof rc);
            std::memcpy(rc.recvData.raw_ack_array, buf, static_cast<std::size_t>(n));
#if FAKE_OSDK_VERSION == 41
            rc.recvInfo.len = static_cast<std::uint16_t>(n + OpenProtocol::PackageMin);
#else
            rc.recvInfo.len = static_cast<std::uint16_t>(OpenProtocol::PackageMin + 2 + n);
#endif
            h.callback(device_->getVehicle(), rc, h.userData);
        }
    }

    MobileDevice* device_;
    int fd_ = -1;
    std::mutex m_;
    sockaddr_in peer_{};
    bool have_peer_ = false;
    std::atomic<bool> running_{true};
    std::thread thread_;
};

Radio* g_radio = nullptr;

}  // namespace

namespace DJI {
namespace OSDK {

// Headers' static firmware constants call it: a.b.c.d packed as their comments show
// (M100_31 = 0x03010A00 = FW(3, 1, 10, 0)). The header declares the return type const.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wignored-qualifiers"
const Version::FirmWare Version::FW(uint8_t a, uint8_t b, uint8_t c, uint8_t d)
{
    return static_cast<FirmWare>(a) << 24 | static_cast<FirmWare>(b) << 16 | static_cast<FirmWare>(c) << 8 | d;
}
#pragma GCC diagnostic pop

// The headers make the logger's singleton at start-up (Singleton<Log>::singleInstance = new T()).
Log::Log(Mutex* m) : mutex(m), vaild(true),
#if FAKE_OSDK_VERSION == 41
                     initFlag(true),
#endif
                     enable_status(false), enable_debug(false), enable_error(true)
{
}

Log::~Log() = default;

Log& Log::print(const char* /*fmt*/, ...) { return *this; }  // the SDK's log: silent here

MobileDevice::MobileDevice(Vehicle* vehicle) : vehicle(vehicle)
{
    fromMSDKHandler.callback = nullptr;
    fromMSDKHandler.userData = nullptr;
}

MobileDevice::~MobileDevice() = default;

Vehicle* MobileDevice::getVehicle() const { return vehicle; }

void MobileDevice::sendDataToMSDK(uint8_t* data, uint8_t len)
{
    if (len > 100) {
        return;  // the SDK: "Too much data to send", dropped
    }
    g_radio->send(data, len);
}

void MobileDevice::setFromMSDKCallback(VehicleCallBack callback, UserData userData)
{
    fromMSDKHandler.callback = callback;
    fromMSDKHandler.userData = userData;
}

#if FAKE_OSDK_VERSION == 41
// (the MOP server's stand-in is fake_osdk_mop.cpp: a program that links it uses vehicle->mopServer)
Vehicle::Vehicle(Linker* /*linker*/) : mobileDevice(new MobileDevice(this)), djiHms(nullptr), mopServer(nullptr) {}

Setup::Setup(bool enableAdvancedSensing) : vehicle(nullptr), linker(nullptr), useAdvancedSensing(enableAdvancedSensing)
{
}

Setup::~Setup() = default;
bool Setup::initVehicle() { return true; }
void Setup::setupEnvironment() {}
#else
Vehicle::Vehicle(bool /*threadSupport*/) : mobileDevice(new MobileDevice(this)) {}
#endif

Vehicle::~Vehicle() { delete mobileDevice; }

}  // namespace OSDK
}  // namespace DJI

#if FAKE_OSDK_VERSION == 41
// fake_osdk_mop.cpp's MOP server, when the program links it (weak symbols: null otherwise).
__attribute__((weak)) DJI::OSDK::MopServer* fake_osdk_mop_server();
__attribute__((weak)) void fake_osdk_mop_server_free(DJI::OSDK::MopServer* server);

LinuxSetup::LinuxSetup(int /*argc*/, char** /*argv*/, bool enableAdvancedSensing)
    : Setup(enableAdvancedSensing), functionTimeout(1), activateData(), environment(nullptr)
{
    vehicle = new Vehicle(static_cast<DJI::OSDK::Linker*>(nullptr));  // "activated"
    g_radio = new Radio(vehicle->mobileDevice);
    if (fake_osdk_mop_server != nullptr) {
        vehicle->mopServer = fake_osdk_mop_server();  // as the SDK's initMopServer on Linux
    }
}

LinuxSetup::~LinuxSetup()
{
    delete g_radio;
    if (fake_osdk_mop_server_free != nullptr) {
        fake_osdk_mop_server_free(vehicle->mopServer);
    }
    delete vehicle;
}

bool LinuxSetup::initVehicle() { return true; }
#else
LinuxSetup::LinuxSetup(int /*argc*/, char** /*argv*/, bool enableAdvancedSensing)
    : vehicle(new Vehicle(true)), testSerialDevice(nullptr), environment(nullptr), activateData(),
      functionTimeout(1), useAdvancedSensing(enableAdvancedSensing)
{
    g_radio = new Radio(vehicle->mobileDevice);  // "activated"
}

LinuxSetup::~LinuxSetup()
{
    delete g_radio;
    delete vehicle;
}
#endif
