// --resume: an interrupted render leaves OUT.resume; the same command with --resume renders only
// what is missing and gives the uninterrupted render's bytes; a resume file made for another
// render, or damaged, is refused with one line and exit status 2.

#include <gtest/gtest.h>

#include <fstream>

#include "LancerRun.h"

#ifndef _WIN32
#include <csignal>
#include <thread>

namespace lancer::test {
namespace {

// Long enough in a release build to be interrupted half a second after its start.
const std::vector<std::string> kRender = {"scene.json", "-o",        "out.pfm", "--width",
                                          "320",        "--height",  "240",     "--spp",
                                          "64",         "--threads", "2",       "--quiet"};
// The render finished twice by each bit-for-bit test: a quarter of kRender's work, so that it
// stays in seconds under AddressSanitizer on a slow machine.
const std::vector<std::string> kSmallRender = {"scene.json", "-o",        "out.pfm", "--width",
                                               "160",        "--height",  "120",     "--spp",
                                               "64",         "--threads", "2",       "--quiet"};

std::vector<std::string> with(std::vector<std::string> arguments,
                              const std::vector<std::string>& more) {
    arguments.insert(arguments.end(), more.begin(), more.end());
    return arguments;
}

// Starts `render`, interrupts it after `delay`, and returns once it has left its resume file. A
// busy machine may still be loading the scene then (nothing is written): the render is started
// again and interrupted later, twice as late each time. A machine that was busier while the delay
// was measured than now may have finished the render before the signal: it is started again and
// interrupted earlier, half as late each time.
void interruptedRender(const TempFolder& folder, const std::vector<std::string>& render,
                       std::chrono::milliseconds delay) {
    for (int attempt = 0;; ++attempt) {
        LancerProcess lancer(render, folder.path());
        std::this_thread::sleep_for(delay);
        lancer.sendSignal(SIGINT);
        const RunResult run = lancer.wait(std::chrono::seconds(30));
        if (attempt < 4 && run.exitStatus == 0) {
            fs::remove(folder / "out.pfm");
            delay /= 2;
            continue;
        }
        ASSERT_EQ(run.exitStatus, 130) << run << " (the render ended before the signal?)";
        if (attempt < 4 &&
            run.standardError.find("interrupted while loading the scene") != std::string::npos) {
            delay *= 2;
            continue;
        }
        ASSERT_TRUE(fs::exists(folder / "out.pfm.resume")) << run;
        return;
    }
}

// The parameter is when the render is interrupted, as a fraction of the time the whole render took
// just before: early and later interruptions whatever the build and the machine.
class CliResume : public testing::TestWithParam<double> {};

TEST_P(CliResume, FinishesTheImageBitForBit) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    const auto start = std::chrono::steady_clock::now();
    const RunResult whole = runLancer(kSmallRender, folder.path());
    const auto took = std::chrono::steady_clock::now() - start;
    ASSERT_EQ(whole.exitStatus, 0) << whole;
    fs::rename(folder / "out.pfm", folder / "whole.pfm");

    interruptedRender(folder, kSmallRender,
                      std::chrono::duration_cast<std::chrono::milliseconds>(took * GetParam()));
    const RunResult resumed = runLancer(with(kSmallRender, {"--resume"}), folder.path());
    ASSERT_EQ(resumed.exitStatus, 0) << resumed;
    EXPECT_EQ(readFile(folder / "out.pfm"), readFile(folder / "whole.pfm"));
    EXPECT_FALSE(fs::exists(folder / "out.pfm.resume")) << "deleted once the image is finished";
}

// Well before the end even if the machine is twice as busy during the interrupted render.
INSTANTIATE_TEST_SUITE_P(Delays, CliResume, testing::Values(0.15, 0.45));

TEST(CliResumeRefuses, AnotherRenderOrADamagedFile) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    interruptedRender(folder, kRender, std::chrono::milliseconds(500));
    const std::string saved = readFile(folder / "out.pfm.resume");

    for (const auto& option : std::vector<std::vector<std::string>>{{"--seed", "7"},
                                                                    {"--max-depth", "2"},
                                                                    {"--adc-bailout", "0.5"},
                                                                    {"--light-edge-factor", "4"},
                                                                    {"--aov", "depth"},
                                                                    {"--crop", "0,0,64,64"}}) {
        const RunResult run = runLancer(with(kRender, with(option, {"--resume"})), folder.path());
        EXPECT_EQ(run.exitStatus, 2) << option[0] << ": " << run;
        ASSERT_EQ(run.errorLines().size(), 1u) << run;
        EXPECT_NE(run.standardError.find("out.pfm.resume: error: the resume file was made for "
                                         "another render"),
                  std::string::npos)
            << run;
    }
    const auto refusedWith = [&](const std::string& bytes, const std::string& message) {
        {
            std::ofstream out(folder / "out.pfm.resume", std::ios::binary | std::ios::trunc);
            out << bytes;
        }
        const RunResult run = runLancer(with(kRender, {"--resume"}), folder.path());
        EXPECT_EQ(run.exitStatus, 2) << run;
        ASSERT_EQ(run.errorLines().size(), 1u) << run;
        EXPECT_NE(run.standardError.find(message), std::string::npos) << run;
    };
    refusedWith(saved.substr(0, saved.size() / 2), "damaged");
    std::string altered = saved;
    altered[altered.size() / 2] ^= 1;
    refusedWith(altered, "damaged");
    refusedWith("P3\n1 1\n", "not a lancer resume file");
    refusedWith("", "not a lancer resume file");
}

// A glTF model's buffers and images are files the render depends on, as the model's own file is.
TEST(CliResumeRefuses, AfterAGltfModelsBufferOrImageChanged) {
    const TempFolder folder;
    const fs::path spot = fs::path(LANCER_SOURCE_DIR) / "scenes/models/spot";
    for (const char* file : {"spot.gltf", "spot.bin", "spot_texture.png"})
        fs::copy_file(spot / file, folder / file);
    nlohmann::json scene = loadWhittedScene();
    scene["objects"].push_back({{"type", "gltf"},
                                {"file", "spot.gltf"},
                                {"transform", {{"translate", {-0.5, 0.6, 2.5}}}}});
    folder.write("scene.json", scene.dump());
    for (const char* changed : {"spot.bin", "spot_texture.png"}) {
        interruptedRender(folder, kRender, std::chrono::milliseconds(500));
        fs::last_write_time(folder / changed,
                            fs::last_write_time(folder / changed) + std::chrono::hours(1));
        const RunResult run = runLancer(with(kRender, {"--resume"}), folder.path());
        EXPECT_EQ(run.exitStatus, 2) << changed << ": " << run;
        EXPECT_NE(run.standardError.find("the resume file was made for another render"),
                  std::string::npos)
            << changed << ": " << run;
    }
}

}  // namespace
}  // namespace lancer::test

#endif
