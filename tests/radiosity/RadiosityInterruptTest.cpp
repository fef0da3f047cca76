// Ctrl-C during a radiosity solve (progressive or hierarchical): the solver stops soon, lancer says
// so in one line and exits 130, and writes nothing: no image (nothing was rendered), no saved
// solution, no temporary file.

#include <gtest/gtest.h>

#include "LancerRun.h"

#ifndef _WIN32
#include <csignal>
#include <thread>

namespace lancer::test {
namespace {

using namespace std::chrono_literals;

// A method, and settings that make its solve of the Whitted scene last far longer than the delay
// before Ctrl-C.
struct SlowSolve {
    const char* name;
    const char* radiosity;
};

class RadiosityInterrupt : public testing::TestWithParam<SlowSolve> {};

TEST_P(RadiosityInterrupt, CtrlCDuringTheSolveWritesNothingAndExits130) {
    nlohmann::json scene = loadWhittedScene();
    scene["render"]["integrator"] = "radiosity";
    scene["radiosity"] = nlohmann::json::parse(GetParam().radiosity);
    const TempFolder folder;
    folder.write("scene.json", scene.dump());
    LancerProcess lancer({"scene.json", "-o", "out.png", "--width", "32", "--height", "24",
                          "--threads", "2", "--save-radiosity", "solution.rad"},
                         folder.path());
    std::this_thread::sleep_for(1s);
    lancer.sendSignal(SIGINT);
    const auto interrupted = std::chrono::steady_clock::now();
    const RunResult run = lancer.wait(20s);
    // The solvers check between their steps, and while a step's work is shared out.
    EXPECT_LT(std::chrono::steady_clock::now() - interrupted, 5s) << "stops promptly";

    EXPECT_EQ(run.exitStatus, 130) << run;
    EXPECT_EQ(run.errorLines(), (std::vector<std::string>{"lancer: interrupted during the "
                                                          "radiosity solve; nothing was written"}))
        << run;
    EXPECT_EQ(folder.entries(), (std::vector<std::string>{"scene.json"}))
        << "no image, no solution, no temporary file";
}

INSTANTIATE_TEST_SUITE_P(
    Methods, RadiosityInterrupt,
    testing::Values(
        // About 7 s of solving for two threads in a release build (longer under sanitizers).
        SlowSolve{"Progressive", R"({"patch_size": 1})"},
        // About 4.5 s.
        SlowSolve{"Hierarchical",
                  R"({"method": "hierarchical", "patch_size": 0.5,
                      "refinement_tolerance": 0.005})"}),
    [](const testing::TestParamInfo<SlowSolve>& solve) { return std::string(solve.param.name); });

}  // namespace
}  // namespace lancer::test

#endif
