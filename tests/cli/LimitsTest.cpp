// The limits of docs/SCENE-FORMAT.md ("Limits"): the largest accepted values work, within a
// bounded time and memory, and the first refused ones are one line and exit status 2 before any
// work (ErrorTest checks the messages of the refused ones).

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>

#include "LancerRun.h"
#include "scene/RenderSettings.h"

namespace lancer::test {
namespace {

using nlohmann::json;

// The camera between two parallel mirrors, looking at one of them: every ray bounces until the
// depth limit stops it.
json facingMirrors(int maxDepth, const std::string& integrator) {
    json scene = json::parse(R"({
      "render": { "width": 4, "height": 4, "spp": 1 },
      "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1], "vfov": 30 },
      "materials": { "mirror": { "diffuse": 0, "reflection": 1 } },
      "objects": [
        { "type": "plane", "point": [0, 0, -1], "normal": [0, 0, 1], "material": "mirror" },
        { "type": "plane", "point": [0, 0, 1], "normal": [0, 0, -1], "material": "mirror" }
      ],
      "lights": [ { "type": "point", "position": [0, 0, 0.5], "intensity": 1 } ]
    })");
    scene["render"]["max_depth"] = maxDepth;
    scene["render"]["integrator"] = integrator;
    return scene;
}

class CliDepthLimit : public testing::TestWithParam<std::string> {};

// Whitted recursion takes stack per bounce, and a path between perfect mirrors never ends by
// Russian roulette (its throughput stays 1): at the deepest accepted depth both follow every
// bounce and end, in the stack the program gives its render threads.
TEST_P(CliDepthLimit, TheDeepestAcceptedDepthIsFollowedToItsEnd) {
    const TempFolder folder;
    folder.write("scene.json", facingMirrors(RenderSettings::kMaxDepthLimit, GetParam()).dump());
    const RunResult run = runLancer({"scene.json", "-o", "out.pfm", "--stats"}, folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    // One camera ray and one per bounce for each of the 16 pixels; mirrors take no shadow rays.
    const std::string rays =
        "stats: " + std::to_string(16 * (RenderSettings::kMaxDepthLimit + 1)) + " rays";
    EXPECT_NE(run.standardError.find(rays), std::string::npos) << run;
}

// The largest image accepted, with a float output: its buffers (the 12-byte film, the writer's
// bitmap and file of as much) take about 38.7 GB, more than the machines this suite runs on. It
// is refused with one line before anything is allocated; rendering would take hours.
TEST(CliImageLimit, AnImageLargerThanTheMemoryIsRefusedBeforeAnyWork) {
    constexpr int kSide = RenderSettings::kMaxImageSide;
    const std::uint64_t needed = 36ull * kSide * kSide;
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    if (static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize) >= needed)
        GTEST_SKIP() << "this machine has the memory for the largest image";
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    const RunResult run = runLancer({"scene.json", "-o", "out.pfm", "--width",
                                     std::to_string(kSide), "--height", std::to_string(kSide)},
                                    folder.path(), std::chrono::seconds(10));
    EXPECT_EQ(run.exitStatus, 2) << run;
    const std::vector<std::string> lines = run.errorLines();
    ASSERT_EQ(lines.size(), 1u) << run;
    EXPECT_EQ(lines[0].rfind("lancer: error: a 32768 x 32768 image needs about 38.7 GB of memory "
                             "for its buffers, more than the ",
                             0),
              0u)
        << lines[0];
    const std::string override = " this machine has (--max-memory overrides)";
    EXPECT_EQ(lines[0].substr(lines[0].size() - override.size()), override) << lines[0];
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"scene.json"});
}

// --max-memory replaces the machine's memory as the bound, both ways: a 1000 x 1000 PNG needs
// 18 MB (12 bytes a pixel for the film, 2 x 3 for the writer), so 17.9M refuses it in one line
// before any work and 18M lets it render (one pixel of it, by --crop: the buffers are the whole
// image's all the same).
TEST(CliImageLimit, MaxMemoryReplacesTheMachinesMemory) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    const std::vector<std::string> image = {"scene.json", "-o",   "out.png", "--width", "1000",
                                            "--height",   "1000", "--crop",  "0,0,1,1", "--quiet"};
    std::vector<std::string> arguments = image;
    arguments.insert(arguments.end(), {"--max-memory", "17.9M"});
    const RunResult refused = runLancer(arguments, folder.path(), std::chrono::seconds(10));
    EXPECT_EQ(refused.exitStatus, 2) << refused;
    EXPECT_EQ(refused.errorLines(),
              std::vector<std::string>{"lancer: error: a 1000 x 1000 image needs about 18.0 MB of "
                                       "memory for its buffers, more than the 17.9 MB "
                                       "--max-memory allows"});
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"scene.json"});

    arguments = image;
    arguments.insert(arguments.end(), {"--max-memory", "18m"});
    const RunResult rendered = runLancer(arguments, folder.path());
    EXPECT_EQ(rendered.exitStatus, 0) << rendered;
    EXPECT_EQ(loadImage(folder / "out.png").width, 1000);
}

// Each auxiliary output adds its film and its EXR's bitmap and file (36 bytes a pixel again).
TEST(CliImageLimit, TheAuxiliaryOutputsCountInTheMemoryNeeded) {
    constexpr int kSide = RenderSettings::kMaxImageSide;
    const std::uint64_t needed = 4 * 36ull * kSide * kSide;
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    if (static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize) >= needed)
        GTEST_SKIP() << "this machine has the memory for the largest image and its outputs";
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    const RunResult run =
        runLancer({"scene.json", "-o", "out.pfm", "--width", std::to_string(kSide), "--height",
                   std::to_string(kSide), "--aov", "albedo,normal,depth"},
                  folder.path(), std::chrono::seconds(10));
    EXPECT_EQ(run.exitStatus, 2) << run;
    EXPECT_NE(run.standardError.find("image needs about 154.6 GB of memory"), std::string::npos)
        << run;
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"scene.json"});
}

// Inputs that would grow memory without end: a device read as a scene, an OBJ or an MTL file,
// and files larger than their limits (sparse files: their size costs no disk). Each is refused
// with one line and exit status 2 within a second, and nothing is written.
struct InputCase {
    std::string name;
    std::string sceneArgument;  // the scene file given to lancer
    std::string objects;        // the scene's "objects", when the scene is scene.json
    std::string expectedLine;
};

std::ostream& operator<<(std::ostream& out, const InputCase& c) {
    return out << c.name;
}

class CliInputSizeLimit : public testing::TestWithParam<InputCase> {};

TEST_P(CliInputSizeLimit, IsRefusedWithOneLineBeforeItIsRead) {
    const InputCase& c = GetParam();
    const TempFolder folder;
    folder.write("scene.json", R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
  "objects": [)" + c.objects + "] }");
    folder.write("uses-zero.obj", "mtllib /dev/zero\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    for (const auto& [name, size] : {std::pair{"huge.json", 2ull << 30}, {"huge.obj", 5ull << 30}})
        ASSERT_EQ(truncate(folder.write(name, "").c_str(), static_cast<off_t>(size)), 0) << name;
    const RunResult run =
        runLancer({c.sceneArgument, "-o", "out.png"}, folder.path(), std::chrono::seconds(10));
    EXPECT_EQ(run.exitStatus, 2) << run;
    const std::vector<std::string> lines = run.errorLines();
    ASSERT_EQ(lines.size(), 1u) << run;
    EXPECT_EQ(lines[0], c.expectedLine);
    EXPECT_FALSE(fs::exists(folder / "out.png"));
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, CliInputSizeLimit,
    testing::Values(
        InputCase{"DeviceAsTheScene", "/dev/zero", "",
                  "/dev/zero: error: is a device, not a scene file"},
        InputCase{"SceneLargerThanItsLimit", "huge.json", "",
                  "huge.json: error: is larger than the 1 GiB limit for scene files"},
        InputCase{"DeviceAsAModel", "scene.json", R"({ "type": "mesh", "file": "/dev/zero" })",
                  R"(scene.json:2:41: error: mesh "/dev/zero": is a device, not an OBJ file)"},
        InputCase{
            "ModelLargerThanItsLimit", "scene.json", R"({ "type": "mesh", "file": "huge.obj" })",
            R"(scene.json:2:41: error: mesh "huge.obj": is larger than the 4 GiB limit for OBJ files)"},
        InputCase{
            "DeviceAsAMaterialLibrary", "scene.json",
            R"({ "type": "mesh", "file": "uses-zero.obj" })",
            R"(scene.json:2:41: error: mesh "uses-zero.obj": mtllib "/dev/zero": is a device, not an MTL file)"}),
    [](const testing::TestParamInfo<InputCase>& test) { return test.param.name; });

INSTANTIATE_TEST_SUITE_P(Integrators, CliDepthLimit, testing::Values("whitted", "path"),
                         [](const testing::TestParamInfo<std::string>& test) {
                             return test.param;
                         });

}  // namespace
}  // namespace lancer::test
