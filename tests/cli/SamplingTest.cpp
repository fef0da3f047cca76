// The render block's sampling keys end to end: every reconstruction filter keeps a constant
// image constant; adaptive sampling is deterministic whatever the threads, reports its mean
// sample count, and takes its budget from spp / max_spp / --spp; NaN and infinite samples are
// dropped and counted by --stats.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "LancerRun.h"

namespace lancer::test {
namespace {

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// The camera inside a sphere that emits `emission` and reflects nothing: every ray, whatever
// its direction, sees the same radiance, so every pixel must be exactly that.
nlohmann::json insideAnEmissiveSphere(const nlohmann::json& renderExtras) {
    nlohmann::json scene = {
        {"render", {{"width", 24}, {"height", 18}, {"spp", 16}, {"max_depth", 2}}},
        {"camera", {{"position", {0, 0, 0}}, {"look_at", {0, 0, -1}}, {"vfov", 90}}},
        {"materials", {{"lamp", {{"diffuse", 0}, {"emission", {0.25, 0.5, 2.0}}}}}},
        {"objects",
         {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 3}, {"material", "lamp"}}}}};
    scene["render"].update(renderExtras);
    return scene;
}

struct FilterCase {
    std::string name;
    nlohmann::json render;  // keys added to the "render" block
};

std::ostream& operator<<(std::ostream& out, const FilterCase& c) {
    return out << c.name;
}

class CliConstantImage : public testing::TestWithParam<FilterCase> {};

TEST_P(CliConstantImage, EveryPixelIsTheEmission) {
    const Image image = renderScene(insideAnEmissiveSphere(GetParam().render)).image;
    const double expected[3] = {0.25, 0.5, 2.0};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                // sum(w L) / sum(w) with a constant L: only rounding.
                ASSERT_NEAR(image.at(x, y)[static_cast<std::size_t>(c)], expected[c],
                            2e-6 * expected[c])
                    << "pixel " << x << "," << y << " channel " << c;
}

INSTANTIATE_TEST_SUITE_P(
    Filters, CliConstantImage,
    testing::Values(
        FilterCase{"Default", nlohmann::json::object()}, FilterCase{"Box", {{"filter", "box"}}},
        FilterCase{"WideBox", {{"filter", {{"type", "box"}, {"radius", 1.5}}}}},
        FilterCase{"Tent", {{"filter", "tent"}}}, FilterCase{"Gaussian", {{"filter", "gaussian"}}},
        FilterCase{"NarrowGaussian", {{"filter", {{"type", "gaussian"}, {"radius", 0.6}}}}},
        FilterCase{"Mitchell", {{"filter", "mitchell"}}},
        FilterCase{"WideMitchell", {{"filter", {{"type", "mitchell"}, {"radius", 3}}}}},
        FilterCase{"MitchellFewSamples", {{"filter", "mitchell"}, {"spp", 2}}},
        FilterCase{"AdaptiveMitchell",
                   {{"filter", "mitchell"},
                    {"spp", 64},
                    {"adaptive", {{"min_spp", 4}, {"threshold", 0.001}}}}}),
    CaseName());

// A mirror, a glass sphere and a fine checkerboard to the horizon under a bright light: pixels
// whose neighbours differ a lot, where a negative-lobed filter with few samples goes wrong.
nlohmann::json mirrorGlassChecker(const nlohmann::json& filter, int spp) {
    return {
        {"render",
         {{"width", 96}, {"height", 64}, {"spp", spp}, {"max_depth", 4}, {"filter", filter}}},
        {"camera", {{"position", {0, 1.2, 6}}, {"look_at", {0, 0.7, 0}}, {"vfov", 45}}},
        {"background", {0.3, 0.4, 0.7}},
        {"ambient", 0.02},
        {"materials",
         {{"checker",
           {{"diffuse",
             {{"checker",
               {{"even", {0.9, 0.9, 0.9}}, {"odd", {0.02, 0.02, 0.02}}, {"scale", 0.4}}}}},
            {"specular", 0.8},
            {"shininess", 200}}},
          {"mirror", {{"diffuse", 0.02}, {"specular", 1}, {"shininess", 800}, {"reflection", 0.9}}},
          {"glass",
           {{"diffuse", 0},
            {"specular", 1},
            {"shininess", 400},
            {"transmission", 0.95},
            {"ior", 1.5}}}}},
        {"objects",
         {{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "checker"}},
          {{"type", "sphere"}, {"center", {-1.2, 0.9, 0}}, {"radius", 0.9}, {"material", "mirror"}},
          {{"type", "sphere"}, {"center", {1.0, 0.7, 1}}, {"radius", 0.7}, {"material", "glass"}}}},
        {"lights",
         {{{"type", "point"}, {"position", {-3, 6, 4}}, {"intensity", 400}},
          {{"type", "point"}, {"position", {4, 3, 2}}, {"intensity", 150}}}}};
}

// Black once stored in 8 bits: every channel below half a step of the sRGB encoding.
bool isBlack(const Image::Rgb& pixel) {
    return std::all_of(pixel.begin(), pixel.end(), [](float c) { return c < 0.5f / 255 / 12.92f; });
}

class CliFilterRange : public testing::TestWithParam<int> {};

// Radiance is never negative, and neither is any filtered pixel; nor is a pixel black where the
// box filter (a plain average of the pixel's own samples) sees light.
TEST_P(CliFilterRange, NoFilterMakesANegativeOrBlackPixel) {
    const int spp = GetParam();
    const Image box = renderScene(mirrorGlassChecker("box", spp)).image;
    const nlohmann::json filters = {
        "tent", "gaussian", "mitchell", {{"type", "mitchell"}, {"radius", 3}}};
    for (const nlohmann::json& filter : filters) {
        const Image image = renderScene(mirrorGlassChecker(filter, spp)).image;
        int negative = 0, blackSpeckles = 0;
        float minimum = 0;
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            for (const float c : image.pixels[i]) {
                minimum = std::min(minimum, c);
                if (c < 0) ++negative;
            }
            if (isBlack(image.pixels[i]) && !isBlack(box.pixels[i])) ++blackSpeckles;
        }
        EXPECT_EQ(negative, 0) << filter.dump() << " at " << spp << " spp: minimum " << minimum;
        EXPECT_EQ(blackSpeckles, 0) << filter.dump() << " at " << spp << " spp";
    }
}

INSTANTIATE_TEST_SUITE_P(Spp, CliFilterRange, testing::Values(1, 4, 16));

// Runs lancer on `scene` (not quiet) and returns the run, after checking it succeeded.
RunResult runOn(const nlohmann::json& scene, const std::vector<std::string>& options) {
    const TempFolder folder;
    folder.write("scene.json", scene.dump(2));
    const RunResult run =
        runLancer(concat({"scene.json", "-o", "out.pfm"}, options), folder.path());
    EXPECT_EQ(run.exitStatus, 0) << run;
    return run;
}

// The summary line's "M spp on average (adaptive, A to B)", as (M, A, B); nothing if absent.
// (Parsed by hand: GCC 12 under the sanitizers warns inside std::regex.)
std::optional<std::array<double, 3>> adaptiveSummary(const RunResult& run) {
    const std::string& text = run.standardError;
    const std::size_t at = text.find(" spp on average (adaptive, ");
    if (at == std::string::npos || at == 0) return std::nullopt;
    const std::size_t start = text.find_last_of(' ', at - 1) + 1;  // where the mean begins
    std::array<double, 3> summary{};
    if (std::sscanf(text.c_str() + start, "%lf spp on average (adaptive, %lf to %lf)", &summary[0],
                    &summary[1], &summary[2]) != 3)
        return std::nullopt;
    return summary;
}

nlohmann::json adaptiveWhitted(const nlohmann::json& adaptive) {
    nlohmann::json scene = loadWhittedScene();
    scene["render"].erase("spp");
    scene["render"]["adaptive"] = adaptive;
    return scene;
}

const std::vector<std::string> kSmall{"--width", "96", "--height", "72"};

TEST(CliAdaptive, OneAndTwoThreadsWriteByteIdenticalFiles) {
    const nlohmann::json scene = adaptiveWhitted({{"min_spp", 4}, {"max_spp", 64}});
    for (const char* filter : {"box", "mitchell"}) {
        nlohmann::json filtered = scene;
        filtered["render"]["filter"] = filter;
        const std::string one = renderScene(filtered, concat(kSmall, {"--threads", "1"})).bytes;
        const std::string two = renderScene(filtered, concat(kSmall, {"--threads", "2"})).bytes;
        EXPECT_TRUE(one == two) << "the files differ (" << filter << ")";
    }
}

TEST(CliAdaptive, SummaryGivesTheMeanSamplesTakenWithinTheRange) {
    const RunResult run = runOn(adaptiveWhitted({{"min_spp", 4}, {"max_spp", 64}}), kSmall);
    const auto summary = adaptiveSummary(run);
    ASSERT_TRUE(summary) << run.standardError;
    EXPECT_EQ((*summary)[1], 4);
    EXPECT_EQ((*summary)[2], 64);
    // Most of the Whitted scene is flat (sky, the insides of squares and spheres): far fewer
    // samples than max_spp on average, but more than min_spp (its edges).
    EXPECT_GT((*summary)[0], 4);
    EXPECT_LT((*summary)[0], 32);
}

TEST(CliAdaptive, SppOptionSetsMaxSppAndLowersMinSppToIt) {
    const nlohmann::json scene = adaptiveWhitted({{"min_spp", 16}, {"max_spp", 256}});
    const auto lowered = adaptiveSummary(runOn(scene, concat(kSmall, {"--spp", "8"})));
    ASSERT_TRUE(lowered);
    EXPECT_EQ((*lowered)[1], 8);
    EXPECT_EQ((*lowered)[2], 8);
    EXPECT_EQ((*lowered)[0], 8) << "min_spp = max_spp: every pixel takes 8";
    const auto raised = adaptiveSummary(runOn(scene, concat(kSmall, {"--spp", "32"})));
    ASSERT_TRUE(raised);
    EXPECT_EQ((*raised)[1], 16);
    EXPECT_EQ((*raised)[2], 32);
}

TEST(CliAdaptive, TheRenderSppIsTheBudgetWhenMaxSppIsNotGiven) {
    nlohmann::json scene = adaptiveWhitted({{"min_spp", 2}});
    scene["render"]["spp"] = 8;
    const auto summary = adaptiveSummary(runOn(scene, kSmall));
    ASSERT_TRUE(summary);
    EXPECT_EQ((*summary)[1], 2);
    EXPECT_EQ((*summary)[2], 8);
}

TEST(CliAdaptive, UniformSamplingSaysSpp) {
    const RunResult run = runOn(loadWhittedScene(), concat(kSmall, {"--spp", "4"}));
    EXPECT_FALSE(adaptiveSummary(run));
    EXPECT_NE(run.standardError.find(", 4 spp, "), std::string::npos) << run.standardError;
}

TEST(CliNonFiniteSamples, AreDroppedAndCountedByStats) {
    // Seen from inside, a mirror that emits 3e38 reflects itself: 3e38 + 3e38 overflows to
    // infinity in every sample.
    const nlohmann::json scene = {
        {"render", {{"width", 6}, {"height", 4}, {"spp", 3}, {"max_depth", 1}}},
        {"camera", {{"position", {0, 0, 0}}, {"look_at", {0, 0, -1}}}},
        {"materials", {{"hot", {{"diffuse", 0}, {"emission", 3e38}, {"reflection", 1}}}}},
        {"objects",
         {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 10}, {"material", "hot"}}}}};
    const TempFolder folder;
    folder.write("scene.json", scene.dump(2));
    const RunResult run =
        runLancer({"scene.json", "-o", "out.pfm", "--stats", "--quiet"}, folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    // One camera ray and one reflected ray per sample, and the 7 x 5 pixel corners' rays that
    // look for lights' edges (LightEdgeProbe: the scene emits).
    EXPECT_NE(
        run.standardError.find("stats: 179 rays, 72 samples, 72 of them NaN or infinite (dropped)"),
        std::string::npos)
        << run.standardError;
    const Image image = loadImage(folder / "out.pfm");
    for (const Image::Rgb& pixel : image.pixels)
        EXPECT_EQ(pixel, (Image::Rgb{0, 0, 0})) << "a dropped sample counts as black";
}

}  // namespace
}  // namespace lancer::test
