// A stand-in for the Onboard SDK 4 samples' LinuxSetup (dji_linux_helpers.hpp): it "activates"
// a fake Vehicle (see dji_vehicle.hpp here) and hands it out.
#ifndef FAKE_OSDK_DJI_LINUX_HELPERS_HPP
#define FAKE_OSDK_DJI_LINUX_HELPERS_HPP

#include "dji_vehicle.hpp"

class LinuxSetup {
public:
    LinuxSetup(int /*argc*/, char** /*argv*/, bool /*enableAdvancedSensing*/ = false) : vehicle_(new DJI::OSDK::Vehicle) {}
    ~LinuxSetup() { delete vehicle_; }
    LinuxSetup(const LinuxSetup&) = delete;
    LinuxSetup& operator=(const LinuxSetup&) = delete;
    DJI::OSDK::Vehicle* getVehicle() { return vehicle_; }

private:
    DJI::OSDK::Vehicle* vehicle_;
};

#endif  // FAKE_OSDK_DJI_LINUX_HELPERS_HPP
