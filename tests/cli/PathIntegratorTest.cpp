// The path integrator end to end, on linear renders: closed furnaces whose radiance is known in
// closed form (Le / (1 - rho) with every bounce, a geometric series when max_depth cuts it),
// direct lighting from delta lights, one-sided emitters, overflowing samples, determinism, and
// the Cornell box against Mitsuba 3's 16384-spp reference, with a tolerance derived from the
// measured noise.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ClosedForm.h"
#include "LancerRun.h"

namespace lancer::test {
namespace {

using nlohmann::json;

json pathScene(int width, int height, int spp, int maxDepth) {
    return {{"render",
             {{"width", width},
              {"height", height},
              {"spp", spp},
              {"max_depth", maxDepth},
              {"integrator", "path"}}},
            {"background", 0},
            {"objects", json::array()},
            {"lights", json::array()}};
}

// The camera at `position` looking along -z, with a wide view so the image sees many directions.
void placeCamera(json& scene, const json& position) {
    scene["camera"] = {{"position", position},
                       {"look_at", {position[0], position[1], position.at(2).get<double>() - 1}},
                       {"vfov", 100}};
}

// Every pixel, channel by channel, against `expected`: |value - expected| <= relative * expected.
// Returns the largest relative deviation seen, for the failure message.
double expectEveryPixelNear(const Image& image, const Radiance& expected, double relative) {
    double worst = 0;
    int failures = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Image::Rgb& p = image.at(x, y);
            const double want[3] = {expected.r, expected.g, expected.b};
            for (int c = 0; c < 3; ++c) {
                const double deviation = std::abs(p[c] - want[c]) / want[c];
                worst = std::max(worst, deviation);
                if (deviation > relative && ++failures <= 5)
                    ADD_FAILURE() << "pixel (" << x << ", " << y << ") channel " << c << ": "
                                  << p[c] << ", expected " << want[c];
            }
        }
    return worst;
}

// --- Furnaces --------------------------------------------------------------------------------

// A closed surface of albedo rho that emits Le everywhere, seen from inside: every path sees Le
// at each of its vertices, weighted rho^k after k bounces, so L = Le (1 + rho + rho^2 + ...) =
// Le / (1 - rho), at every pixel and in any direction. Paths are cut at max_depth 200 (rho^200
// is nothing) and ended early by Russian roulette, which must not bias the result.
struct FurnaceCase {
    std::string name;
    json scene;
    Radiance expected;
};

json sphereFurnace(const json& material) {
    json scene = pathScene(8, 8, 1024, 200);
    placeCamera(scene, {0.1, -0.2, 0.3});
    scene["materials"] = {{"furnace", material}};
    scene["objects"].push_back(
        {{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", "furnace"}});
    return scene;
}

// A cube [-1, 1]^3 of 12 triangles wound so that their front (emitting) side faces inwards.
json boxFurnace(const json& material) {
    json scene = pathScene(8, 8, 1024, 200);
    placeCamera(scene, {0.3, 0.2, 0.5});
    scene["materials"] = {{"furnace", material}};
    // Each face: its four corners clockwise seen from inside the box (counter-clockwise from
    // outside), so the triangles (0, 2, 1) and (0, 3, 2) face inwards.
    const std::vector<std::array<std::array<int, 3>, 4>> faces{
        {{{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}},  // floor, seen from above
        {{{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}}},      // ceiling
        {{{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}}},  // back
        {{{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}},      // front
        {{{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}}},  // left
        {{{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}}}};     // right
    for (const auto& f : faces)
        for (const auto& tri : {std::array<int, 3>{0, 2, 1}, std::array<int, 3>{0, 3, 2}})
            scene["objects"].push_back({{"type", "triangle"},
                                        {"vertices", {f[tri[0]], f[tri[1]], f[tri[2]]}},
                                        {"material", "furnace"}});
    return scene;
}

// The cavity that two overlapping spheres carve in a box, a csg: seen from inside, its surface is
// the spheres' carved pieces, whose fronts (out of the result) face the eye.
json csgCavityFurnace(const json& material) {
    json scene = pathScene(8, 8, 1024, 200);
    placeCamera(scene, {0.1, -0.2, 0.3});
    scene["materials"] = {{"furnace", material}};
    scene["objects"].push_back(json::parse(R"({
      "type": "csg", "operation": "difference", "material": "furnace", "objects": [
        { "type": "box", "min": [-2, -2, -2], "max": [2, 2, 2] },
        { "type": "csg", "operation": "union", "objects": [
          { "type": "sphere", "center": [-0.3, 0, 0], "radius": 1 },
          { "type": "sphere", "center": [0.5, 0.2, 0], "radius": 0.8 } ] } ] })"));
    return scene;
}

// Radiance Le / (1 - rho) per channel.
Radiance furnaceRadiance(const Radiance& le, const Radiance& rho) {
    return {le.r / (1 - rho.r), le.g / (1 - rho.g), le.b / (1 - rho.b)};
}

const json kFurnaceDiffuse{{"diffuse", {0.3, 0.5, 0.7}}, {"emission", {1.0, 0.5, 0.25}}};
// Diffuse and mirror shares: still rho = kd + kr in every direction.
const json kFurnaceDiffuseAndMirror{
    {"diffuse", {0.2, 0.3, 0.1}}, {"reflection", 0.4}, {"emission", {1.0, 0.5, 0.25}}};

class PathFurnace : public testing::TestWithParam<FurnaceCase> {};

// Russian roulette makes the number of bounces random, and with it each path's sum: at 1024
// samples a pixel's channel keeps up to 3% of noise (rho = 0.7: the bounce count's standard
// deviation is 2.8, against a mean of 3.3), so "within 1% everywhere" is checked where noise
// allows it: the mean over the 64 pixels (noise about 0.3%) within 1% in every channel, and
// every pixel within 1% or, where its noise is larger, within 5 standard errors of it (the noise
// measured by a second render with another seed: rms(a - b) / sqrt(2)). Measured on 12 x 12
// pixels: means within 0.14% of Le / (1 - rho).
TEST_P(PathFurnace, SeesLeOverOneMinusRhoEverywhere) {
    const FurnaceCase& c = GetParam();
    const Image first = renderScene(c.scene, {"--seed", "1"}).image;
    const Image second = renderScene(c.scene, {"--seed", "2"}).image;
    const double expected[3] = {c.expected.r, c.expected.g, c.expected.b};
    const auto count = static_cast<double>(first.pixels.size());
    for (std::size_t channel = 0; channel < 3; ++channel) {
        SCOPED_TRACE("channel " + std::to_string(channel));
        double sum = 0, differenceSquared = 0;
        for (std::size_t i = 0; i < first.pixels.size(); ++i) {
            sum += first.pixels[i][channel];
            const double d = first.pixels[i][channel] - second.pixels[i][channel];
            differenceSquared += d * d;
        }
        EXPECT_NEAR(sum / count / expected[channel], 1.0, 0.01) << "the image's mean";
        const double noise = std::sqrt(differenceSquared / count / 2);
        const double allowed = std::max(0.01 * expected[channel], 5 * noise);
        for (std::size_t i = 0; i < first.pixels.size(); ++i)
            EXPECT_NEAR(first.pixels[i][channel], expected[channel], allowed)
                << "pixel " << i << ", noise " << noise;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Furnaces, PathFurnace,
    testing::Values(FurnaceCase{"Sphere", sphereFurnace(kFurnaceDiffuse),
                                furnaceRadiance({1.0, 0.5, 0.25}, {0.3, 0.5, 0.7})},
                    FurnaceCase{"Box", boxFurnace(kFurnaceDiffuse),
                                furnaceRadiance({1.0, 0.5, 0.25}, {0.3, 0.5, 0.7})},
                    FurnaceCase{"SphereDiffuseAndMirror", sphereFurnace(kFurnaceDiffuseAndMirror),
                                furnaceRadiance({1.0, 0.5, 0.25}, {0.6, 0.7, 0.5})},
                    FurnaceCase{"BoxDiffuseAndMirror", boxFurnace(kFurnaceDiffuseAndMirror),
                                furnaceRadiance({1.0, 0.5, 0.25}, {0.6, 0.7, 0.5})},
                    FurnaceCase{"CsgCavity", csgCavityFurnace(kFurnaceDiffuse),
                                furnaceRadiance({1.0, 0.5, 0.25}, {0.3, 0.5, 0.7})},
                    FurnaceCase{"CsgCavityDiffuseAndMirror",
                                csgCavityFurnace(kFurnaceDiffuseAndMirror),
                                furnaceRadiance({1.0, 0.5, 0.25}, {0.6, 0.7, 0.5})}),
    CaseName());

// The box as an OBJ model with its own MTL (Ke, Kd), placed by a rotating and scaling
// transform: its faces become TriangleLights through the instance, and rays that hit them find
// their light by (instance, face) for the MIS weight. A missing or wrong weight counts light
// twice or not at all, far beyond the tolerance.
TEST(PathFurnaceModel, EmissiveObjFacesAreLightsThroughTheirInstance) {
    const TempFolder folder;
    std::string obj = "mtllib box.mtl\nusemtl furnace\n";
    for (const char* v :
         {"-1 -1 -1", "1 -1 -1", "1 1 -1", "-1 1 -1", "-1 -1 1", "1 -1 1", "1 1 1", "-1 1 1"})
        obj += std::string("v ") + v + "\n";
    // Counter-clockwise seen from inside: the faces emit inwards.
    for (const char* f : {"1 2 3 4", "8 7 6 5", "4 8 5 1", "6 7 3 2", "5 6 2 1", "3 7 8 4"})
        obj += std::string("f ") + f + "\n";
    folder.write("box.obj", obj);
    folder.write("box.mtl", "newmtl furnace\nKd 0.3 0.5 0.7\nKe 1 0.5 0.25\nillum 1\n");
    json scene = pathScene(8, 8, 1024, 200);
    placeCamera(scene, {0.5, 0.3, 0.2});
    scene["objects"].push_back(
        {{"type", "mesh"},
         {"file", "box.obj"},
         {"transform", {{"scale", 1.5}, {"rotate", {1, 1, 0, 30}}, {"translate", {0.2, 0, 0}}}}});
    folder.write("scene.json", scene.dump());
    const RunResult run = runLancer({"scene.json", "-o", "out.pfm", "--quiet"}, folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    const Image image = loadImage(folder / "out.pfm");
    const Radiance expected = furnaceRadiance({1.0, 0.5, 0.25}, {0.3, 0.5, 0.7});
    const double want[3] = {expected.r, expected.g, expected.b};
    for (std::size_t channel = 0; channel < 3; ++channel) {
        double sum = 0;
        for (const Image::Rgb& p : image.pixels)
            sum += p[channel];
        EXPECT_NEAR(sum / static_cast<double>(image.pixels.size()) / want[channel], 1.0, 0.01)
            << "channel " << channel;
    }
}

// max_depth counts scattering events: 0 shows the emission only, 1 adds direct lighting, and in
// the furnace depth d gives the partial sum Le (1 + rho + ... + rho^d) exactly.
TEST(PathDepth, FurnaceGivesThePartialGeometricSum) {
    const double rho = 0.5, le = 1;
    for (int depth = 0; depth <= 4; ++depth) {
        json scene = sphereFurnace({{"diffuse", rho}, {"emission", le}});
        scene["render"]["max_depth"] = depth;
        const Image image = renderScene(scene).image;
        const double expected = le * (1 - std::pow(rho, depth + 1)) / (1 - rho);
        SCOPED_TRACE("max_depth " + std::to_string(depth));
        expectEveryPixelNear(image, {expected, expected, expected}, 0.01);
    }
}

// --- Direct lighting from delta lights ------------------------------------------------------

// A diffuse plane of albedo kd under one delta light, with max_depth 1: L = kd / pi * E cos
// (the path tracer's kd is a Lambertian albedo, so it has the 1 / pi that Whitted's shading
// equation leaves out). A delta light is exact in one sample: checked pixel by pixel against the
// closed form.
struct DeltaLightCase {
    std::string name;
    json light;
};

class PathDirectLighting : public testing::TestWithParam<DeltaLightCase> {};

TEST_P(PathDirectLighting, DiffusePlaneShowsKdOverPiTimesECosine) {
    const json& light = GetParam().light;
    const CameraModel camera{{0, 3, 4}, {0, 0, 0}, {0, 1, 0}, 50, 32, 24};
    json scene = pathScene(camera.width, camera.height, 1, 1);
    camera.placeIn(scene);
    scene["render"]["integrator"] = "path";
    scene["render"]["max_depth"] = 1;
    scene["materials"] = {{"floor", {{"diffuse", {0.8, 0.5, 0.2}}}}};
    scene["objects"].push_back(
        {{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "floor"}});
    scene["lights"] = {light};
    const Image image = renderScene(scene).image;
    const Radiance kd{0.8, 0.5, 0.2};
    const int checked = expectPixelsMatch(
        image, camera,
        [&](const RayD& ray) -> std::optional<Radiance> {
            const auto t = intersectPlane(ray, {0, 0, 0}, {0, 1, 0});
            if (!t) return Radiance{};
            const Incident in = incidentLight(light, ray.at(*t));
            const double cosine = std::max(0.0, in.towardsLight.y);
            return (cosine / std::numbers::pi) * (kd * in.irradiance);
        },
        1e-4, 1e-6);
    EXPECT_GT(checked, 300);
}

INSTANTIATE_TEST_SUITE_P(
    Lights, PathDirectLighting,
    testing::Values(
        DeltaLightCase{"Point",
                       {{"type", "point"}, {"position", {1, 2, 0.5}}, {"intensity", {10, 20, 30}}}},
        DeltaLightCase{
            "PointWithoutFalloff",
            {{"type", "point"}, {"position", {-1, 1, 0}}, {"intensity", 0.7}, {"falloff", "none"}}},
        DeltaLightCase{
            "Directional",
            {{"type", "directional"}, {"direction", {-1, -2, -0.5}}, {"irradiance", {0.5, 1, 2}}}}),
    CaseName());

// --- Emitters -------------------------------------------------------------------------------

// A triangle emits from its front side only: seen from behind it is black, and a floor under a
// triangle facing up receives nothing from it, with light sampling (its TriangleLight) as well
// as with BSDF rays.
TEST(PathEmitters, TrianglesEmitFromTheirFrontSideOnly) {
    json scene = pathScene(16, 16, 16, 3);
    // Above the lamp's plane, looking down at it and at the floor around it.
    scene["camera"] = {{"position", {0, 2, 3}}, {"look_at", {0, 1, 0}}, {"vfov", 60}};
    scene["materials"] = {{"lamp", {{"diffuse", 0}, {"emission", 5}}},
                          {"floor", {{"diffuse", 0.8}}}};
    scene["objects"].push_back(
        {{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "floor"}});
    // Counter-clockwise seen from above: its front faces up, away from the floor.
    scene["objects"].push_back({{"type", "triangle"},
                                {"vertices", {{-1, 1, 1}, {1, 1, 1}, {0, 1, -1}}},
                                {"material", "lamp"}});
    const Image upward = renderScene(scene).image;
    // The bottom row sees the floor in front of the lamp; the lamp's front is in the middle.
    EXPECT_NEAR(upward.at(8, 8)[0], 5, 1e-5) << "the camera sees the lamp's front";
    double upwardFloor = 0;
    for (int x = 0; x < upward.width; ++x)
        upwardFloor += upward.at(x, upward.height - 1)[0];
    EXPECT_EQ(upwardFloor, 0) << "the floor is lit by the back of the lamp";

    // Flipped to face the floor, the lamp lights it.
    scene["objects"][1]["vertices"] = {{-1, 1, 1}, {0, 1, -1}, {1, 1, 1}};
    const Image downward = renderScene(scene).image;
    double downwardFloor = 0;
    for (int x = 0; x < downward.width; ++x)
        downwardFloor += downward.at(x, downward.height - 1)[0];
    EXPECT_GT(downwardFloor, 0.1);
    EXPECT_EQ(downward.at(8, 8)[0], 0) << "the camera sees the lamp's back";
}

// --- Samples that overflow ------------------------------------------------------------------

// An emitter near the largest float: its power overflows (the light is still chosen, not an
// error), and some samples through the floor overflow to infinity. They are dropped and counted
// by --stats; the image stays finite.
TEST(PathOverflow, InfiniteSamplesAreDroppedAndCounted) {
    const TempFolder folder;
    json scene = pathScene(8, 8, 4, 3);
    scene["camera"] = {{"position", {0, 1, 3}}, {"look_at", {0, 0, 0}}, {"vfov", 60}};
    scene["materials"] = {{"lamp", {{"diffuse", 0}, {"emission", 3.4e38}}},
                          {"floor", {{"diffuse", 0.8}}}};
    scene["objects"].push_back(
        {{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "floor"}});
    scene["objects"].push_back(
        {{"type", "sphere"}, {"center", {0, 0.5, 0}}, {"radius", 0.45}, {"material", "lamp"}});
    folder.write("scene.json", scene.dump());
    const RunResult run = runLancer({"scene.json", "-o", "out.pfm", "--stats"}, folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    const std::string all = run.standardOutput + run.standardError;
    const std::size_t at = all.find(" of them NaN or infinite");
    ASSERT_NE(at, std::string::npos) << run;
    const std::size_t start = all.rfind(' ', at - 1) + 1;
    EXPECT_GT(std::stoi(all.substr(start, at - start)), 0) << run;
    for (const Image::Rgb& p : loadImage(folder / "out.pfm").pixels)
        for (const float v : p)
            EXPECT_TRUE(std::isfinite(v));
}

// --- Determinism ---------------------------------------------------------------------------

TEST(PathDeterminism, OneAndTwoThreadsWriteByteIdenticalFiles) {
    const fs::path scene = fs::path(LANCER_SOURCE_DIR) / "tests/cli/data/cornell/cornell.json";
    const std::vector<std::string> options{"--width", "48", "--height", "48", "--spp", "4"};
    auto withThreads = [&](const char* threads) {
        std::vector<std::string> o = options;
        o.insert(o.end(), {"--threads", threads, "--seed", "3"});
        return renderSceneFile(scene, o).bytes;
    };
    EXPECT_TRUE(withThreads("1") == withThreads("2")) << "the files differ";
}

// --- Against Mitsuba 3 ------------------------------------------------------------------------

// The Cornell box of ../shared/references/cornell (Mitsuba 3.9.1's cornell_box() as a lancer
// scene, and its path-traced image: 16384 spp, box filter, max_depth 8 in Mitsuba's counting =
// 7 in ours). Stored here: the scene, and the reference averaged over 8 x 8 pixel blocks (32 x 32
// values, 12 kB instead of 750 kB; averaging keeps any bias and divides the noise by 8).
const fs::path kCornellFolder = fs::path(LANCER_SOURCE_DIR) / "tests/cli/data/cornell";
constexpr int kBlock = 8;

// Two renders with different seeds measure the noise: their difference has twice the variance
// of one, so the noise of one is rmse(a, b) / sqrt(2). The reference has noise of its own; at
// 16384 samples against our spp it is sqrt(spp / 16384) of ours (taking Mitsuba's variance per
// sample as ours). An unbiased render's error against the reference is then
// sqrt(noise^2 + referenceNoise^2), up to the estimate's own scatter (a few per cent over 3072
// values); the test allows 20% more plus 0.5% of bias. Measured at 32 spp: noise 1.34%, error
// 1.40%, and the image's mean within 0.01% of the reference's (its own noise is about 0.05%), so
// the mean check catches any error of 1% in the light's power or the walls' albedo; a wrong
// picture (a missing shadow, a colour bleeding wrongly) shows in the block error. A max_depth
// one short is only 0.6% darker: PathDepth checks depth exactly.
TEST(PathAgainstMitsuba, CornellBoxMatchesTheReferenceWithinItsNoise) {
    constexpr int kSpp = 32;
    const Image reference = loadImage(kCornellFolder / "mitsuba-path-16384spp-8x8-blocks.pfm");
    auto render = [&](const char* seed) {
        return blockAverage(renderSceneFile(kCornellFolder / "cornell.json",
                                            {"--spp", std::to_string(kSpp), "--seed", seed})
                                .image,
                            kBlock);
    };
    const Image first = render("1"), second = render("2");
    ASSERT_EQ(first.width, reference.width);
    ASSERT_EQ(first.height, reference.height);
    const double noise = relativeRmse(first, second) / std::sqrt(2.0);
    const double referenceNoise = noise * std::sqrt(kSpp / 16384.0);
    const double expected = std::hypot(noise, referenceNoise);
    const double error = relativeRmse(first, reference);
    std::printf("[ cornell  ] %d spp, 8x8 blocks: noise %.4f, error %.4f, mean ratio %.4f\n", kSpp,
                noise, error, meanValue(first) / meanValue(reference));
    EXPECT_LE(error, 1.2 * expected + 0.005) << "noise " << noise;
    // The image's mean (the light's power and every bounce) to 1%: its noise is far smaller.
    EXPECT_NEAR(meanValue(first) / meanValue(reference), 1.0, 0.01);
}

// The stored block averages are those of the full reference (copied beside them).
TEST(PathAgainstMitsuba, StoredBlocksAreTheFullReferenceAveraged) {
    const fs::path full = kCornellFolder / "mitsuba-path-16384spp.exr";
    const Image stored = loadImage(kCornellFolder / "mitsuba-path-16384spp-8x8-blocks.pfm");
    const Image averaged = blockAverage(loadImage(full), kBlock);
    ASSERT_EQ(stored.width, averaged.width);
    EXPECT_LT(maxAbsoluteDifference(stored, averaged), 1e-5);
}

}  // namespace
}  // namespace lancer::test
