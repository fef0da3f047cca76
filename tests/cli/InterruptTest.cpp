// Ctrl-C during a render: lancer stops, writes what it has rendered (the rest black), says where,
// and exits 130.

#include <gtest/gtest.h>

#include <algorithm>

#include "LancerRun.h"

#ifndef _WIN32
#include <csignal>
#include <thread>

namespace lancer::test {
namespace {

TEST(CliInterrupt, CtrlCWritesTheFinishedPartAndExits130) {
    // About 15 s of work for two threads in a release build (longer under sanitizers): far more
    // than the delay before Ctrl-C, while one 16x16 tile takes a few dozen milliseconds, so that
    // some are finished by then.
    constexpr int kWidth = 640, kHeight = 480;
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    LancerProcess lancer({"scene.json", "-o", "out.pfm", "--width", std::to_string(kWidth),
                          "--height", std::to_string(kHeight), "--spp", "64", "--threads", "2"},
                         folder.path());
    std::this_thread::sleep_for(std::chrono::seconds(1));
    lancer.sendSignal(SIGINT);
    // Stopping takes as long as the row of a tile that each worker is on: well under a second.
    const RunResult run = lancer.wait(std::chrono::seconds(20));

    EXPECT_EQ(run.exitStatus, 130) << run;
    EXPECT_NE(run.standardError.find("out.pfm"), std::string::npos)
        << "says where the image was written: " << run.standardError;
    EXPECT_EQ(folder.entries(), (std::vector<std::string>{"out.pfm", "scene.json"}))
        << "the image, and no temporary file";

    const Image image = loadImage(folder / "out.pfm");
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    // Every rendered pixel of this scene is lit by at least the ambient light, so black means
    // "not rendered".
    const auto black = std::count(image.pixels.begin(), image.pixels.end(), Image::Rgb{0, 0, 0});
    EXPECT_GT(black, 0) << "the render was stopped before its end";
    EXPECT_LT(black, static_cast<long>(image.pixels.size())) << "what was rendered is written";
}

}  // namespace
}  // namespace lancer::test

#endif
