// Animations on the command line: every frame of the scene's "animation" (or those --frames
// names) rendered to OUT-0001.EXT..., each the same bytes as the still scene of that frame;
// --resume keeps the frames finished and finishes the one interrupted; mistakes refused with one
// line and exit status 2.

#include <gtest/gtest.h>

#include <fstream>

#include "LancerRun.h"

#ifndef _WIN32
#include <csignal>
#include <thread>
#endif

namespace lancer::test {
namespace {

using json = nlohmann::json;

// Frame 2 of animatedWhittedScene() as a still: halfway.
json middleFrame() {
    json scene = loadWhittedScene();
    scene["camera"]["position"] = {0, 2, 7};
    scene["objects"][2]["transform"] = {{"translate", {0, 0, 0}}};
    return scene;
}

const std::vector<std::string> kSmall = {"--width", "80", "--height", "60", "--spp", "4"};

std::vector<std::string> command(const std::vector<std::string>& more) {
    std::vector<std::string> arguments = {"scene.json", "-o", "out.pfm", "--quiet"};
    arguments.insert(arguments.end(), kSmall.begin(), kSmall.end());
    arguments.insert(arguments.end(), more.begin(), more.end());
    return arguments;
}

TEST(CliAnimation, RendersEveryFrameToItsNumberedOutput) {
    const TempFolder folder;
    folder.write("scene.json", animatedWhittedScene().dump());
    const RunResult run = runLancer(command({}), folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    for (const char* frame : {"out-0001.pfm", "out-0002.pfm", "out-0003.pfm"})
        EXPECT_TRUE(fs::exists(folder / frame)) << frame;
    EXPECT_FALSE(fs::exists(folder / "out.pfm"));
    EXPECT_FALSE(fs::exists(folder / "out-0004.pfm"));
    // Each frame is the still scene at that frame, bit for bit.
    EXPECT_EQ(readFile(folder / "out-0002.pfm"), renderScene(middleFrame(), kSmall).bytes);
    EXPECT_NE(readFile(folder / "out-0001.pfm"), readFile(folder / "out-0003.pfm"));
}

TEST(CliAnimation, RendersOnlyTheFramesAsked) {
    const TempFolder folder;
    folder.write("scene.json", animatedWhittedScene().dump());
    const RunResult range = runLancer(command({"--frames", "2:3"}), folder.path());
    ASSERT_EQ(range.exitStatus, 0) << range;
    EXPECT_FALSE(fs::exists(folder / "out-0001.pfm"));
    EXPECT_TRUE(fs::exists(folder / "out-0003.pfm"));
    const std::string second = readFile(folder / "out-0002.pfm");
    fs::remove(folder / "out-0002.pfm");
    fs::remove(folder / "out-0003.pfm");

    const RunResult one = runLancer(command({"--frames", "2"}), folder.path());
    ASSERT_EQ(one.exitStatus, 0) << one;
    EXPECT_EQ(readFile(folder / "out-0002.pfm"), second);
    EXPECT_FALSE(fs::exists(folder / "out-0003.pfm"));
}

TEST(CliAnimation, RefusesFramesItCannotRender) {
    const TempFolder folder;
    folder.write("scene.json", animatedWhittedScene().dump());
    folder.write("still.json", loadWhittedScene().dump());
    const auto refused = [&](const std::vector<std::string>& arguments,
                             const std::string& mention) {
        const RunResult run = runLancer(arguments, folder.path());
        EXPECT_EQ(run.exitStatus, 2) << run;
        ASSERT_EQ(run.errorLines().size(), 1u) << run;
        EXPECT_NE(run.standardError.find(mention), std::string::npos) << run;
        EXPECT_FALSE(fs::exists(folder / "out-0001.pfm")) << run;
    };
    for (const char* frames : {"0:2", "3:2", "2:4", "4", "x", "2:", "1:2:3", ":2"})
        refused(command({"--frames", frames}), "--frames");
    refused(command({"--frames", "2:4"}), "1 <= A <= B <= 3");
    refused({"still.json", "-o", "out.pfm", "--frames", "1"}, "is not animated");
    refused(command({"--window"}), "--window shows one image");
    refused(command({"--integrator", "radiosity", "--save-radiosity", "solution.bin"}),
            "keep the solution of one frame");
}

TEST(CliAnimation, ResumeKeepsTheFramesFinished) {
    const TempFolder folder;
    folder.write("scene.json", animatedWhittedScene().dump());
    const RunResult whole = runLancer(command({}), folder.path());
    ASSERT_EQ(whole.exitStatus, 0) << whole;
    const std::string third = readFile(folder / "out-0003.pfm");
    // Frame 1 finished (here marked, to see that it is kept), frame 3 never started.
    folder.write("out-0001.pfm", "kept");
    fs::remove(folder / "out-0003.pfm");
    fs::rename(folder / "out-0002.pfm", folder / "second.pfm");

    const RunResult resumed = runLancer(command({"--resume"}), folder.path());
    ASSERT_EQ(resumed.exitStatus, 0) << resumed;
    EXPECT_EQ(readFile(folder / "out-0001.pfm"), "kept");
    EXPECT_EQ(readFile(folder / "out-0002.pfm"), readFile(folder / "second.pfm"));
    EXPECT_EQ(readFile(folder / "out-0003.pfm"), third);
}

#ifndef _WIN32
TEST(CliAnimation, AnInterruptedAnimationResumesBitForBit) {
    const TempFolder folder;
    folder.write("scene.json", animatedWhittedScene().dump());
    const std::vector<std::string> render = {"scene.json", "-o",  "out.pfm", "--width", "240",
                                             "--height",   "180", "--spp",   "12",      "--quiet"};
    const RunResult whole = runLancer(render, folder.path());
    ASSERT_EQ(whole.exitStatus, 0) << whole;
    std::vector<std::string> frames;
    for (const char* name : {"out-0001.pfm", "out-0002.pfm", "out-0003.pfm"}) {
        frames.push_back(readFile(folder / name));
        fs::remove(folder / name);
    }

    {
        LancerProcess lancer(render, folder.path());
        // Until the first frame is written: then the second is being rendered.
        for (int wait = 0; wait < 600 && !fs::exists(folder / "out-0001.pfm"); ++wait)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        lancer.sendSignal(SIGINT);
        const RunResult interrupted = lancer.wait(std::chrono::seconds(30));
        ASSERT_EQ(interrupted.exitStatus, 130) << interrupted;
    }
    EXPECT_TRUE(fs::exists(folder / "out-0002.pfm.resume")) << "the frame it was on";
    EXPECT_FALSE(fs::exists(folder / "out-0003.pfm")) << "the frames after it are not started";
    std::vector<std::string> resume = render;
    resume.push_back("--resume");
    const RunResult resumed = runLancer(resume, folder.path());
    ASSERT_EQ(resumed.exitStatus, 0) << resumed;
    EXPECT_EQ(readFile(folder / "out-0001.pfm"), frames[0]);
    EXPECT_EQ(readFile(folder / "out-0002.pfm"), frames[1]);
    EXPECT_EQ(readFile(folder / "out-0003.pfm"), frames[2]);
    for (const char* name : {"out-0001.pfm.resume", "out-0002.pfm.resume", "out-0003.pfm.resume"})
        EXPECT_FALSE(fs::exists(folder / name)) << name;
}
#endif

}  // namespace
}  // namespace lancer::test
