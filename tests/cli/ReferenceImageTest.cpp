// scenes/whitted.json against a stored reference render, to catch any change of the picture.
//
// The reference, data/whitted-160x120.pfm, was rendered by lancer itself with the options below
// and checked by eye (a checkered floor, a mirror sphere reflecting the scene, a glass sphere
// refracting the floor upside down, a shiny blue sphere, a gold triangle, two shadows per
// object). To regenerate it after an intended change of the picture, from the source folder:
//   lancer scenes/whitted.json --width 160 --height 120 --spp 4 --quiet
//          -o tests/cli/data/whitted-160x120.pfm

#include <gtest/gtest.h>

#include "LancerRun.h"

namespace lancer::test {
namespace {

TEST(CliReferenceImage, WhittedSceneMatchesTheStoredRender) {
    const Image reference =
        loadImage(fs::path(LANCER_SOURCE_DIR) / "tests/cli/data/whitted-160x120.pfm");
    const Image rendered =
        renderScene(loadWhittedScene(), {"--width", "160", "--height", "120", "--spp", "4"}).image;
    ASSERT_EQ(rendered.width, reference.width);
    ASSERT_EQ(rendered.height, reference.height);

    // Another compiler, optimisation level or sanitizer build may round differently (fused
    // multiply-adds, reordered sums): values move by about 1e-6, and now and then a sample near
    // an edge falls on its other side, moving its pixel by up to a quarter of the edge's contrast.
    // A real regression (a wrong term, a missing shadow or reflection, a changed sampling
    // pattern) moves thousands of pixels by far more than 0.02.
    EXPECT_LT(meanAbsoluteDifference(rendered, reference), 0.002);
    EXPECT_GE(fractionOfPixelsWithin(rendered, reference, 0.02, 0), 0.995);
}

}  // namespace
}  // namespace lancer::test
