// One pixel's estimate: adaptive sampling spends samples where the pixel is noisy and stays
// within min_spp and max_spp; the estimate is deterministic; NaN and infinite samples are dropped
// and counted.

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "integrators/IntegratorRegistry.h"
#include "io/SceneLoader.h"
#include "render/PixelEstimator.h"

namespace lancer {
namespace {

constexpr int kSize = 16;

// A white emissive sphere filling the middle of a 16 x 16 image on black: pixels inside it or
// outside it are flat (every sample gives the same radiance), pixels on its outline are not.
std::string sphereScene(const std::string& renderExtras) {
    return R"({
      "render": { "width": 16, "height": 16, "max_depth": 0)" +
           renderExtras + R"( },
      "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0], "vfov": 30 },
      "materials": { "lamp": { "diffuse": 0, "emission": 1 } },
      "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 0.9, "material": "lamp" } ]
    })";
}

// A scene, its integrator and a pixel estimator, kept together.
struct RenderablePixels {
    explicit RenderablePixels(const std::string& text)
        : scene(load(text)),
          integrator(IntegratorRegistry::create(scene)),
          estimator(std::make_unique<PixelEstimator>(scene, *integrator)) {}

    static Scene load(const std::string& text) {
        std::vector<std::string> warnings;
        return SceneLoader::loadString(text, "test.json", warnings);
    }

    // The samples pixel (x, y) took.
    std::uint64_t samplesAt(int x, int y, Color* value = nullptr) const {
        RenderCounters counters;
        const Color c = estimator->estimate(x, y, 0, counters);
        if (value) *value = c;
        EXPECT_EQ(counters.pixels, 1u);
        return counters.samples;
    }

    Scene scene;
    std::unique_ptr<Integrator> integrator;
    std::unique_ptr<PixelEstimator> estimator;
};

const std::string kAdaptive =
    R"(, "adaptive": { "min_spp": 8, "max_spp": 256, "threshold": 0.02 })";

TEST(PixelEstimatorTest, AdaptiveSamplingSpendsMoreOnTheOutlineThanOnFlatPixels) {
    const RenderablePixels pixels(sphereScene(kAdaptive));
    Color value;
    EXPECT_EQ(pixels.samplesAt(8, 8, &value), 8u) << "inside the sphere";
    EXPECT_FLOAT_EQ(value.r, 1);
    EXPECT_EQ(pixels.samplesAt(0, 0, &value), 8u) << "on the background";
    EXPECT_EQ(value.r, 0);

    // Every pixel that the outline crosses (neither 0 nor 1) takes more than min_spp.
    int outlinePixels = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const std::uint64_t samples = pixels.samplesAt(x, y, &value);
            EXPECT_GE(samples, 8u);
            EXPECT_LE(samples, 256u);
            if (value.r > 0.02f && value.r < 0.98f) {
                ++outlinePixels;
                EXPECT_GT(samples, 8u) << "pixel " << x << "," << y << " = " << value.r;
            } else if (value.r == 0 || value.r == 1) {
                EXPECT_EQ(samples, 8u) << "pixel " << x << "," << y;
            }
        }
    EXPECT_GT(outlinePixels, 10);
}

TEST(PixelEstimatorTest, AStrictThresholdTakesMaxSppOnTheOutlineOnly) {
    const RenderablePixels pixels(
        sphereScene(R"(, "adaptive": { "min_spp": 4, "max_spp": 100, "threshold": 0.000001 })"));
    std::uint64_t most = 0;
    for (int x = 0; x < kSize; ++x)
        most = std::max(most, pixels.samplesAt(x, kSize / 2));
    EXPECT_EQ(most, 100u) << "a batch is cut short at max_spp, not rounded up";
    EXPECT_EQ(pixels.samplesAt(8, 8), 4u);
}

TEST(PixelEstimatorTest, APixelOnALightsEdgeTakesTheFactorTimesItsBudget) {
    const auto samples = [](const RenderablePixels& pixels, int x, int y, bool onLightEdge) {
        RenderCounters counters;
        pixels.estimator->estimate(x, y, 0, counters, onLightEdge);
        return counters.samples;
    };
    const RenderablePixels uniform(sphereScene(R"(, "spp": 4, "light_edge_factor": 3)"));
    EXPECT_EQ(samples(uniform, 8, 8, true), 12u);
    EXPECT_EQ(samples(uniform, 8, 8, false), 4u);
    // With adaptive sampling, up to the factor times max_spp where the pixel stays noisy; a flat
    // pixel still stops at min_spp.
    const RenderablePixels adaptive(sphereScene(
        R"(, "adaptive": { "min_spp": 4, "max_spp": 100, "threshold": 0.000001 },
             "light_edge_factor": 3)"));
    std::uint64_t most = 0;
    for (int x = 0; x < kSize; ++x) {
        most = std::max(most, samples(adaptive, x, kSize / 2, true));
        EXPECT_LE(samples(adaptive, x, kSize / 2, false), 100u);
    }
    EXPECT_EQ(most, 300u);
    EXPECT_EQ(samples(adaptive, 8, 8, true), 4u);
}

TEST(PixelEstimatorTest, AdaptiveConvergesToTheUniformValue) {
    const RenderablePixels adaptive(sphereScene(kAdaptive));
    const RenderablePixels uniform(sphereScene(R"(, "spp": 4096)"));
    int outlinePixels = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            Color a, u;
            adaptive.samplesAt(x, y, &a);
            uniform.samplesAt(x, y, &u);
            if (u.r >= 0.125f && u.r <= 0.875f) {
                // The outline is in sight of the first min_spp = 8 samples, so the stopping rule
                // sees the pixel is noisy; it asks for a relative standard error of 2% (as if the
                // samples were independent: stratified ones do better).
                ++outlinePixels;
                EXPECT_NEAR(a.r, u.r, 0.06 * u.r) << "pixel " << x << "," << y;
            } else {
                // A sliver of the sphere thinner than one sample's share of the pixel may be
                // missed by all of the first 8 samples, which then agree: the pixel stops, as a
                // render with 8 samples everywhere would have missed it too.
                EXPECT_NEAR(a.r, u.r, 0.125) << "pixel " << x << "," << y;
            }
        }
    EXPECT_GT(outlinePixels, 10);
}

TEST(PixelEstimatorTest, EstimatesAreDeterministic) {
    const RenderablePixels pixels(sphereScene(kAdaptive + R"(, "filter": "mitchell")"));
    for (int x = 0; x < kSize; ++x) {
        RenderCounters first, second;
        const Color a = pixels.estimator->estimate(x, 7, 42, first);
        pixels.estimator->estimate(x + 1 < kSize ? x + 1 : 0, 7, 42, second);  // other work between
        RenderCounters third;
        const Color b = pixels.estimator->estimate(x, 7, 42, third);
        EXPECT_EQ(a, b);
        EXPECT_EQ(first.samples, third.samples);
        EXPECT_EQ(first.rays, third.rays);
    }
}

TEST(PixelEstimatorTest, UniformSamplingTakesSppInEveryPixel) {
    const RenderablePixels pixels(sphereScene(R"(, "spp": 12, "filter": "tent")"));
    for (int x = 0; x < kSize; ++x)
        EXPECT_EQ(pixels.samplesAt(x, 6), 12u);
}

TEST(PixelEstimatorTest, NonFiniteSamplesAreDroppedAndCounted) {
    // Seen from inside, a mirror that emits 3e38 reflects itself: 3e38 + 3e38 overflows to
    // infinity in every sample.
    const RenderablePixels pixels(R"({
      "render": { "width": 4, "height": 4, "spp": 8, "max_depth": 1 },
      "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1] },
      "materials": { "hot": { "diffuse": 0, "emission": 3e38, "reflection": 1 } },
      "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 10, "material": "hot" } ]
    })");
    RenderCounters counters;
    const Color c = pixels.estimator->estimate(1, 2, 0, counters);
    EXPECT_EQ(c, Color(0));
    EXPECT_EQ(counters.samples, 8u);
    EXPECT_EQ(counters.nonFiniteSamples, 8u);
}

}  // namespace
}  // namespace lancer
