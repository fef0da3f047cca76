// The renderer's side of the live window: coarse preview passes before the image, tiles
// reported with the film that holds them, and an image that previews never change.

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "LancerRun.h"
#include "integrators/IntegratorRegistry.h"
#include "io/SceneLoader.h"
#include "render/Renderer.h"

namespace lancer::test {
namespace {

constexpr int kWidth = 72, kHeight = 40;  // not multiples of the tile or block sizes

Scene smallWhittedScene() {
    nlohmann::json scene = loadWhittedScene();
    scene["render"]["width"] = kWidth;
    scene["render"]["height"] = kHeight;
    scene["render"]["spp"] = 2;
    std::vector<std::string> warnings;
    return SceneLoader::loadString(scene.dump(), "whitted.json", warnings);
}

bool sameImage(const lancer::Image& a, const lancer::Image& b) {
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (!(a.at(x, y) == b.at(x, y))) return false;
    return true;
}

struct Report {
    PixelWindow tile;
    bool preview;
    int tilesDone;
};

TEST(PreviewPass, CoarsePassesComeFirstCoverTheImageAndLeaveItUnchanged) {
    const Scene scene = smallWhittedScene();
    const auto integrator = IntegratorRegistry::create(scene);
    const Renderer renderer(scene, *integrator);

    RenderOptions plain;
    plain.threads = 2;
    const RenderResult reference = renderer.render(plain);

    RenderOptions live = plain;
    live.previewBlockSizes = {8, 2};
    std::vector<Report> reports;
    lancer::Image shown(kWidth, kHeight);  // what a viewer would show, copied during the calls
    std::vector<int> coverage(kWidth * kHeight, 0);
    int previewTiles = 0;
    live.onTileDone = [&](const FinishedTile& done) {
        reports.push_back({done.tile, done.preview(), done.tilesDone});
        for (int y = done.tile.y0; y < done.tile.y1; ++y)
            for (int x = done.tile.x0; x < done.tile.x1; ++x) {
                shown.at(x, y) = done.film.at(x, y);
                ++coverage[static_cast<std::size_t>(y * kWidth + x)];
            }
        if (done.preview()) {
            // A block holds one value. The 8 x 8 pass has tiles of 128 x 128 pixels: one here.
            const PixelWindow& t = done.tile;
            const int block = previewTiles++ == 0 ? 8 : 2;
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x)
                    EXPECT_EQ(done.film.at(x, y),
                              done.film.at(x - (x - t.x0) % block, y - (y - t.y0) % block));
        }
    };
    const RenderResult result = renderer.render(live);

    EXPECT_FALSE(result.interrupted);
    EXPECT_TRUE(sameImage(result.film, reference.film)) << "previews do not change the image";
    EXPECT_TRUE(sameImage(shown, reference.film)) << "the last word on every pixel is the image's";
    // Three passes, each over every pixel once: 8x8 blocks, 2x2 blocks, the image.
    for (int covered : coverage)
        ASSERT_EQ(covered, 3);
    // Previews first, then the image's tiles counted 1, 2, ...
    const auto firstImageTile =
        std::find_if(reports.begin(), reports.end(), [](const Report& r) { return !r.preview; });
    EXPECT_TRUE(
        std::all_of(firstImageTile, reports.end(), [](const Report& r) { return !r.preview; }));
    const int tilesTotal = ((kWidth + 15) / 16) * ((kHeight + 15) / 16);
    ASSERT_EQ(reports.end() - firstImageTile, tilesTotal);
    for (int i = 0; i < tilesTotal; ++i)
        EXPECT_EQ(firstImageTile[i].tilesDone, i + 1);
    // A preview costs about a quarter of a ray per pixel, next to the image's two per pixel and
    // more (shadow and secondary rays).
    EXPECT_LT(result.counters.rays - reference.counters.rays, reference.counters.rays / 4);
}

TEST(PreviewPass, ACancelledRenderHoldsNoPreviewPixels) {
    const Scene scene = smallWhittedScene();
    const auto integrator = IntegratorRegistry::create(scene);
    std::atomic<bool> cancel{false};
    RenderOptions options;
    options.threads = 2;
    options.cancel = &cancel;
    options.previewBlockSizes = {8, 2};
    int previews = 0;
    options.onTileDone = [&](const FinishedTile& done) {
        previews += done.preview() ? 1 : 0;
        cancel = true;  // after the first preview tile
    };
    const RenderResult result = Renderer(scene, *integrator).render(options);

    EXPECT_TRUE(result.interrupted);
    EXPECT_GE(previews, 1);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            ASSERT_EQ(result.film.at(x, y), Color(0)) << "pixel " << x << "," << y;
}

}  // namespace
}  // namespace lancer::test
