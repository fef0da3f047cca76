#pragma once

#include <string>

namespace lancer::test {

// A virtual X server (Xvfb) of the test's own, on a free display number that Xvfb picks itself,
// so that tests run in parallel do not meet. Killed when destroyed.
class XvfbServer {
public:
    // Whether Xvfb is installed (on the PATH).
    static bool installed();

    // Starts a server with one screen of width x height pixels, 24-bit colour; throws
    // std::runtime_error if it does not come up.
    XvfbServer(int width, int height);
    ~XvfbServer();
    XvfbServer(const XvfbServer&) = delete;
    XvfbServer& operator=(const XvfbServer&) = delete;

    // Its display name, ":N", for DISPLAY.
    const std::string& display() const { return display_; }

private:
    int pid_ = -1;
    std::string display_;
};

}  // namespace lancer::test
