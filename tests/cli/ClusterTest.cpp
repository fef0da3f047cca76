// mpirun -np N lancer ...: the processes share out the tiles, the leader writes the output, and
// the file is the same, byte for byte, as one process's, for every integrator and N. Ctrl-C under
// mpirun saves what was finished (and --resume under mpirun finishes it), a scene error is
// reported once, and a process killed mid-render stops the run within seconds.

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <thread>

#include "LancerRun.h"

namespace lancer::test {
namespace {

// mpirun, with as many processes as asked on this machine whatever its cores; Open MPI refuses
// to run as root (CI's containers) unless told.
std::vector<std::string> mpirun(int processes, const std::vector<std::string>& arguments) {
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    std::vector<std::string> all = {"--oversubscribe", "-np", std::to_string(processes),
                                    LANCER_EXE};
    all.insert(all.end(), arguments.begin(), arguments.end());
    return all;
}

RunResult runUnderMpirun(int processes, const std::vector<std::string>& arguments,
                         const fs::path& folder) {
    return LancerProcess(mpirun(processes, arguments), folder, 0, LANCER_MPIRUN).wait();
}

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

struct ClusterCase {
    std::string name;
    std::vector<std::string> options;  // besides the scene, the output and --quiet
    nlohmann::json render;             // merged into the whitted scene's "render" block
    std::string output = "out.pfm";
};

std::ostream& operator<<(std::ostream& out, const ClusterCase& c) {
    return out << c.name;
}

const std::vector<std::string> kSmall = {"--width", "96", "--height", "72", "--spp", "4"};

class CliCluster : public testing::TestWithParam<ClusterCase> {};

TEST_P(CliCluster, TwoThreeAndFourProcessesWriteTheBytesOfOne) {
    const ClusterCase& c = GetParam();
    nlohmann::json scene = loadWhittedScene();
    scene["render"].merge_patch(c.render);
    // A short radiosity solve: each process solves it, identically.
    scene["radiosity"] = {{"max_shots", 40}};
    const TempFolder folder;
    folder.write("scene.json", scene.dump());
    const std::vector<std::string> arguments =
        concat({"scene.json", "-o", c.output, "--quiet", "--threads", "1"}, c.options);
    const RunResult alone = runLancer(arguments, folder.path());
    ASSERT_EQ(alone.exitStatus, 0) << alone;
    const std::string expected = readFile(folder / c.output);
    for (const int processes : {2, 3, 4}) {
        fs::remove(folder / c.output);
        const RunResult run = runUnderMpirun(processes, arguments, folder.path());
        ASSERT_EQ(run.exitStatus, 0) << processes << " processes: " << run;
        EXPECT_TRUE(readFile(folder / c.output) == expected)
            << processes << " processes: the file differs from one process's";
    }
}

INSTANTIATE_TEST_SUITE_P(
    Renders, CliCluster,
    testing::Values(
        ClusterCase{"Whitted", kSmall, nlohmann::json::object()},
        ClusterCase{"WhittedPng", kSmall, nlohmann::json::object(), "out.png"},
        ClusterCase{"Path", concat(kSmall, {"--integrator", "path"}), nlohmann::json::object()},
        ClusterCase{"PathAdaptive",
                    {"--width", "96", "--height", "72", "--spp", "32", "--integrator", "path"},
                    {{"adaptive", {{"min_spp", 4}, {"threshold", 0.05}}}}},
        ClusterCase{"Radiosity", concat(kSmall, {"--integrator", "radiosity"}),
                    nlohmann::json::object()},
        ClusterCase{
            "CropSeedAndAuxiliaryOutputs",
            concat(kSmall, {"--crop", "10,5,70,60", "--seed", "9", "--aov", "albedo,normal,depth"}),
            nlohmann::json::object()}),
    CaseName());

TEST(CliClusterOutputs, TheAuxiliaryOutputsAreTheOnesOfOneProcess) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    const std::vector<std::string> arguments =
        concat({"scene.json", "-o", "out.pfm", "--quiet", "--aov", "albedo,depth"}, kSmall);
    ASSERT_EQ(runLancer(arguments, folder.path()).exitStatus, 0);
    const std::string albedo = readFile(folder / "out.albedo.exr");
    const std::string depth = readFile(folder / "out.depth.exr");
    const RunResult run = runUnderMpirun(3, arguments, folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    EXPECT_TRUE(readFile(folder / "out.albedo.exr") == albedo);
    EXPECT_TRUE(readFile(folder / "out.depth.exr") == depth);
}

// An animation's frames, each shared out tile by tile; radiosity solved again for each frame, by
// every process alike. --resume under mpirun keeps the frames finished.
TEST(CliClusterAnimation, TheFramesAreTheOnesOfOneProcess) {
    nlohmann::json scene = animatedWhittedScene();
    scene["radiosity"] = {{"max_shots", 40}};
    const TempFolder folder;
    folder.write("scene.json", scene.dump());
    const std::vector<std::string> arguments =
        concat({"scene.json", "-o", "out.pfm", "--quiet", "--integrator", "radiosity"}, kSmall);
    ASSERT_EQ(runLancer(arguments, folder.path()).exitStatus, 0);
    const std::vector<std::string> names = {"out-0001.pfm", "out-0002.pfm", "out-0003.pfm"};
    std::vector<std::string> alone;
    for (const std::string& name : names) {
        alone.push_back(readFile(folder / name));
        fs::remove(folder / name);
    }
    const RunResult run = runUnderMpirun(3, arguments, folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    for (std::size_t i = 0; i < names.size(); ++i)
        EXPECT_TRUE(readFile(folder / names[i]) == alone[i]) << names[i] << " differs";

    folder.write("out-0001.pfm", "kept");
    fs::remove(folder / "out-0003.pfm");
    const RunResult resumed = runUnderMpirun(2, concat(arguments, {"--resume"}), folder.path());
    ASSERT_EQ(resumed.exitStatus, 0) << resumed;
    EXPECT_EQ(readFile(folder / "out-0001.pfm"), "kept");
    EXPECT_TRUE(readFile(folder / "out-0003.pfm") == alone[2]);
}

TEST(CliClusterErrors, ASceneErrorIsReportedOnceWithStatus2) {
    const TempFolder folder;
    folder.write("scene.json", R"({"camera": {"fov": 40}, "bogus": 1})");
    const RunResult run = runUnderMpirun(3, {"scene.json", "-o", "out.png"}, folder.path());
    EXPECT_EQ(run.exitStatus, 2) << run;
    int reports = 0;
    for (const std::string& line : run.errorLines())
        reports += line.find("error: unknown key \"bogus\"") != std::string::npos ? 1 : 0;
    EXPECT_EQ(reports, 1) << run;
    EXPECT_FALSE(fs::exists(folder / "out.png"));
}

TEST(CliClusterErrors, WindowIsRefusedUnderMpirun) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    const RunResult run = runUnderMpirun(
        2, concat({"scene.json", "-o", "out.png", "--window"}, kSmall), folder.path());
    EXPECT_EQ(run.exitStatus, 2) << run;
    int reports = 0;
    for (const std::string& line : run.errorLines())
        reports += line.find("--window") != std::string::npos ? 1 : 0;
    EXPECT_EQ(reports, 1) << run;
}

// A render that takes some four seconds on three processes of one thread on the build machine
// (a Ctrl-C sent a second into it must find it still rendering, on a machine twice as fast).
std::vector<std::string> longRender(int threads = 1) {
    return {"scene.json",
            "-o",
            "out.pfm",
            "--width",
            "320",
            "--height",
            "240",
            "--spp",
            "128",
            "--threads",
            std::to_string(threads),
            "--quiet"};
}

// The lancer processes mpirun started (its children), newest last.
std::vector<int> childrenOf(int parent) {
    std::vector<int> children;
    for (const fs::directory_entry& entry : fs::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::ifstream stat(entry.path() / "stat");
        std::string pid, command, state;
        int parentPid = 0;
        if (stat >> pid >> command >> state >> parentPid && parentPid == parent &&
            command == "(lancer)")
            children.push_back(std::stoi(pid));
    }
    std::sort(children.begin(), children.end());
    return children;
}

// Whether the process has its own handler for the signal (the SigCgt mask of /proc/PID/status).
bool catches(int pid, int signal) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("SigCgt:", 0) == 0)
            return (std::stoull(line.substr(7), nullptr, 16) >> (signal - 1) & 1) != 0;
    return false;
}

// Waits (up to 20 s) until mpirun has started `count` lancer processes, each with its interrupt
// handler in place: a signal sent sooner, on a loaded machine, would end a process that has not
// yet started rendering. Returns them, newest last.
std::vector<int> waitForRenderingProcesses(int mpirunPid, std::size_t count) {
    std::vector<int> processes;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (std::chrono::steady_clock::now() < deadline) {
        processes = childrenOf(mpirunPid);
        if (processes.size() == count && std::all_of(processes.begin(), processes.end(),
                                                     [](int pid) { return catches(pid, SIGTERM); }))
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return processes;
}

TEST(CliClusterInterrupt, CtrlCSavesTheFinishedTilesAndResumeFinishesThemBitForBit) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    // The reference on every core, to save time: the image does not depend on the threads.
    const RunResult whole = runLancer(longRender(0), folder.path());
    ASSERT_EQ(whole.exitStatus, 0) << whole;
    fs::rename(folder / "out.pfm", folder / "whole.pfm");
    {
        // mpirun turns the Ctrl-C into SIGTERM for every process, and reports its own status.
        LancerProcess run(mpirun(3, longRender()), folder.path(), 0, LANCER_MPIRUN);
        ASSERT_EQ(waitForRenderingProcesses(run.pid(), 3).size(), 3u)
            << "mpirun did not start three lancer processes";
        // Long enough for the scene to load and some tiles to finish; the render takes seconds.
        std::this_thread::sleep_for(std::chrono::milliseconds(700));
        run.sendSignal(SIGINT);
        const RunResult stopped = run.wait();
        ASSERT_FALSE(stopped.timedOut) << stopped;
        ASSERT_NE(stopped.standardError.find("lancer: interrupted; the part rendered so far"),
                  std::string::npos)
            << stopped << " (the render ended before the signal?)";
    }
    ASSERT_TRUE(fs::exists(folder / "out.pfm.resume"));
    const Image partial = loadImage(folder / "out.pfm");
    EXPECT_EQ(partial.width, 320);
    const RunResult resumed = runUnderMpirun(3, concat(longRender(), {"--resume"}), folder.path());
    ASSERT_EQ(resumed.exitStatus, 0) << resumed;
    EXPECT_TRUE(readFile(folder / "out.pfm") == readFile(folder / "whole.pfm"));
    EXPECT_FALSE(fs::exists(folder / "out.pfm.resume"));
}

TEST(CliClusterInterrupt, AKilledProcessStopsTheRunWithinSeconds) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    LancerProcess run(mpirun(3, longRender()), folder.path(), 0, LANCER_MPIRUN);
    const std::vector<int> processes = waitForRenderingProcesses(run.pid(), 3);
    ASSERT_EQ(processes.size(), 3u) << "mpirun did not start three lancer processes";
    std::this_thread::sleep_for(std::chrono::milliseconds(1000));
    kill(processes.back(), SIGKILL);
    const auto killed = std::chrono::steady_clock::now();
    const RunResult stopped = run.wait(std::chrono::seconds(30));
    ASSERT_FALSE(stopped.timedOut) << stopped;
    EXPECT_LT(std::chrono::steady_clock::now() - killed, std::chrono::seconds(10));
    EXPECT_NE(stopped.exitStatus, 0) << stopped;
    // mpirun names the process that died.
    EXPECT_NE(stopped.standardError.find("signal 9"), std::string::npos) << stopped;
    // No damaged output: none, or a whole image.
    if (fs::exists(folder / "out.pfm")) {
        EXPECT_EQ(loadImage(folder / "out.pfm").width, 320);
    }
}

}  // namespace
}  // namespace lancer::test
