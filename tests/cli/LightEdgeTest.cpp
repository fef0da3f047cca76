// "light_edge_factor" in the render block (docs/SCENE-FORMAT.md, `render`): a pixel whose corners
// see emitted light differing by more than display white takes that many times the samples.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "LancerRun.h"

namespace lancer::test {
namespace {

constexpr int kSide = 16;
constexpr double kRadiance = 10;
// The light's rectangle on the plane z = -1, away from the pixels' corners (multiples of 1/8).
constexpr double kLeft = -0.3, kRight = 0.45, kBottom = -0.2, kTop = 0.35;

// A quad light of radiance 10 on black, facing a camera at the origin that looks down -z with a
// 90-degree field of view: on the plane z = -1 the image spans [-1, 1] in x and y, and the
// samples of a pixel (box filter) are spread uniformly over its square there, so the pixel's
// exact value is 10 times the fraction of its square the light covers.
nlohmann::json lightOnBlack(int spp) {
    nlohmann::json scene = nlohmann::json::parse(R"({
      "render": { "width": 16, "height": 16, "integrator": "path", "max_depth": 0 },
      "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1], "vfov": 90 }
    })");
    scene["render"]["spp"] = spp;
    scene["lights"] = nlohmann::json::array({{{"type", "quad"},
                                              {"corner", {kLeft, kBottom, -1}},
                                              {"edge1", {kRight - kLeft, 0, 0}},
                                              {"edge2", {0, kTop - kBottom, 0}},
                                              {"radiance", kRadiance}}});
    return scene;
}

// The fraction of pixel (i, j)'s square, [x0, x0 + 1/8] x [y0, y0 + 1/8] on the plane, that the
// light covers.
double coveredFraction(int i, int j) {
    const double size = 2.0 / kSide;
    const double x0 = -1 + size * i, y0 = 1 - size * (j + 1);
    const double width = std::max(0.0, std::min(x0 + size, kRight) - std::max(x0, kLeft));
    const double height = std::max(0.0, std::min(y0 + size, kTop) - std::max(y0, kBottom));
    return width * height / (size * size);
}

// The largest error, relative to the light's radiance, over the pixels one edge of the light
// crosses (the four corner pixels, which two edges cross, left out); and it checks every other
// pixel is exactly the light's radiance or black.
double largestEdgeError(const Image& image) {
    double largest = 0;
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
            const double covered = coveredFraction(i, j);
            const float value = image.at(i, j)[0];
            if (covered == 0 || covered == 1) {
                EXPECT_EQ(value, static_cast<float>(kRadiance * covered)) << i << ", " << j;
                continue;
            }
            const double size = 2.0 / kSide;
            const double x0 = -1 + size * i, y0 = 1 - size * (j + 1);
            const bool crossedInX = x0 < kLeft || x0 + size > kRight;
            const bool crossedInY = y0 < kBottom || y0 + size > kTop;
            if (crossedInX && crossedInY) continue;
            largest = std::max(largest, std::abs(value / kRadiance - covered));
        }
    return largest;
}

TEST(CliLightEdge, APixelOnALightsEdgeIsItsCoveredFractionOfTheLight) {
    // 4 spp, 16 times on the edge: 64 Owen-scrambled Sobol points, one in each 1/64-wide strip of
    // the pixel across either axis, so the fraction of them a straight edge parallel to an axis
    // leaves on its light side is within 1/64 of the covered fraction.
    EXPECT_LE(largestEdgeError(renderScene(lightOnBlack(4)).image), 1.0 / 64 + 1e-6);
    // Without the extra samples, 4 points in 1/4-wide strips: some pixel is further off (else
    // this test proves nothing).
    EXPECT_GT(largestEdgeError(renderScene(lightOnBlack(4), {"--light-edge-factor", "1"}).image),
              1.0 / 64 + 1e-6);
}

TEST(CliLightEdge, OnlyTheEdgesPixelsTakeMoreSamples) {
    const auto samplesTaken = [](const std::vector<std::string>& options) {
        const TempFolder folder;
        folder.write("scene.json", lightOnBlack(4).dump());
        std::vector<std::string> arguments{"scene.json", "-o", "out.pfm", "--stats", "--quiet"};
        arguments.insert(arguments.end(), options.begin(), options.end());
        const RunResult run = runLancer(arguments, folder.path());
        EXPECT_EQ(run.exitStatus, 0) << run;
        const std::size_t at = run.standardError.find(" rays, ");
        EXPECT_NE(at, std::string::npos) << run;
        return std::stoll(run.standardError.substr(at + 7));
    };
    int edgePixels = 0;
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i)
            edgePixels += coveredFraction(i, j) > 0 && coveredFraction(i, j) < 1;
    EXPECT_EQ(edgePixels, 20);  // the light meets 7 x 5 pixels: the 5 x 3 inside, 20 around
    EXPECT_EQ(samplesTaken({}), kSide * kSide * 4 + edgePixels * 4 * 15);
    EXPECT_EQ(samplesTaken({"--light-edge-factor", "3"}), kSide * kSide * 4 + edgePixels * 4 * 2);
    EXPECT_EQ(samplesTaken({"--light-edge-factor", "1"}), kSide * kSide * 4);
    // One sample a pixel is the classic ray tracer's ray through each pixel's centre, everywhere.
    EXPECT_EQ(samplesTaken({"--spp", "1"}), kSide * kSide);
}

TEST(CliLightEdge, TheOptionRendersWhatTheSceneKeyDoes) {
    nlohmann::json scene = lightOnBlack(4);
    const std::string byOption = renderScene(scene, {"--light-edge-factor", "2"}).bytes;
    scene["render"]["light_edge_factor"] = 2;
    EXPECT_TRUE(byOption == renderScene(scene).bytes);
    EXPECT_FALSE(byOption == renderScene(lightOnBlack(4)).bytes);
}

// A dark sphere in front of a bright background (radiance 3): its outline is an edge of what the
// camera sees emitted, as a light's is; a background at display white or below makes none, white
// being the radiance the exposure shows as white (4 at exposure -2).
TEST(CliLightEdge, ABrightBackgroundsOutlineIsAnEdgeToo) {
    const auto render = [](double background, double exposure,
                           const std::vector<std::string>& options) {
        nlohmann::json scene = nlohmann::json::parse(R"({
          "render": { "width": 12, "height": 12, "spp": 4, "integrator": "path",
                      "max_depth": 0 },
          "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0], "vfov": 30 },
          "materials": { "dark": { "diffuse": 0 } },
          "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 0.9,
                         "material": "dark" } ]
        })");
        scene["background"] = background;
        scene["render"]["exposure"] = exposure;
        return renderScene(scene, options).image;
    };
    const auto changedByEdges = [&](double background, double exposure) {
        return maxAbsoluteDifference(render(background, exposure, {}),
                                     render(background, exposure, {"--light-edge-factor", "1"})) >
               0;
    };
    EXPECT_TRUE(changedByEdges(3, 0));
    EXPECT_FALSE(changedByEdges(1, 0));
    EXPECT_FALSE(changedByEdges(3, -2));
    EXPECT_TRUE(changedByEdges(5, -2));
}

}  // namespace
}  // namespace lancer::test
