// A stand-in for DJI's Linux sample Application (samples/sample_c++/platform/linux/manifold2/
// application/application.hpp, the real header, vendored): on an aircraft it registers the
// platform's handlers and calls DjiCore_Init; here there is nothing to set up (the low-speed
// channel's stand-in, fake_psdk.cpp, needs no core).
#include "application.hpp"

Application::Application(int /*argc*/, char** /*argv*/) {}

Application::~Application() = default;
