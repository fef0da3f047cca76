// Rough and metallic materials end to end: roughness 0 renders the very bytes of the smooth
// mirror and glass (and a named metal those of its explicit conductor), smooth gold shows the
// table's colour head-on, a rough mirror of Fresnel 1 under a uniform sky shows its
// single-scattering albedo (integrated here, independently of lancer's code) in all three
// integrators, and a rough gold and a rough glass sphere under a constant environment agree with
// Mitsuba 3's renders (references made by data/rough/make_references.py) within the noise of both.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "LancerRun.h"

namespace lancer::test {
namespace {

using nlohmann::json;

const fs::path kRoughFolder = fs::path(LANCER_SOURCE_DIR) / "tests/cli/data/rough";

// Spheres of mirror, glass, gold and a conductor over a checker floor, lit by a point light and
// a quad light, seen by every integrator: the materials' keys are edited per test.
json materialsScene(const std::string& integrator) {
    json scene = json::parse(R"({
      "render": { "width": 48, "height": 32, "spp": 4, "max_depth": 4 },
      "camera": { "position": [0, 1.5, 6], "look_at": [0, 0.6, 0], "vfov": 40 },
      "background": [0.2, 0.3, 0.4],
      "materials": {
        "mirror": { "diffuse": 0.1, "reflection": 0.8 },
        "glass": { "diffuse": 0, "transmission": 1, "ior": 1.5 },
        "gold": { "metal": "gold" },
        "conductor": { "conductor": { "eta": [0.143, 0.3753, 1.442], "k": [3.983, 2.3856, 1.6034] } },
        "floor": { "diffuse": { "checker": { "even": 0.8, "odd": 0.2, "scale": 0.5 } } }
      },
      "objects": [
        { "type": "sphere", "center": [-1.8, 0.6, 0], "radius": 0.6, "material": "mirror" },
        { "type": "sphere", "center": [-0.6, 0.6, 0], "radius": 0.6, "material": "glass" },
        { "type": "sphere", "center": [0.6, 0.6, 0], "radius": 0.6, "material": "gold" },
        { "type": "sphere", "center": [1.8, 0.6, 0], "radius": 0.6, "material": "conductor" },
        { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" }
      ],
      "lights": [
        { "type": "point", "position": [3, 5, 4], "intensity": 30 },
        { "type": "quad", "corner": [-1, 4, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 2],
          "radiance": 3, "samples": 2 }
      ]
    })");
    scene["render"]["integrator"] = integrator;
    if (integrator == "radiosity") scene["radiosity"] = {{"patch_size", 1}};
    return scene;
}

class RoughnessZero : public testing::TestWithParam<std::string> {};

// "roughness": 0 is the smooth mirror, glass and conductor of before, to the byte; and "metal":
// "gold" is the conductor of the table's eta and k.
TEST_P(RoughnessZero, RendersTheSameBytesAsTheSmoothMaterials) {
    const json smooth = materialsScene(GetParam());
    json zero = smooth;
    for (const char* name : {"mirror", "glass", "gold"})
        zero["materials"][name]["roughness"] = 0;
    json conductor = smooth;
    conductor["materials"]["gold"] = json::parse(
        R"({ "conductor": { "eta": [0.143, 0.3753, 1.442], "k": [3.983, 2.3856, 1.6034] } })");
    const RenderedFile a = renderScene(smooth);
    EXPECT_EQ(a.bytes, renderScene(zero).bytes);
    EXPECT_EQ(a.bytes, renderScene(conductor).bytes);
}

INSTANTIATE_TEST_SUITE_P(Integrators, RoughnessZero,
                         testing::Values("whitted", "path", "radiosity"));

// The single-scattering albedo of a GGX mirror of Fresnel 1 seen head-on, written out again here
// in double: wo = z, so G1(wo) = 1 and f cos_i = D(h) G1(wi) / 4 with theta_h = theta_i / 2;
// integrated over the hemisphere by the midpoint rule in cos theta_i (200 000 bands).
double headOnAlbedo(double alpha) {
    const double a2 = alpha * alpha;
    constexpr int kBands = 200000;
    double sum = 0;
    for (int i = 0; i < kBands; ++i) {
        const double cosI = (i + 0.5) / kBands;
        const double thetaH = std::acos(cosI) / 2;
        const double cosH = std::cos(thetaH), tanH2 = std::pow(std::tan(thetaH), 2);
        const double d = a2 / (std::numbers::pi * std::pow(cosH, 4) * std::pow(a2 + tanH2, 2));
        const double tanI2 = (1 - cosI * cosI) / (cosI * cosI);
        const double g1 = 2 / (1 + std::sqrt(1 + a2 * tanI2));
        sum += d * g1 / 4;
    }
    return 2 * std::numbers::pi * sum / kBands;
}

// A unit sphere of the given material under a sky of radiance 1, seen head-on from 4 units away
// through a 2-degree view (5 x 5 pixels): the normal turns by at most 1.5 degrees over the view.
Image sphereUnderUniformSky(const json& material, int spp, const std::string& integrator) {
    json scene = json::parse(R"({
      "render": { "width": 5, "height": 5, "max_depth": 3 },
      "camera": { "position": [0, 0, 4], "look_at": [0, 0, 0], "vfov": 2 },
      "background": 1,
      "ambient": 0,
      "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" } ]
    })");
    scene["materials"] = {{"m", material}};
    scene["render"]["spp"] = spp;
    scene["render"]["integrator"] = integrator;
    return renderScene(scene).image;
}

class RoughMirrorUnderUniformSky : public testing::TestWithParam<std::string> {};

// A rough mirror sphere (alpha 0.6, kr 1, no Fresnel) under the uniform sky: every pixel is the
// albedo head-on (the 1.5 degrees the normal turns move it by under 1e-4). The estimate averages 25
// x 1024 samples of weights G1(wi) in [0, 1], or 0 for a reflection into the surface (a standard
// deviation near 0.35): a standard error near 0.0022, so 0.011 is 5 of them.
TEST_P(RoughMirrorUnderUniformSky, ShowsTheSingleScatteringAlbedo) {
    const Image image = sphereUnderUniformSky(
        json::parse(R"({ "diffuse": 0, "reflection": 1, "roughness": 0.6 })"), 1024, GetParam());
    const double expected = headOnAlbedo(0.6);
    // The known single-scattering loss: 41% at alpha 0.6 head-on, of which alpha^2 / (1 +
    // alpha^2) = 26% are the microfacets beyond 45 degrees, whose reflection enters the surface.
    EXPECT_NEAR(expected, 0.5915, 1e-4);
    EXPECT_NEAR(meanValue(image), expected, 0.011);
}

INSTANTIATE_TEST_SUITE_P(Integrators, RoughMirrorUnderUniformSky,
                         testing::Values("whitted", "path", "radiosity"));

class SmoothGoldUnderUniformSky : public testing::TestWithParam<std::string> {};

// A smooth gold sphere under the uniform sky reflects it with the table's reflectance at normal
// incidence (docs/SCENE-FORMAT.md: 0.967, 0.802, 0.324); over the 1.5 degrees the normal turns,
// the Fresnel term changes by under 1e-4.
TEST_P(SmoothGoldUnderUniformSky, ShowsTheTablesColourHeadOn) {
    const Image image = sphereUnderUniformSky(json::parse(R"({ "metal": "gold" })"), 1, GetParam());
    for (const Image::Rgb& pixel : image.pixels) {
        EXPECT_NEAR(pixel[0], 0.967, 6e-4);
        EXPECT_NEAR(pixel[1], 0.802, 6e-4);
        EXPECT_NEAR(pixel[2], 0.324, 6e-4);
    }
}

INSTANTIATE_TEST_SUITE_P(Integrators, SmoothGoldUnderUniformSky,
                         testing::Values("whitted", "path", "radiosity"));

// Against Mitsuba 3: the noise of one render is rmse(a, b) / sqrt(2) for two seeds (4 x 4 pixel
// blocks), the reference's that times sqrt(spp / 4096) (Mitsuba's variance per sample taken as
// ours); an unbiased render's error is then their hypotenuse, up to the estimate's own scatter
// (a few per cent over 768 values): the test allows 25% more, plus 0.3% of the mean for what
// differs besides noise (the table's eta and k rounded to 4 decimals, float arithmetic).
// Measured: gold noise 0.0011, error 0.0017; glass noise 0.0083, error 0.0077. Gold rendered with
// roughness 0.33 instead of 0.3 has an error of 0.0185, four times the bound.
void expectMatchesMitsuba(const std::string& name) {
    constexpr int kSpp = 64, kReferenceSpp = 4096, kRoughBlock = 4;
    const Image reference = blockAverage(
        loadImage(kRoughFolder / ("mitsuba-rough-" + name + "-4096spp.exr")), kRoughBlock);
    const auto render = [&](const char* seed) {
        return blockAverage(renderSceneFile(kRoughFolder / ("rough-" + name + ".json"),
                                            {"--spp", std::to_string(kSpp), "--seed", seed})
                                .image,
                            kRoughBlock);
    };
    const Image first = render("1"), second = render("2");
    const double noise = relativeRmse(first, second) / std::sqrt(2.0);
    const double referenceNoise = noise * std::sqrt(static_cast<double>(kSpp) / kReferenceSpp);
    const double expected = std::hypot(noise, referenceNoise);
    const double error = relativeRmse(first, reference);
    std::printf("[ rough %s ] %d spp, 4x4 blocks: noise %.4f, error %.4f, mean ratio %.4f\n",
                name.c_str(), kSpp, noise, error, meanValue(first) / meanValue(reference));
    EXPECT_LE(error, 1.25 * expected + 0.003) << "noise " << noise;
    EXPECT_NEAR(meanValue(first) / meanValue(reference), 1.0, 0.005);
}

TEST(RoughAgainstMitsuba, RoughGoldSphereMatchesTheReferenceWithinItsNoise) {
    expectMatchesMitsuba("gold");
}

TEST(RoughAgainstMitsuba, RoughGlassSphereMatchesTheReferenceWithinItsNoise) {
    expectMatchesMitsuba("glass");
}

}  // namespace
}  // namespace lancer::test
