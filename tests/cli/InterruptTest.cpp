// Ctrl-C, SIGTERM and SIGHUP during a render: lancer stops, writes what it has rendered (the rest
// black), says where, and exits 128 + the signal's number; more signals do not break the save; a
// signal while the scene loads exits at once and writes nothing.

#include <gtest/gtest.h>

#include <algorithm>

#include "LancerRun.h"

#ifndef _WIN32
#include <sys/stat.h>

#include <csignal>
#include <thread>

namespace lancer::test {
namespace {

constexpr int kWidth = 640, kHeight = 480;

// About 15 s of work for two threads in a release build (longer under sanitizers): far more
// than the delay before the signal, while one 16x16 tile takes a few dozen milliseconds, so that
// some are finished by then.
LancerProcess startLongRender(const TempFolder& folder,
                              const std::vector<std::string>& moreOptions = {}) {
    folder.write("scene.json", loadWhittedScene().dump());
    std::vector<std::string> arguments = {"scene.json",
                                          "-o",
                                          "out.pfm",
                                          "--width",
                                          std::to_string(kWidth),
                                          "--height",
                                          std::to_string(kHeight),
                                          "--spp",
                                          "64",
                                          "--threads",
                                          "2"};
    arguments.insert(arguments.end(), moreOptions.begin(), moreOptions.end());
    return LancerProcess(arguments, folder.path());
}

// The partial image: its size, some of it rendered and some not.
void expectPartialImage(const TempFolder& folder) {
    const Image image = loadImage(folder / "out.pfm");
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    // Every rendered pixel of this scene is lit by at least the ambient light, so black means
    // "not rendered".
    const auto black = std::count(image.pixels.begin(), image.pixels.end(), Image::Rgb{0, 0, 0});
    EXPECT_GT(black, 0) << "the render was stopped before its end";
    EXPECT_LT(black, static_cast<long>(image.pixels.size())) << "what was rendered is written";
}

struct SignalCase {
    std::string name;
    int signal;
    int exitStatus;
};

std::ostream& operator<<(std::ostream& out, const SignalCase& c) {
    return out << c.name;
}

class CliInterrupt : public testing::TestWithParam<SignalCase> {};

TEST_P(CliInterrupt, WritesTheFinishedPartAndExitsWithTheSignalsStatus) {
    const TempFolder folder;
    LancerProcess lancer = startLongRender(folder);
    std::this_thread::sleep_for(std::chrono::seconds(1));
    lancer.sendSignal(GetParam().signal);
    // Stopping takes as long as the row of a tile that each worker is on: well under a second.
    const RunResult run = lancer.wait(std::chrono::seconds(20));

    EXPECT_EQ(run.exitStatus, GetParam().exitStatus) << run;
    EXPECT_NE(run.standardError.find("out.pfm"), std::string::npos)
        << "says where the image was written: " << run.standardError;
    EXPECT_EQ(folder.entries(),
              (std::vector<std::string>{"out.pfm", "out.pfm.resume", "scene.json"}))
        << "the image and its resume file, and no temporary file";
    expectPartialImage(folder);
}

INSTANTIATE_TEST_SUITE_P(Signals, CliInterrupt,
                         testing::Values(SignalCase{"CtrlC", SIGINT, 130},
                                         SignalCase{"Term", SIGTERM, 143},
                                         SignalCase{"Hangup", SIGHUP, 129}),
                         CaseName());

// The auxiliary outputs are written with the partial image, holding the same tiles. The crop
// starts below the horizon, so that the first tiles see the floor (depth > 0) rather than the sky.
TEST(CliInterruptWithAovs, WritesThemWithTheFinishedPart) {
    const TempFolder folder;
    LancerProcess lancer = startLongRender(folder, {"--aov", "depth", "--crop", "0,300,640,480"});
    std::this_thread::sleep_for(std::chrono::seconds(1));
    lancer.sendSignal(SIGINT);
    const RunResult run = lancer.wait(std::chrono::seconds(20));
    EXPECT_EQ(run.exitStatus, 130) << run;
    EXPECT_EQ(folder.entries(), (std::vector<std::string>{"out.depth.exr", "out.pfm",
                                                          "out.pfm.resume", "scene.json"}));
    expectPartialImage(folder);
    const Image image = loadImage(folder / "out.pfm");
    const Image depth = loadImage(folder / "out.depth.exr");
    ASSERT_EQ(depth.pixels.size(), image.pixels.size());
    std::size_t rendered = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        // Unrendered pixels (black) have no depth; a rendered one may be sky (depth 0 too).
        if (image.pixels[i] == Image::Rgb{0, 0, 0})
            ASSERT_EQ(depth.pixels[i], (Image::Rgb{0, 0, 0})) << "pixel " << i;
        else
            rendered += depth.pixels[i][0] > 0;
    }
    EXPECT_GT(rendered, 0u);
}

TEST(CliInterruptAgain, MoreCtrlCsWhileItStopsAndSavesAreHarmless) {
    const TempFolder folder;
    LancerProcess lancer = startLongRender(folder);
    std::this_thread::sleep_for(std::chrono::seconds(1));
    // Ctrl-C after Ctrl-C until it ends: many land while the workers stop and the image is
    // written (a 3.7 MB PFM).
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!lancer.hasEnded() && std::chrono::steady_clock::now() < until) {
        lancer.sendSignal(SIGINT);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const RunResult run = lancer.wait(std::chrono::seconds(1));

    EXPECT_EQ(run.exitStatus, 130) << run;
    EXPECT_EQ(folder.entries(),
              (std::vector<std::string>{"out.pfm", "out.pfm.resume", "scene.json"}))
        << "the image and its resume file, and no temporary file";
    expectPartialImage(folder);
}

TEST(CliInterruptWhileLoading, ExitsAtOnceAndWritesNothing) {
    // The scene is a pipe that nobody writes to: lancer waits in the middle of loading it.
    const TempFolder folder;
    ASSERT_EQ(mkfifo((folder / "scene.json").c_str(), 0600), 0);
    LancerProcess lancer({"scene.json", "-o", "out.png"}, folder.path());
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    lancer.sendSignal(SIGINT);
    const RunResult run = lancer.wait(std::chrono::seconds(10));

    EXPECT_EQ(run.exitStatus, 130) << run;
    EXPECT_EQ(run.errorLines(),
              std::vector<std::string>{
                  "lancer: interrupted while loading the scene; nothing was written"})
        << run;
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"scene.json"}) << "nothing written";
}

}  // namespace
}  // namespace lancer::test

#endif
