// Command-line options that change what is rendered: --crop, the overrides of the scene's
// "render" block, the default output name, --help and --version.

#include <gtest/gtest.h>

#include <cstdlib>

#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>

#include "LancerRun.h"
#include "io/SceneLoader.h"

namespace lancer::test {
namespace {

using nlohmann::json;

// The Whitted scene at a small size, one sample per pixel.
json smallWhittedScene() {
    json scene = loadWhittedScene();
    scene["render"] = {{"width", 64}, {"height", 48}, {"spp", 1}, {"max_depth", 5}};
    return scene;
}

// --- --crop ---

struct CropCase {
    std::string name;
    int x0, y0, x1, y1;
};

std::ostream& operator<<(std::ostream& out, const CropCase& c) {
    return out << c.name;
}

class CliCrop : public testing::TestWithParam<CropCase> {};

TEST_P(CliCrop, InsideTheWindowIsTheFullRenderOutsideIsBlack) {
    const CropCase& crop = GetParam();
    const json scene = smallWhittedScene();
    const Image full = renderScene(scene).image;
    const Image cropped =
        renderScene(scene,
                    {"--crop", std::to_string(crop.x0) + "," + std::to_string(crop.y0) + "," +
                                   std::to_string(crop.x1) + "," + std::to_string(crop.y1)})
            .image;
    ASSERT_EQ(cropped.width, full.width);
    ASSERT_EQ(cropped.height, full.height);

    // Exactly: a pixel's value depends on the scene, the seed and the pixel only.
    int mismatches = 0;
    for (int y = 0; y < full.height; ++y)
        for (int x = 0; x < full.width; ++x) {
            const bool inside = crop.x0 <= x && x < crop.x1 && crop.y0 <= y && y < crop.y1;
            const Image::Rgb expected = inside ? full.at(x, y) : Image::Rgb{0, 0, 0};
            if (cropped.at(x, y) != expected && ++mismatches <= 5)
                ADD_FAILURE() << "pixel (" << x << ", " << y << ") "
                              << (inside ? "inside" : "outside") << " the window";
        }
    EXPECT_EQ(mismatches, 0);
}

INSTANTIATE_TEST_SUITE_P(Windows, CliCrop,
                         testing::Values(CropCase{"Interior", 10, 6, 50, 30},
                                         CropCase{"BottomRightCorner", 40, 20, 64, 48},
                                         CropCase{"OnePixel", 17, 33, 18, 34},
                                         CropCase{"WholeImage", 0, 0, 64, 48}),
                         CaseName());

// --- overrides of the scene's "render" block ---

struct OverrideCase {
    std::string name;
    std::string option;  // the command-line option
    std::string key;     // the key of "render" that it overrides
    int value;
};

std::ostream& operator<<(std::ostream& out, const OverrideCase& c) {
    return out << c.name;
}

class CliOverride : public testing::TestWithParam<OverrideCase> {};

TEST_P(CliOverride, OptionRendersWhatTheSceneWouldWithThatValue) {
    const OverrideCase& param = GetParam();
    const json scene = smallWhittedScene();
    json sceneWithValue = scene;
    sceneWithValue["render"][param.key] = param.value;

    const std::string overridden =
        renderScene(scene, {param.option, std::to_string(param.value)}).bytes;
    EXPECT_TRUE(overridden == renderScene(sceneWithValue).bytes)
        << param.option << " " << param.value << " renders as \"" << param.key
        << "\": " << param.value;
    EXPECT_FALSE(overridden == renderScene(scene).bytes)
        << "the value changes the picture (else this test proves nothing)";
}

INSTANTIATE_TEST_SUITE_P(Options, CliOverride,
                         testing::Values(OverrideCase{"Width", "--width", "width", 40},
                                         OverrideCase{"Height", "--height", "height", 30},
                                         OverrideCase{"Spp", "--spp", "spp", 4},
                                         OverrideCase{"MaxDepth", "--max-depth", "max_depth", 0},
                                         OverrideCase{"AdcBailout", "--adc-bailout", "adc_bailout",
                                                      1}),
                         CaseName());

TEST(CliIntegratorOption, OverridesTheScenes) {
    // "path" and "radiosity" come with later work; overriding them by whitted must already work.
    json scene = smallWhittedScene();
    scene["render"]["integrator"] = "path";
    const std::string overridden = renderScene(scene, {"--integrator", "whitted"}).bytes;
    EXPECT_TRUE(overridden == renderScene(smallWhittedScene()).bytes);
}

// --- the default output ---

TEST(CliDefaultOutput, IsTheScenePathWithPng) {
    const TempFolder folder;
    folder.write("scenes/my.scene.json", smallWhittedScene().dump());
    const RunResult run = runLancer({"scenes/my.scene.json", "--quiet"}, folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    EXPECT_EQ(folder.entries("scenes"),
              (std::vector<std::string>{"my.scene.json", "my.scene.png"}));
    const Image image = loadImage(folder / "scenes/my.scene.png");
    EXPECT_EQ(image.encoding, Image::Encoding::EightBit);
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 48);
}

// --- --help and --version ---

TEST(CliHelp, ListsEveryOptionOfTheContract) {
    const TempFolder folder;
    const RunResult run = runLancer({"--help"}, folder.path());
    EXPECT_EQ(run.exitStatus, 0) << run;
    for (const char* option :
         {"--output", "--width", "--height", "--spp", "--max-depth", "--integrator", "--threads",
          "--seed", "--crop", "--aov", "--window", "--quiet", "--help", "--version"})
        EXPECT_NE(run.standardOutput.find(option), std::string::npos) << option;
}

// The tables the scene loader reads are the lists --help and the documentation give.
TEST(CliHelp, ListsWhatAScenesCanNameAsTheDocumentationDoes) {
    const TempFolder folder;
    const RunResult run = runLancer({"--help"}, folder.path());
    std::ifstream file(fs::path(LANCER_SOURCE_DIR) / "docs/SCENE-FORMAT.md");
    const std::string documentation((std::istreambuf_iterator<char>(file)),
                                    std::istreambuf_iterator<char>());
    ASSERT_FALSE(documentation.empty());
    for (const SceneLoader::Vocabulary& v : SceneLoader::vocabulary()) {
        std::string line = "  " + v.what + ":";
        for (const std::string& name : v.names) {
            line += " " + name;
            EXPECT_TRUE(documentation.find("`" + name + "`") != std::string::npos ||
                        documentation.find("\"" + name + "\"") != std::string::npos)
                << v.what << " " << name << " is not in docs/SCENE-FORMAT.md";
        }
        EXPECT_NE(run.standardOutput.find(line + "\n"), std::string::npos) << line;
    }
}

TEST(CliHelp, DescribesWhatLancerIs) {
    const TempFolder folder;
    const std::string help = runLancer({"--help"}, folder.path()).standardOutput;
    EXPECT_EQ(help.find("Whitted-style"), std::string::npos) << help;
    for (const char* fragment : {"Whitted ray tracing", "path tracing", "radiosity"})
        EXPECT_NE(help.find(fragment), std::string::npos) << fragment;
}

TEST(CliVersion, PrintsTheVersion) {
    const TempFolder folder;
    const RunResult run = runLancer({"--version"}, folder.path());
    EXPECT_EQ(run.exitStatus, 0) << run;
    EXPECT_EQ(run.standardOutput.rfind("lancer ", 0), 0u) << run.standardOutput;
}

TEST(CliVersion, SaysTheBuildAndTheLibraries) {
    const TempFolder folder;
    const std::string version = runLancer({"--version"}, folder.path()).standardOutput;
    EXPECT_TRUE(version.find("built with GCC ") != std::string::npos ||
                version.find("built with Clang ") != std::string::npos ||
                version.find("built with MSVC ") != std::string::npos)
        << version;
    // The MPI library the build found (LANCER_MPIRUN: the cluster's tests are built), or none.
#ifdef LANCER_MPIRUN
    EXPECT_NE(version.find(", with Open MPI v"), std::string::npos) << version;
#else
    EXPECT_NE(version.find(", without MPI\n"), std::string::npos) << version;
#endif
    for (const char* library :
         {"FreeImage 3.", "nlohmann-json 3.", "tinyobjloader ", "SDL2 2.", "oneTBB 20", "CLI11 2."})
        EXPECT_NE(version.find(library), std::string::npos) << library << " in " << version;
#if LANCER_WITH_OPENEXR  // OpenEXR, whose thread pool compresses EXR files, if the build found it
    EXPECT_NE(version.find(", OpenEXR 3."), std::string::npos) << version;
#else
    EXPECT_EQ(version.find("OpenEXR"), std::string::npos) << version;
#endif
}

// The kernels chosen by the CPU give the image of the baseline ones, byte for byte; the
// environment's LANCER_SIMD=baseline asks for those, and --version says which run.
#ifndef _WIN32  // setenv
TEST(CliSimd, TheBaselineKernelsGiveTheSameImage) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    const std::vector<std::string> render{"scene.json", "--width", "96", "--height",
                                          "72",         "--spp",   "2",  "--quiet"};
    const auto withOutput = [&](const std::string& output) {
        std::vector<std::string> arguments = render;
        arguments.insert(arguments.end(), {"-o", output});
        return arguments;
    };
    ASSERT_EQ(runLancer(withOutput("best.pfm"), folder.path()).exitStatus, 0);
    const std::string bestVersion = runLancer({"--version"}, folder.path()).standardOutput;
    ::setenv("LANCER_SIMD", "baseline", 1);
    const RunResult baseline = runLancer(withOutput("baseline.pfm"), folder.path());
    const std::string baselineVersion = runLancer({"--version"}, folder.path()).standardOutput;
    ::unsetenv("LANCER_SIMD");
    ASSERT_EQ(baseline.exitStatus, 0) << baseline;
    EXPECT_EQ(readFile(folder / "baseline.pfm"), readFile(folder / "best.pfm"));
    EXPECT_EQ(baselineVersion.find("AVX2 kernels"), std::string::npos) << baselineVersion;
#if defined(__x86_64__) && defined(__GNUC__)
    if (__builtin_cpu_supports("avx2")) {
        EXPECT_NE(bestVersion.find("(AVX2 kernels on this CPU)"), std::string::npos) << bestVersion;
    }
#endif
}
#endif

// The summary's thread count, in the singular for one.
TEST(CliSummary, CountsThreadsInWords) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    for (const auto& [threads, words] :
         {std::pair{"1", ", 1 thread, "}, std::pair{"2", ", 2 threads, "}}) {
        const RunResult run = runLancer({"scene.json", "-o", "out.png", "--width", "16", "--height",
                                         "12", "--spp", "1", "--threads", threads},
                                        folder.path());
        ASSERT_EQ(run.exitStatus, 0) << run;
        EXPECT_NE(run.standardError.find(words), std::string::npos) << run.standardError;
    }
}

// --stats gives the load's time and, within it, the BVHs' build (the model's and the scene's).
TEST(CliStats, TheLoadTimeSaysHowMuchOfItWasTheBvhBuild) {
    const TempFolder folder;
    json scene = loadWhittedScene();
    scene["objects"].push_back(
        {{"type", "mesh"},
         {"file", (fs::path(LANCER_SOURCE_DIR) / "scenes/models/stanford_bunny_lowres/bunny.obj")
                      .string()}});
    folder.write("scene.json", scene.dump());
    const RunResult run = runLancer(
        {"scene.json", "-o", "out.pfm", "--width", "16", "--height", "12", "--spp", "1", "--stats"},
        folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    // "stats: scene loaded in L s (B s of it building BVHs)"
    const std::string prefix = "stats: scene loaded in ";
    const std::size_t line = run.standardError.find(prefix);
    ASSERT_NE(line, std::string::npos) << run.standardError;
    std::istringstream numbers(run.standardError.substr(line + prefix.size()));
    double load = 0, build = 0;
    std::string seconds;
    char opening = 0;
    numbers >> load >> seconds >> opening >> build;
    ASSERT_EQ(opening, '(') << run.standardError;
    std::string rest;
    std::getline(numbers, rest);
    EXPECT_EQ(rest, " s of it building BVHs)");
    EXPECT_GE(build, 0);
    EXPECT_LE(build, load);
}

}  // namespace
}  // namespace lancer::test
