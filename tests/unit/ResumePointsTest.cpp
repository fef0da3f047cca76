// --resume from every point of a render: interrupted after its first tile, half-way and before its
// last tile (exactly, by counting the finished tiles rather than by a timer as the end-to-end
// tests do), saved as a resume file, read back and finished, the image and its auxiliary outputs
// are those of the uninterrupted render to the bit.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <string>
#include <vector>

#include "TempFolder.h"
#include "integrators/IntegratorRegistry.h"
#include "io/ResumeFile.h"
#include "io/SceneLoader.h"
#include "render/Aov.h"
#include "render/Renderer.h"

namespace lancer::test {
namespace {

// Not multiples of the tile size: 5 x 3 tiles, the last row and column partial.
constexpr int kWidth = 72, kHeight = 40;
constexpr std::uint64_t kFingerprint = 0x5eed;

// A glass ball and a diffuse one on a checkered floor, under a sphere lamp and a point light:
// every integrator's work (refraction, soft shadows, textures), small.
std::string sceneText(const std::string& integrator, const std::string& sampling) {
    return R"({
      "render": {"width": 72, "height": 40, "integrator": ")" +
           integrator + R"(", )" + sampling + R"(},
      "camera": {"position": [0, 1, 5], "look_at": [0, 0.5, 0], "vfov": 40},
      "background": [0.1, 0.1, 0.2],
      "materials": {
        "floor": {"diffuse": {"checker": {"even": 0.8, "odd": 0.2, "scale": 0.25}}},
        "glass": {"diffuse": 0, "specular": 0.5, "shininess": 200, "transmission": 1, "ior": 1.5},
        "red": {"diffuse": [0.8, 0.2, 0.1]}
      },
      "objects": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
        {"type": "sphere", "center": [-0.6, 0.5, 0], "radius": 0.5, "material": "glass"},
        {"type": "sphere", "center": [0.7, 0.4, -0.5], "radius": 0.4, "material": "red"}
      ],
      "lights": [
        {"type": "sphere", "center": [1, 3, 2], "radius": 0.3, "radiance": 20},
        {"type": "point", "position": [-2, 3, 1], "intensity": 4}
      ]
    })";
}

struct Case {
    const char* name;
    std::string integrator;
    std::string sampling;
};

std::vector<Case> cases() {
    return {
        {"Whitted", "whitted", R"("spp": 4)"},
        {"Path", "path", R"("spp": 4, "max_depth": 4)"},
        {"PathAdaptive", "path", R"("adaptive": {"min_spp": 2, "max_spp": 16, "threshold": 0.05})"},
        {"Radiosity", "radiosity", R"("spp": 2)"}};
}

bool sameBits(const Image& a, const Image& b) {
    if (a.width() != b.width() || a.height() != b.height()) return false;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const Color p = a.at(x, y), q = b.at(x, y);
            if (std::bit_cast<std::uint32_t>(p.r) != std::bit_cast<std::uint32_t>(q.r) ||
                std::bit_cast<std::uint32_t>(p.g) != std::bit_cast<std::uint32_t>(q.g) ||
                std::bit_cast<std::uint32_t>(p.b) != std::bit_cast<std::uint32_t>(q.b))
                return false;
        }
    return true;
}

class ResumePoints : public testing::TestWithParam<Case> {};

TEST_P(ResumePoints, AfterTheFirstTileHalfWayAndBeforeTheLastTheImageIsTheUninterruptedOne) {
    std::vector<std::string> warnings;
    const Scene scene = SceneLoader::loadString(
        sceneText(GetParam().integrator, GetParam().sampling), "scene.json", warnings);
    const auto integrator = IntegratorRegistry::create(scene);
    const Renderer renderer(scene, *integrator);
    const PixelWindow window{0, 0, kWidth, kHeight};
    const std::size_t tileCount = Renderer::tiles(window).size();
    ASSERT_EQ(tileCount, 15u);

    RenderOptions options;
    options.threads = 1;  // so that no tile is in flight beside the one that stops the render
    options.aovs = Aov::parseList("albedo,normal,depth");
    const RenderResult whole = renderer.render(options);
    ASSERT_FALSE(whole.interrupted);

    for (const std::size_t stopAfter : {std::size_t{1}, tileCount / 2, tileCount - 1}) {
        SCOPED_TRACE("interrupted after " + std::to_string(stopAfter) + " tiles");
        std::atomic<bool> cancel{false};
        RenderOptions interrupted = options;
        interrupted.cancel = &cancel;
        interrupted.onTileDone = [&](const FinishedTile& done) {
            if (static_cast<std::size_t>(done.tilesDone) == stopAfter) cancel = true;
        };
        const RenderResult partial = renderer.render(interrupted);
        ASSERT_TRUE(partial.interrupted);
        ASSERT_EQ(std::count(partial.finishedTiles.begin(), partial.finishedTiles.end(), true),
                  static_cast<std::ptrdiff_t>(stopAfter));

        const TempFolder folder;
        const fs::path file = folder / "out.pfm.resume";
        ResumeFile::write(file, kFingerprint, window, partial);
        const RenderResult saved =
            ResumeFile::read(file, kFingerprint, kWidth, kHeight, window, options.aovs.size());

        RenderOptions resumed = options;
        resumed.resumeFrom = &saved;
        std::vector<std::size_t> reported;
        resumed.onTileDone = [&](const FinishedTile& done) { reported.push_back(*done.index); };
        const RenderResult finished = renderer.render(resumed);
        EXPECT_FALSE(finished.interrupted);
        // Every tile reported once, the kept ones first.
        ASSERT_EQ(reported.size(), tileCount);
        for (std::size_t i = 0; i < tileCount; ++i)
            EXPECT_EQ(partial.finishedTiles[reported[i]], i < stopAfter) << "report " << i;
        EXPECT_TRUE(sameBits(finished.film, whole.film));
        ASSERT_EQ(finished.aovFilms.size(), whole.aovFilms.size());
        for (std::size_t i = 0; i < whole.aovFilms.size(); ++i)
            EXPECT_TRUE(sameBits(finished.aovFilms[i], whole.aovFilms[i])) << options.aovs[i]->name;
        EXPECT_EQ(finished.counters.samples, whole.counters.samples);
        EXPECT_EQ(finished.counters.rays, whole.counters.rays);

        // The kept tiles are taken from the file, not rendered again: a pixel changed in it is
        // in the image.
        RenderResult marked = saved;
        const PixelWindow kept = Renderer::tiles(window)[reported.front()];
        marked.film.at(kept.x0, kept.y0) = Color(-1);
        resumed.resumeFrom = &marked;
        EXPECT_EQ(renderer.render(resumed).film.at(kept.x0, kept.y0), Color(-1));
    }
}

INSTANTIATE_TEST_SUITE_P(Integrators, ResumePoints, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<Case>& param) {
                             return param.param.name;
                         });

}  // namespace
}  // namespace lancer::test
