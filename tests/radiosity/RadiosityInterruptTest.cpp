// Ctrl-C during a radiosity solve: the solver stops between shots, lancer says so in one line and
// exits 130, and writes nothing: no image (nothing was rendered), no saved solution, no temporary
// file.

#include <gtest/gtest.h>

#include "LancerRun.h"

#ifndef _WIN32
#include <csignal>
#include <thread>

namespace lancer::test {
namespace {

using namespace std::chrono_literals;

TEST(RadiosityInterrupt, CtrlCDuringTheSolveWritesNothingAndExits130) {
    // The Whitted scene solved with patches of 1: about 7 s of solving for two threads in a
    // release build (longer under sanitizers), far more than the delay before Ctrl-C.
    nlohmann::json scene = loadWhittedScene();
    scene["render"]["integrator"] = "radiosity";
    scene["radiosity"] = {{"patch_size", 1}};
    const TempFolder folder;
    folder.write("scene.json", scene.dump());
    LancerProcess lancer({"scene.json", "-o", "out.png", "--width", "32", "--height", "24",
                          "--threads", "2", "--save-radiosity", "solution.rad"},
                         folder.path());
    std::this_thread::sleep_for(1s);
    lancer.sendSignal(SIGINT);
    const auto interrupted = std::chrono::steady_clock::now();
    const RunResult run = lancer.wait(20s);
    // The solver checks between shots, and while a shot's work is shared out: a shot takes
    // milliseconds.
    EXPECT_LT(std::chrono::steady_clock::now() - interrupted, 5s) << "stops promptly";

    EXPECT_EQ(run.exitStatus, 130) << run;
    EXPECT_EQ(run.errorLines(), (std::vector<std::string>{"lancer: interrupted during the "
                                                          "radiosity solve; nothing was written"}))
        << run;
    EXPECT_EQ(folder.entries(), (std::vector<std::string>{"scene.json"}))
        << "no image, no solution, no temporary file";
}

}  // namespace
}  // namespace lancer::test

#endif
