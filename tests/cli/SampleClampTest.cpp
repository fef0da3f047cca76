// "clamp" in the render block (docs/SCENE-FORMAT.md, `render`): each camera sample brighter than
// the limit is scaled down to it (its largest component), before the pixel's average.

#include <gtest/gtest.h>

#include <algorithm>

#include "LancerRun.h"

namespace lancer::test {
namespace {

// A 4x3 picture of a coloured background, so that every sample is that radiance.
nlohmann::json backgroundScene(const nlohmann::json& renderKeys) {
    nlohmann::json scene = nlohmann::json::parse(R"({
      "render": { "width": 4, "height": 3, "spp": 4 },
      "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
      "background": [8, 4, 2]
    })");
    scene["render"].update(renderKeys);
    return scene;
}

TEST(CliSampleClamp, ScalesABrightSampleDownToTheLimitKeepingItsHue) {
    const Image image = renderScene(backgroundScene({{"clamp", 2}})).image;
    // 2/8 is a power of two: the scaled values are exact.
    for (const Image::Rgb& pixel : image.pixels) {
        EXPECT_EQ(pixel[0], 2.0f);
        EXPECT_EQ(pixel[1], 1.0f);
        EXPECT_EQ(pixel[2], 0.5f);
    }
}

TEST(CliSampleClamp, LeavesSamplesAtOrBelowTheLimitAsTheyAre) {
    for (const double limit : {8.0, 100.0}) {
        const Image image = renderScene(backgroundScene({{"clamp", limit}})).image;
        for (const Image::Rgb& pixel : image.pixels) {
            EXPECT_EQ(pixel[0], 8.0f);
            EXPECT_EQ(pixel[1], 4.0f);
            EXPECT_EQ(pixel[2], 2.0f);
        }
    }
}

// An emitter of radiance 100 on black, seen through a 16-sample box filter: each sample is 100
// or 0, so clamping each to 1 gives the fraction of samples that see the emitter, which is the
// unclamped pixel / 100 (the samples are the same in both renders). Clamping the pixel's average
// instead would give 1 wherever that fraction is above 1%.
TEST(CliSampleClamp, ActsOnEachSampleNotOnThePixel) {
    nlohmann::json scene = nlohmann::json::parse(R"({
      "render": { "width": 8, "height": 8, "spp": 16, "integrator": "path", "max_depth": 0 },
      "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0], "vfov": 30 },
      "materials": { "lamp": { "diffuse": 0, "emission": 100 } },
      "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 0.9, "material": "lamp" } ]
    })");
    const Image unclamped = renderScene(scene).image;
    scene["render"]["clamp"] = 1;
    const Image clamped = renderScene(scene).image;
    int partlyCovered = 0;
    for (std::size_t i = 0; i < clamped.pixels.size(); ++i) {
        const float expected = unclamped.pixels[i][0] / 100;
        // Float sums of 16 terms in a different order of magnitude: a few ulps.
        EXPECT_NEAR(clamped.pixels[i][0], expected, 1e-6f) << "pixel " << i;
        if (expected > 0.01f && expected < 0.99f) ++partlyCovered;
    }
    EXPECT_GT(partlyCovered, 4) << "the sphere's rim crosses pixels";
}

}  // namespace
}  // namespace lancer::test
