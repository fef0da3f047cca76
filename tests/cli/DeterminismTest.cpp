// The image depends on the scene and the seed only: never on how many threads rendered it.

#include <gtest/gtest.h>

#include "LancerRun.h"

namespace lancer::test {
namespace {

// Small, and several samples per pixel so that the seed matters.
const std::vector<std::string> kSmallRender{"--width", "96", "--height", "72", "--spp", "4"};

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

struct ThreadCase {
    std::string name;
    std::string output;
    std::vector<std::string> seed;  // the --seed option, or nothing for the default
};

std::ostream& operator<<(std::ostream& out, const ThreadCase& c) {
    return out << c.name;
}

class CliThreads : public testing::TestWithParam<ThreadCase> {};

TEST_P(CliThreads, OneAndTwoThreadsWriteByteIdenticalFiles) {
    const nlohmann::json scene = loadWhittedScene();
    const std::vector<std::string> options = concat(kSmallRender, GetParam().seed);
    const std::string oneThread =
        renderScene(scene, concat(options, {"--threads", "1"}), GetParam().output).bytes;
    const std::string twoThreads =
        renderScene(scene, concat(options, {"--threads", "2"}), GetParam().output).bytes;
    EXPECT_TRUE(oneThread == twoThreads) << "the files differ";
}

INSTANTIATE_TEST_SUITE_P(Outputs, CliThreads,
                         testing::Values(ThreadCase{"Pfm", "out.pfm", {}},
                                         ThreadCase{"Png", "out.png", {}},
                                         ThreadCase{"PfmWithSeed", "out.pfm", {"--seed", "12345"}},
                                         ThreadCase{"PngWithSeed", "out.png", {"--seed", "987"}}),
                         CaseName());

TEST(CliSeed, DifferentSeedsGiveDifferentEstimatesOfTheSamePicture) {
    const nlohmann::json scene = loadWhittedScene();
    const RenderedFile first = renderScene(scene, concat(kSmallRender, {"--seed", "1"}));
    const RenderedFile second = renderScene(scene, concat(kSmallRender, {"--seed", "2"}));
    EXPECT_FALSE(first.bytes == second.bytes) << "the seed changes the samples";
    // Both average 4 samples of the same pixels: they differ only along edges (silhouettes,
    // checker borders, the glass), by at most the contrast across the edge, so on average by far
    // less than 0.02.
    EXPECT_LT(meanAbsoluteDifference(first.image, second.image), 0.02);
}

TEST(CliSeed, DefaultSeedIsZero) {
    const nlohmann::json scene = loadWhittedScene();
    EXPECT_TRUE(renderScene(scene, kSmallRender).bytes ==
                renderScene(scene, concat(kSmallRender, {"--seed", "0"})).bytes);
}

}  // namespace
}  // namespace lancer::test
