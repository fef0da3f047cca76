// Scenes of scenes/ against stored reference renders, to catch any change of the picture.
//
// Each reference in data/ was rendered by lancer itself with the options below and checked by
// eye. To regenerate one after an intended change of the picture, from the source folder:
//   lancer scenes/NAME.json OPTIONS --quiet -o tests/cli/data/REFERENCE
// whitted: a checkered floor, a mirror sphere reflecting the scene, a glass sphere refracting the
//   floor upside down, a shiny blue sphere, a gold triangle, two shadows per object.
// cornell-original-whitted: McGuire's OBJ with its MTL colours (red and green walls, white
//   blocks), the quad light in front of the lamp, the blocks' soft shadows.
// spot: the cow's PNG texture (black patches, pink nose) through uvs and mip-maps, a checkered
//   floor, the cow's shadow.

#include <gtest/gtest.h>

#include <vector>

#include "LancerRun.h"

namespace lancer::test {
namespace {

struct ReferenceCase {
    std::string name;
    std::string scene;  // under scenes/
    std::vector<std::string> options;
    std::string reference;  // under tests/cli/data/
};

class CliReferenceImage : public testing::TestWithParam<ReferenceCase> {};

TEST_P(CliReferenceImage, MatchesTheStoredRender) {
    const ReferenceCase& c = GetParam();
    const Image reference = loadImage(fs::path(LANCER_SOURCE_DIR) / "tests/cli/data" / c.reference);
    const Image rendered =
        renderSceneFile(fs::path(LANCER_SOURCE_DIR) / "scenes" / c.scene, c.options).image;
    ASSERT_EQ(rendered.width, reference.width);
    ASSERT_EQ(rendered.height, reference.height);

    // Another compiler, optimisation level or sanitizer build may round differently (fused
    // multiply-adds, reordered sums): values move by about 1e-6, and now and then a sample near
    // an edge falls on its other side, moving its pixel by up to a quarter of the edge's contrast.
    // A real regression (a wrong term, a missing shadow or reflection, a wrong texel, a changed
    // sampling pattern) moves thousands of pixels by far more than 0.02.
    EXPECT_LT(meanAbsoluteDifference(rendered, reference), 0.002);
    EXPECT_GE(fractionOfPixelsWithin(rendered, reference, 0.02, 0), 0.995);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, CliReferenceImage,
    testing::Values(ReferenceCase{"Whitted",
                                  "whitted.json",
                                  {"--width", "160", "--height", "120", "--spp", "4"},
                                  "whitted-160x120.pfm"},
                    ReferenceCase{"CornellBox",
                                  "cornell-original-whitted.json",
                                  {"--width", "128", "--height", "128", "--spp", "4"},
                                  "cornell-original-whitted-128.exr"},
                    ReferenceCase{"TexturedModel",
                                  "spot.json",
                                  {"--width", "160", "--height", "120", "--spp", "4"},
                                  "spot-160x120.exr"}),
    CaseName{});

}  // namespace
}  // namespace lancer::test
