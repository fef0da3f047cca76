// LightEdgeProbe: which pixels the renderer gives more samples, decided from the pixels' corners
// alone (never from their samples), the same whatever the tiles.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "io/SceneLoader.h"
#include "render/LightEdgeProbe.h"
#include "render/PixelWindow.h"
#include "scene/Scene.h"

namespace lancer::test {
namespace {

constexpr int kWidth = 37, kHeight = 23;

// A sphere lamp and a dark ball in front of a background.
Scene loadScene(const std::string& background, const std::string& lampMaterial, int spp = 4,
                int lightEdgeFactor = 16) {
    std::vector<std::string> warnings;
    return SceneLoader::loadString(R"({
      "render": {"width": 37, "height": 23, "spp": )" +
                                       std::to_string(spp) + R"(, "light_edge_factor": )" +
                                       std::to_string(lightEdgeFactor) + R"(},
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "vfov": 40},
      "background": )" + background + R"(,
      "materials": {"lamp": )" + lampMaterial +
                                       R"(, "dark": {"diffuse": 0.2}},
      "objects": [
        {"type": "sphere", "center": [-0.8, 0, 0], "radius": 0.6, "material": "lamp"},
        {"type": "sphere", "center": [0.9, 0.2, -1], "radius": 0.7, "material": "dark"}
      ]
    })",
                                   "scene.json", warnings);
}

// What the probe finds over the whole image.
struct WholeImage {
    bool active;
    std::vector<bool> edges;
    std::uint64_t rays = 0;
    long edgePixels;
};

WholeImage probeWholeImage(const Scene& scene) {
    const LightEdgeProbe probe(scene);
    WholeImage found{probe.active(), {}, 0, 0};
    found.edges = probe.edges({0, 0, kWidth, kHeight}, found.rays);
    found.edgePixels = std::count(found.edges.begin(), found.edges.end(), true);
    EXPECT_EQ(found.edges.size(), std::size_t{kWidth * kHeight});
    return found;
}

TEST(LightEdgeProbe, FindsTheLampsOutlineAndTheSameEdgesWhateverTheTiles) {
    const Scene scene = loadScene("0", R"({"diffuse": 0, "emission": 5})");
    const auto [active, whole, wholeRays, edgePixels] = probeWholeImage(scene);
    ASSERT_TRUE(active);
    EXPECT_EQ(wholeRays, std::uint64_t{(kWidth + 1) * (kHeight + 1)});  // each corner once
    // The lamp's outline, a ring of pixels around a disc some 8 pixels across.
    EXPECT_GT(edgePixels, 16);
    EXPECT_LT(edgePixels, 60);
    // Cut into windows of odd sizes, the same pixels.
    const LightEdgeProbe probe(scene);
    std::uint64_t rays = 0;
    for (const int size : {1, 3, 16}) {
        for (int y0 = 0; y0 < kHeight; y0 += size)
            for (int x0 = 0; x0 < kWidth; x0 += size) {
                const PixelWindow window{x0, y0, std::min(x0 + size, kWidth),
                                         std::min(y0 + size, kHeight)};
                const std::vector<bool> part = probe.edges(window, rays);
                for (int y = window.y0; y < window.y1; ++y)
                    for (int x = window.x0; x < window.x1; ++x)
                        EXPECT_EQ(
                            part[static_cast<std::size_t>((y - y0) * window.width() + (x - x0))],
                            whole[static_cast<std::size_t>(y * kWidth + x)])
                            << "pixel " << x << ", " << y << " in windows of " << size;
            }
    }
}

TEST(LightEdgeProbe, LooksForNothingWhereNoEdgeCanBe) {
    const auto tracesNothing = [](const Scene& scene) {
        const WholeImage found = probeWholeImage(scene);
        EXPECT_EQ(found.edgePixels, 0);
        EXPECT_EQ(found.rays, 0u);
        return !found.active;
    };
    // Nothing emits, and the background is no brighter than display white.
    EXPECT_TRUE(tracesNothing(loadScene("1", R"({"diffuse": 0.5})")));
    // An emitter, but no extra samples to give, or one ray through each pixel's centre.
    EXPECT_TRUE(tracesNothing(loadScene("0", R"({"diffuse": 0, "emission": 5})", 4, 1)));
    EXPECT_TRUE(tracesNothing(loadScene("0", R"({"diffuse": 0, "emission": 5})", 1)));
}

TEST(LightEdgeProbe, AFaintLampMakesNoEdge) {
    // The lamp's radiance 0.9 on black: a step below display white.
    const WholeImage found = probeWholeImage(loadScene("0", R"({"diffuse": 0, "emission": 0.9})"));
    EXPECT_TRUE(found.active);
    EXPECT_EQ(found.edgePixels, 0);
}

}  // namespace
}  // namespace lancer::test
