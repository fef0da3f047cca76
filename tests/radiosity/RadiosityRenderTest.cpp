// The radiosity integrator end to end: furnaces seen from inside, the Cornell box against
// Mitsuba 3's path-traced reference, saved and loaded solutions, and every error.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "LancerRun.h"
#include "RadiosityTestSupport.h"

namespace lancer::test {
namespace {

using nlohmann::json;

constexpr int kBadInput = 2;

json sceneWith(const std::string& objects, const std::string& material) {
    return json::parse(R"({
      "render": {"width": 16, "height": 12, "spp": 1, "integrator": "radiosity"},
      "camera": {"position": [0.5, 0.5, 0.5], "look_at": [0.2, 0.3, 0.1], "vfov": 100},
      "materials": {"glow": )" +
                       material + R"(},
      "objects": [)" + objects +
                       R"(],
      "radiosity": {"patch_size": 0.5, "threshold": 1e-4}
    })");
}

// Le / (1 - rho) at every pixel, within 1%.
void expectFurnace(const Image& image, double expected) {
    for (const auto& pixel : image.pixels)
        for (float channel : pixel)
            ASSERT_NEAR(channel, expected, 0.01 * expected);
}

// Inside a sphere of albedo 0.7 emitting 0.3: 0.3 / (1 - 0.7) everywhere.
json insideAGlowingSphere() {
    json scene = sceneWith(
        R"({"type": "sphere", "center": [0.5, 0.5, 0.5], "radius": 1, "material": "glow"})",
        R"({"diffuse": 0.7, "emission": 0.3})");
    scene["radiosity"]["patch_size"] = 1;
    return scene;
}

TEST(RadiosityRender, ClosedSphereFurnace) {
    expectFurnace(renderScene(insideAGlowingSphere()).image, 0.3 / (1 - 0.7));
}

TEST(RadiosityRender, ClosedBoxFurnace) {
    // The box [0, 1]^3 of inward-facing squares (triangles emit on their front side only).
    const std::string box = closedBox("glow");
    expectFurnace(renderScene(sceneWith(box, R"({"diffuse": 0.5, "emission": 0.2})")).image,
                  0.2 / (1 - 0.5));
}

// The final gather from inside an emissive sphere: sampling the sphere by area from a point of
// it, and gathering the uniform solution, are both exact, so the furnace holds pixel by pixel.
TEST(RadiosityRender, ClosedSphereFurnaceWithAFinalGather) {
    json scene = insideAGlowingSphere();
    scene["radiosity"]["final_gather"] = 8;
    expectFurnace(renderScene(scene).image, 0.3 / (1 - 0.7));
}

// The direct light computed at the eye rays' hits, the indirect part from the solution: from
// inside an emissive sphere, sampling it by area from a point of it is exact, so the furnace
// holds pixel by pixel (with the direct part counted twice or not at all it would be off by pi Le
// of the 3.3 pi Le).
TEST(RadiosityRender, ClosedSphereFurnaceWithDirectSamples) {
    json scene = insideAGlowingSphere();
    scene["radiosity"]["direct_samples"] = 4;
    expectFurnace(renderScene(scene).image, 0.3 / (1 - 0.7));
}

// A glossy surface (the normalized Blinn-Phong lobe alone, no diffuse part) reflects what its
// lobe sees, as the path tracer's first bounce does: the two integrators estimate the same
// light, so their images agree on average within their noise. The scenes: a glossy disk inside an
// emitting sphere (the light of a room), under an emissive disk (a lamp that is a surface, not a
// light), under a quad light, and under a point light (whose highlight no traced ray meets).
struct GlossyCase {
    std::string name;
    std::string objects;  // besides the glossy disk
    std::string lights;
    // Relative, on the image's mean: about four times the standard deviation of the two renders'
    // difference (measured over 5 to 20 seeds: radiosity's mean 0.23% in the sphere, 0.10% and
    // 0.11% under the lamps, which its light samples find; path's 0.04% to 0.07%; none under the
    // point light).
    double tolerance;
};

json glossyScene(const GlossyCase& c, const std::string& integrator) {
    return json::parse(R"({
      "render": {"width": 32, "height": 24, "spp": 64, "integrator": ")" +
                       integrator + R"("},
      "camera": {"position": [0, 1.2, 2.5], "look_at": [0, 0, 0], "vfov": 40},
      "materials": {"glossy": {"diffuse": 0, "specular": 0.8, "shininess": 30},
                    "glow": {"diffuse": 0, "emission": 2}},
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 2,
                   "material": "glossy"})" +
                       c.objects + R"(],
      "lights": [)" + c.lights +
                       R"(],
      "radiosity": {"patch_size": 4}
    })");
}

double imageMean(const Image& image) {
    double sum = 0;
    for (const auto& pixel : image.pixels)
        for (float channel : pixel)
            sum += channel;
    return sum / (3.0 * static_cast<double>(image.pixels.size()));
}

// The relative RMSE, sqrt(mean (a - b)^2) / mean(b), over the pixels (x, y) that `counts`.
template <typename Counts>
double relativeRmse(const Image& image, const Image& reference, Counts counts) {
    double squared = 0, sum = 0;
    std::size_t count = 0;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            if (!counts(x, y)) continue;
            for (int c = 0; c < 3; ++c) {
                const double d = image.at(x, y)[c] - reference.at(x, y)[c];
                squared += d * d;
                sum += reference.at(x, y)[c];
            }
            count += 3;
        }
    return std::sqrt(squared / static_cast<double>(count)) / (sum / static_cast<double>(count));
}

class RadiosityGlossy : public testing::TestWithParam<GlossyCase> {};

TEST_P(RadiosityGlossy, ReflectsWhatThePathTracerReflects) {
    const double radiosity = imageMean(renderScene(glossyScene(GetParam(), "radiosity")).image);
    const double path = imageMean(renderScene(glossyScene(GetParam(), "path")).image);
    ASSERT_GT(path, 0.01);
    EXPECT_NEAR(radiosity, path, GetParam().tolerance * path);
}

INSTANTIATE_TEST_SUITE_P(
    Lighting, RadiosityGlossy,
    testing::Values(
        GlossyCase{"InsideAnEmittingSphere",
                   R"(, {"type": "sphere", "center": [0, 0, 0], "radius": 6, "material": "glow"})",
                   "", 0.01},
        GlossyCase{"UnderAnEmissiveDisk",
                   R"(, {"type": "disk", "center": [0, 1.5, -1], "normal": [0, -1, 0.5],
                         "radius": 0.6, "material": "glow"})",
                   "", 0.005},
        GlossyCase{"UnderAQuadLight", "",
                   R"({"type": "quad", "corner": [-0.5, 1.5, -1.5], "edge1": [1, 0, 0],
                       "edge2": [0, 0, 1], "radiance": 3})",
                   0.005},
        GlossyCase{"UnderAPointLight", "",
                   R"({"type": "point", "position": [0, 1.5, -1], "intensity": 2})", 1e-4}),
    CaseName{});

// Lobes whose weights sum to more than 1 (diffuse 0.6 and specular 0.8, as MTL files often have)
// are scaled as the path tracer scales them, in the solution and in the image: the two
// integrators agree on a disk of such a material inside an emitting sphere. (With the weights as
// given, radiosity's disk was 40% too bright.) The tolerance is about four times the spread of
// the renders' difference (0.12% each, over 5 seeds).
TEST(RadiosityRender, WeighsALobesSumOverOneAsThePathTracer) {
    GlossyCase inASphere{"", R"(, {"type": "sphere", "center": [0, 0, 0], "radius": 6,
                                   "material": "glow"})",
                         "", 0};
    const auto render = [&](const std::string& integrator) {
        json scene = glossyScene(inASphere, integrator);
        scene["materials"]["glossy"] = {{"diffuse", 0.6}, {"specular", 0.8}, {"shininess", 30}};
        return imageMean(renderScene(scene).image);
    };
    const double radiosity = render("radiosity"), path = render("path");
    EXPECT_NEAR(radiosity, path, 0.007 * path);
}

// The means of `scene`'s image rendered by radiosity (its "radiosity" block updated with
// `radiosity`) and by path (at max_depth `pathDepth`).
struct RadiosityAndPath {
    double radiosity = 0, path = 0;
};
RadiosityAndPath radiosityAndPathMeans(const json& scene, const json& radiosity, int pathDepth) {
    json radiosityScene = scene;
    radiosityScene["render"]["integrator"] = "radiosity";
    radiosityScene["radiosity"].update(radiosity);
    json pathScene = scene;
    pathScene["render"]["integrator"] = "path";
    pathScene["render"]["max_depth"] = pathDepth;
    return {imageMean(renderScene(radiosityScene).image), imageMean(renderScene(pathScene).image)};
}

// A diffuse ceiling lit only through a glossy floor (no diffuse part) reflecting a quad light
// that faces down, its back to the ceiling: radiosity's ceiling gets what path's does by that way
// (path without a depth limit: ceiling, floor, light, and the higher orders, ceiling-floor-ceiling
// ..., which the solution's glossy transport carries too), interpolated from the solution or
// through the final gather (which follows the floor's lobe from each pixel). Without the glossy
// transport and the gather the ceiling is black. Measured: 0.993 (hierarchical), 0.996
// (progressive) and 0.995 (the gather) of path's mean; the tolerance is about four times the
// spread of the gather's and path's difference (over 5 seeds at 32 spp: 2.8% for radiosity with
// the gather, 1.9% for path, so about 1.2% at 256 spp).
class RadiosityThroughAGlossyFloor : public testing::TestWithParam<std::pair<std::string, json>> {};

TEST_P(RadiosityThroughAGlossyFloor, LightsTheCeilingAsThePathTracer) {
    const json scene = json::parse(R"({
      "render": {"width": 24, "height": 16, "spp": 256, "max_depth": 2},
      "camera": {"position": [0, 1.2, 2], "look_at": [0, 2, 0], "vfov": 60},
      "materials": {"glossy": {"diffuse": 0, "specular": 0.8, "shininess": 10},
                    "ceiling": {"diffuse": 0.5}},
      "objects": [
        {"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 3,
         "material": "glossy"},
        {"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 3,
         "material": "ceiling"}],
      "lights": [{"type": "quad", "corner": [-0.25, 1, -0.25], "edge1": [0.5, 0, 0],
                  "edge2": [0, 0, 0.5], "radiance": 10}],
      "radiosity": {"patch_size": 1}
    })");
    const auto [radiosity, path] = radiosityAndPathMeans(scene, GetParam().second, 64);
    ASSERT_GT(path, 0.005);
    std::cout << GetParam().first << ": radiosity / path " << radiosity / path << '\n';
    EXPECT_NEAR(radiosity, path, 0.05 * path);
}

INSTANTIATE_TEST_SUITE_P(
    Ways, RadiosityThroughAGlossyFloor,
    testing::Values(std::pair{std::string("FinalGather"), json{{"method", "hierarchical"},
                                                               {"patch_size", 0.25},
                                                               {"final_gather", 16}}},
                    std::pair{std::string("ProgressiveGlossyTransport"), json{{"patch_size", 0.5}}},
                    std::pair{std::string("GlossyTransport"),
                              json{{"method", "hierarchical"}, {"patch_size", 0.25}}}),
    [](const testing::TestParamInfo<std::pair<std::string, json>>& way) {
        return way.param.first;
    });

// A diffuse receiver whose lit side sees only a glossy ceiling, which reflects a glossy floor
// that reflects a quad light facing down (its back to the ceiling; a black disk under the receiver
// keeps the floor's light off its other side): light reaches the receiver through two glossy
// reflections in a row, then four (floor, ceiling, floor, ceiling), and through its own light
// sent back by the ceiling (as a lamp's highlight on a glossy floor seen in a glossy sphere lights
// cornell-glossy's walls). The solution's glossy transport follows such chains up to four
// reflections; when it stopped at the first glossy surface, the receiver was black. Against path at
// max_depth 5, which holds the same chains: 1.001 measured (at max_depth 64, the longer chains
// add 1.7%); the solution needs small patches here (its vertices' estimate of the chains is 4% low
// at patch_size 0.1, 15% high at 0.25).
TEST(RadiosityRender, LightsAReceiverThroughGlossyReflectionsInARow) {
    const json scene = json::parse(R"({
      "render": {"width": 16, "height": 16, "spp": 256, "max_depth": 5},
      "camera": {"position": [1.2, 1.95, 0.25], "look_at": [1.2, 1.5, 0], "vfov": 40},
      "materials": {"glossy": {"diffuse": 0, "specular": 0.8, "shininess": 10},
                    "receiver": {"diffuse": 0.5}, "black": {"diffuse": 0}},
      "objects": [
        {"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 3,
         "material": "glossy"},
        {"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 3,
         "material": "glossy"},
        {"type": "disk", "center": [1.2, 1.5, 0], "normal": [0, 1, 0], "radius": 0.5,
         "material": "receiver"},
        {"type": "disk", "center": [1.2, 1.49, 0], "normal": [0, -1, 0], "radius": 0.5,
         "material": "black"}],
      "lights": [{"type": "quad", "corner": [-0.25, 1, -0.25], "edge1": [0.5, 0, 0],
                  "edge2": [0, 0, 0.5], "radiance": 10}],
      "radiosity": {"method": "hierarchical", "patch_size": 0.05}
    })");
    const auto [radiosity, path] = radiosityAndPathMeans(scene, json::object(), 5);
    ASSERT_GT(path, 0.002);
    std::cout << "radiosity / path " << radiosity / path << '\n';
    EXPECT_NEAR(radiosity, path, 0.05 * path);
}

// A lone sphere under a quad light (no light comes back to it): radiosity's image against path's
// direct light, pixel for pixel. The light at the solution's vertices goes by the sphere's own
// normal there; by the normal of the flat element each vertex was gathered on (up to 15 degrees
// off), neighbouring vertices disagreed: blotches of +-30% and the image 7.9% too bright
// (hierarchical) or 5.1% too dark (progressive), relative RMSE 33% and 39% over the image.
// Measured now: means 0.999 and 0.991, relative RMSE 8.3% and 5.9% (the interpolation across the
// facets, and the sphere's outline at 16 spp).
TEST(RadiosityRender, ASphereUnderALightIsShadedByItsOwnNormals) {
    const json scene = json::parse(R"({
      "render": {"width": 48, "height": 48, "spp": 16, "max_depth": 1},
      "camera": {"position": [0, 0.7, 0.7], "look_at": [0, 0, 0], "vfov": 45},
      "materials": {"white": {"diffuse": 0.5}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.3, "material": "white"}],
      "lights": [{"type": "quad", "corner": [-0.5, 1, -0.5], "edge1": [1, 0, 0],
                  "edge2": [0, 0, 1], "radiance": 1}]
    })");
    json pathScene = scene;
    pathScene["render"].update({{"integrator", "path"}, {"spp", 1024}});
    const Image path = renderScene(pathScene).image;
    for (const std::string method : {"hierarchical", "progressive"}) {
        json radiosityScene = scene;
        radiosityScene["render"]["integrator"] = "radiosity";
        radiosityScene["radiosity"]["method"] = method;
        const Image radiosity = renderScene(radiosityScene).image;
        const double mean = imageMean(radiosity) / imageMean(path);
        const double error = relativeRmse(radiosity, path, [](int, int) { return true; });
        std::cout << method << ": mean " << mean << ", relative RMSE " << error << '\n';
        EXPECT_NEAR(mean, 1, 0.02) << method;
        EXPECT_LT(error, 0.1) << method;
    }
}

TEST(RadiosityRender, ClosedCsgCavityFurnace) {
    // A sphere carved out of a box, seen from inside: the sphere's patches are the cavity's,
    // facing in. (Where two carving children meet, the patches along the seam converge slowly
    // with the patch size: 0.87-0.92 of the furnace's value at patch size 1, 0.95-0.97 at 0.5.)
    json scene = sceneWith(R"({ "type": "csg", "operation": "difference", "material": "glow",
        "objects": [
          { "type": "box", "min": [-0.6, -0.6, -0.6], "max": [1.6, 1.6, 1.6] },
          { "type": "sphere", "center": [0.5, 0.5, 0.5], "radius": 1 } ] })",
                           R"({"diffuse": 0.7, "emission": 0.3})");
    scene["radiosity"]["patch_size"] = 1;
    expectFurnace(renderScene(scene).image, 0.3 / (1 - 0.7));
}

// The Cornell box of ../shared/references (Mitsuba 3.9.1's, as a lancer scene; copied with its
// reference image into tests/cli/data/cornell) with the given
// radiosity settings, rendered with the radiosity integrator.
Image renderCornell(const json& radiosity, int spp) {
    json scene =
        json::parse(readFile(fs::path(LANCER_CORNELL_DIR) / "cornell.json"), nullptr, true, true);
    scene["radiosity"] = radiosity;
    const TempFolder folder;
    folder.write("scene.json", scene.dump());
    // The solve takes a few seconds, many more under the sanitizers on a busy machine.
    const RunResult run = runLancer({"scene.json", "-o", "out.exr", "--quiet", "--integrator",
                                     "radiosity", "--spp", std::to_string(spp)},
                                    folder.path(), std::chrono::minutes(5));
    if (run.exitStatus != 0) throw std::runtime_error(run.standardError);
    return loadImage(folder / "out.exr");
}

// Mitsuba's reference without a depth limit (bench/mitsuba_cornell_unbounded.py): radiosity
// carries every bounce of light, and the stored reference, cut at 7 bounces, lacks up to 20% of the
// light in the dark corners (docs/BENCHMARKS.md).
Image unboundedCornellReference() {
    return loadImage(fs::path(LANCER_CORNELL_DIR) / "mitsuba-path-unbounded-16384spp.exr");
}

// Whether a pixel lies within 2 pixels of the lamp (a pixel of the reference at 1 or more): the
// lamp's own edge pixels measure anti-aliasing (the references have 16384 samples per pixel), not
// lighting.
bool nearTheLamp(const Image& reference, int x, int y) {
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= reference.width || ny >= reference.height) continue;
            const auto& p = reference.at(nx, ny);
            if (std::max({p[0], p[1], p[2]}) >= 1) return true;
        }
    return false;
}

// The relative RMSE over the pixels farther than 2 pixels from the lamp.
double relativeRmseOffTheLamp(const Image& image, const Image& reference) {
    return relativeRmse(image, reference,
                        [&](int x, int y) { return !nearTheLamp(reference, x, y); });
}

// The given percentile of |a - b| / (b + 1% of b's mean), on the mean of the channels, over the
// pixels farther than 2 pixels from the lamp.
double percentileOfRelativeErrorOffTheLamp(const Image& image, const Image& reference,
                                           double fraction) {
    const auto mean = [](const Image::Rgb& p) { return (p[0] + p[1] + p[2]) / 3.0; };
    double sum = 0;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x)
            sum += mean(reference.at(x, y));
    const double floor = 0.01 * sum / (reference.width * reference.height);
    std::vector<double> errors;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x)
            if (!nearTheLamp(reference, x, y)) {
                const double b = mean(reference.at(x, y));
                errors.push_back(std::abs(mean(image.at(x, y)) - b) / (b + floor));
            }
    std::sort(errors.begin(), errors.end());
    return errors[static_cast<std::size_t>(fraction * static_cast<double>(errors.size() - 1))];
}

TEST(RadiosityRender, CornellBoxAgainstMitsuba) {
    // A fast solve: coarse patches (0.7 instead of 0.43), one level of subdivision instead of
    // two. Measured relative RMSE against Mitsuba's 16384-spp path tracing without a depth
    // limit: 0.0487 (the default settings give 0.0320). What remains (docs/SCENE-FORMAT.md):
    // darkening along corners and contact lines finer than the elements, elements straddling
    // shadow edges, one visibility ray per weak shooter, and the 1% of the power left unshot.
    const Image reference = unboundedCornellReference();
    const Image image =
        renderCornell({{"patch_size", 0.7}, {"threshold", 0.01}, {"subdivision_levels", 1}}, 16);
    ASSERT_EQ(image.width, reference.width);
    const double error = relativeRmseOffTheLamp(image, reference);
    std::cout << "radiosity vs Mitsuba: relative RMSE off the lamp " << error << '\n';
    EXPECT_LT(error, 0.055);
}

TEST(RadiosityRender, HierarchicalCornellBoxAgainstMitsuba) {
    // Hierarchical radiosity with its default settings. Measured relative RMSE against Mitsuba's
    // 16384-spp path tracing without a depth limit: 0.0277 off the lamp (0.0020 absolute, of
    // which about 0.0008 is the reference's own noise), solved in under 2 s on 2 threads.
    const Image reference = unboundedCornellReference();
    const Image image = renderCornell({{"method", "hierarchical"}}, 16);
    ASSERT_EQ(image.width, reference.width);
    const double error = relativeRmseOffTheLamp(image, reference);
    std::cout << "hierarchical radiosity vs Mitsuba: relative RMSE off the lamp " << error << '\n';
    EXPECT_LT(error, 0.033);
}

TEST(RadiosityRender, ClusteredHierarchicalCornellBoxAgainstMitsuba) {
    // Hierarchical radiosity with clusters (the solve starts from the top cluster's link to
    // itself), its other settings the defaults. Measured: 0.0398.
    const Image reference = unboundedCornellReference();
    const Image image = renderCornell({{"method", "hierarchical"}, {"clusters", true}}, 16);
    ASSERT_EQ(image.width, reference.width);
    const double error = relativeRmseOffTheLamp(image, reference);
    std::cout << "clustered hierarchical radiosity vs Mitsuba: relative RMSE off the lamp " << error
              << '\n';
    EXPECT_LT(error, 0.045);
}

TEST(RadiosityRender, HierarchicalCornellBoxWithDirectSamplesAgainstMitsuba) {
    // The lamp's direct light from 16 samples at each eye ray's hit, the rest from the default
    // hierarchical solution. Measured: 0.0265 (0.0277 all from the solution), sampling noise
    // included.
    const Image reference = unboundedCornellReference();
    const Image image = renderCornell({{"method", "hierarchical"}, {"direct_samples", 16}}, 16);
    ASSERT_EQ(image.width, reference.width);
    const double error = relativeRmseOffTheLamp(image, reference);
    std::cout << "hierarchical radiosity, direct samples, vs Mitsuba: relative RMSE off the lamp "
              << error << '\n';
    EXPECT_LT(error, 0.030);
}

// Issue 12's quality measure on a small scene: McGuire's cornell-original at 64 x 64 (16 spp)
// against lancer's path tracer at 16384 spp without a depth limit (tests/radiosity/data), over
// the pixels more than 2 pixels from the lamp (the box's surfaces are all diffuse): the relative
// RMSE, and the 99th percentile of the per-pixel relative error |a - b| / (b + 1% of b's mean)
// on the mean of the channels (blotches, dots and misplaced shadows fail it). The aims: 3% and
// 10%. Measured (2026-12-06): hierarchical defaults 2.51% and 9.8%, with 16 direct samples 2.48%
// and 7.9% (before McGuire's repeated faces were meshed once, the floor beside the short block
// was 10-35% too light). The reference's own noise, scaled from two 4096-spp renders at 200 x 200,
// is about 1% at that percentile.
struct QualityCase {
    std::string name;
    json radiosity;
    double rmseBound, percentileBound;
};

class RadiosityQuality : public testing::TestWithParam<QualityCase> {};

TEST_P(RadiosityQuality, OnCornellOriginal) {
    const fs::path source(LANCER_SOURCE_DIR);
    json scene =
        json::parse(readFile(source / "scenes" / "cornell-original.json"), nullptr, true, true);
    scene["objects"][0]["file"] =
        (source / "scenes" / scene["objects"][0]["file"].get<std::string>()).string();
    scene["render"].update(
        {{"integrator", "radiosity"}, {"width", 64}, {"height", 64}, {"spp", 16}});
    scene["radiosity"] = GetParam().radiosity;
    const Image image = renderScene(scene).image;
    const Image reference = loadImage(source / "tests" / "radiosity" / "data" /
                                      "cornell-original-path-64-16384spp.pfm");
    ASSERT_EQ(image.width, reference.width);
    const double rmse = relativeRmseOffTheLamp(image, reference);
    EXPECT_LT(rmse, GetParam().rmseBound);
    const double percentile = percentileOfRelativeErrorOffTheLamp(image, reference, 0.99);
    EXPECT_LT(percentile, GetParam().percentileBound);
    std::cout << GetParam().name << ": relative RMSE " << rmse << ", 99th percentile " << percentile
              << '\n';
}

INSTANTIATE_TEST_SUITE_P(
    Settings, RadiosityQuality,
    testing::Values(QualityCase{"HierarchicalDefaults", {{"method", "hierarchical"}}, 0.03, 0.11},
                    QualityCase{"HierarchicalWithDirectSamples",
                                {{"method", "hierarchical"}, {"direct_samples", 16}},
                                0.03,
                                0.10}),
    CaseName{});

// A scene file and its views, in a folder of their own.
struct SolutionFiles {
    TempFolder folder;
    fs::path scene;

    explicit SolutionFiles(const json& content)
        : scene(folder.write("scene.json", content.dump())) {}

    // Renders the scene to a.pfm, saving its solution as solution.rad.
    RunResult saveSolution() const {
        return runLancer(
            {"scene.json", "-o", "a.pfm", "--quiet", "--save-radiosity", "solution.rad"},
            folder.path());
    }
};

json smallScene() {
    json scene = sceneWith(square(Vec3(-2, 0, 2), Vec3(4, 0, 0), Vec3(0, 0, -4), "glow") + ", " +
                               R"({"type": "sphere", "center": [0, 0.5, 0], "radius": 0.4,
                                   "material": "glow"})",
                           R"({"diffuse": [0.8, 0.5, 0.3]})");
    scene["camera"] = {{"position", {0, 2, 3}}, {"look_at", {0, 0, 0}}};
    scene["lights"] = json::parse(R"([{"type": "point", "position": [1, 3, 1], "intensity": 20}])");
    scene["radiosity"] = {{"patch_size", 1}};
    return scene;
}

TEST(RadiosityRender, SavedSolutionGivesTheSameImages) {
    const SolutionFiles files(smallScene());
    const RunResult solved = runLancer(
        {"scene.json", "-o", "a.pfm", "--save-radiosity", "solution.rad"}, files.folder.path());
    ASSERT_EQ(solved.exitStatus, 0) << solved;
    EXPECT_NE(solved.standardError.find("patches"), std::string::npos) << solved;
    EXPECT_NE(solved.standardError.find("residual unshot power"), std::string::npos) << solved;
    const RunResult loaded = runLancer(
        {"scene.json", "-o", "b.pfm", "--load-radiosity", "solution.rad"}, files.folder.path());
    ASSERT_EQ(loaded.exitStatus, 0) << loaded;
    EXPECT_EQ(readFile(files.folder / "a.pfm"), readFile(files.folder / "b.pfm"));

    // Another view of the same scene reuses it: the same image as solving again.
    json otherView = smallScene();
    otherView["camera"]["position"] = {2, 1, 2};
    otherView["render"]["width"] = 24;
    files.folder.write("view.json", otherView.dump());
    ASSERT_EQ(runLancer({"view.json", "-o", "c.pfm", "--quiet"}, files.folder.path()).exitStatus,
              0);
    const RunResult reused =
        runLancer({"view.json", "-o", "d.pfm", "--quiet", "--load-radiosity", "solution.rad"},
                  files.folder.path());
    ASSERT_EQ(reused.exitStatus, 0) << reused;
    EXPECT_EQ(readFile(files.folder / "c.pfm"), readFile(files.folder / "d.pfm"));
}

// The final gather and the direct samples are part of the render, not of the solution: a
// solution saved without them is taken by the same scene with them, and gives the image that
// solving again does.
class SavedSolutionServes : public testing::TestWithParam<std::string> {};

TEST_P(SavedSolutionServes, TheRenderKey) {
    const SolutionFiles files(smallScene());
    ASSERT_EQ(files.saveSolution().exitStatus, 0);
    json rendered = smallScene();
    rendered["radiosity"][GetParam()] = 4;
    files.folder.write("rendered.json", rendered.dump());
    const RunResult solved =
        runLancer({"rendered.json", "-o", "b.pfm", "--quiet"}, files.folder.path());
    ASSERT_EQ(solved.exitStatus, 0) << solved;
    const RunResult loaded =
        runLancer({"rendered.json", "-o", "c.pfm", "--quiet", "--load-radiosity", "solution.rad"},
                  files.folder.path());
    ASSERT_EQ(loaded.exitStatus, 0) << loaded;
    EXPECT_EQ(readFile(files.folder / "b.pfm"), readFile(files.folder / "c.pfm"));
    EXPECT_NE(readFile(files.folder / "a.pfm"), readFile(files.folder / "b.pfm"));
}

INSTANTIATE_TEST_SUITE_P(Keys, SavedSolutionServes,
                         testing::Values("final_gather", "direct_samples"));

TEST(RadiosityRender, HierarchicalSolutionIsSavedLoadedAndRefusedForAnotherMethod) {
    json scene = smallScene();
    scene["radiosity"]["method"] = "hierarchical";
    const SolutionFiles files(scene);
    const RunResult solved = runLancer(
        {"scene.json", "-o", "a.pfm", "--save-radiosity", "solution.rad"}, files.folder.path());
    ASSERT_EQ(solved.exitStatus, 0) << solved;
    const RunResult loaded = runLancer(
        {"scene.json", "-o", "b.pfm", "--load-radiosity", "solution.rad"}, files.folder.path());
    ASSERT_EQ(loaded.exitStatus, 0) << loaded;
    EXPECT_EQ(readFile(files.folder / "a.pfm"), readFile(files.folder / "b.pfm"));
    // The same scene solved progressively is another solution.
    files.folder.write("progressive.json", smallScene().dump());
    const RunResult refused =
        runLancer({"progressive.json", "-o", "c.pfm", "--load-radiosity", "solution.rad"},
                  files.folder.path());
    EXPECT_EQ(refused.exitStatus, kBadInput) << refused;
    EXPECT_NE(refused.standardError.find("solved for another scene"), std::string::npos) << refused;
    EXPECT_FALSE(fs::exists(files.folder / "c.pfm"));
}

TEST(RadiosityRender, SameImageWhateverTheThreadCount) {
    // --threads bounds the solve's workers as well as the render's.
    EXPECT_EQ(renderScene(smallScene(), {"--threads", "1"}).bytes,
              renderScene(smallScene(), {"--threads", "2"}).bytes);
    json hierarchical = smallScene();
    hierarchical["radiosity"]["method"] = "hierarchical";
    EXPECT_EQ(renderScene(hierarchical, {"--threads", "1"}).bytes,
              renderScene(hierarchical, {"--threads", "2"}).bytes);
}

struct LoadErrorCase {
    std::string name;
    std::string mention;  // in the error message
    // Makes the mismatch: edits the scene or damages the saved file.
    std::function<void(json& scene, std::string& file)> spoil;
};

class RadiosityLoadError : public testing::TestWithParam<LoadErrorCase> {};

TEST_P(RadiosityLoadError, ExitsWithStatus2AndOneLine) {
    const SolutionFiles files(smallScene());
    ASSERT_EQ(files.saveSolution().exitStatus, 0);
    json scene = smallScene();
    std::string bytes = readFile(files.folder / "solution.rad");
    GetParam().spoil(scene, bytes);
    files.folder.write("scene.json", scene.dump());
    files.folder.write("solution.rad", bytes);
    const RunResult run = runLancer(
        {"scene.json", "-o", "b.pfm", "--load-radiosity", "solution.rad"}, files.folder.path());
    EXPECT_EQ(run.exitStatus, kBadInput) << run;
    ASSERT_EQ(run.errorLines().size(), 1u) << run;
    EXPECT_EQ(run.errorLines()[0].rfind("solution.rad: error: ", 0), 0u) << run;
    EXPECT_NE(run.standardError.find(GetParam().mention), std::string::npos) << run;
    EXPECT_FALSE(fs::exists(files.folder / "b.pfm"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RadiosityLoadError,
    testing::Values(
        LoadErrorCase{
            "OtherMaterial", "another scene",
            [](json& scene, std::string&) { scene["materials"]["glow"]["diffuse"] = 0.5; }},
        LoadErrorCase{"OtherGeometry", "another scene",
                      [](json& scene, std::string&) { scene["objects"][2]["radius"] = 0.5; }},
        LoadErrorCase{"OtherLight", "another scene",
                      [](json& scene, std::string&) { scene["lights"][0]["intensity"] = 30; }},
        LoadErrorCase{"Truncated", "truncated",
                      [](json&, std::string& file) { file.resize(file.size() / 2); }},
        LoadErrorCase{"TrailingBytes", "after its end",
                      [](json&, std::string& file) { file += "x"; }},
        LoadErrorCase{"NotASolution", "not a lancer radiosity file",
                      [](json&, std::string& file) { file = "P3\n1 1\n255\n0 0 0\n"; }},
        LoadErrorCase{"BadVertexIndex", "vertex",
                      [](json&, std::string& file) {
                          // The last face's last vertex index.
                          file.replace(file.size() - 4, 4, std::string(4, '\xff'));
                      }}),
    CaseName{});

TEST(RadiosityRender, MissingSolutionFileIsBadInput) {
    const SolutionFiles files(smallScene());
    const RunResult run = runLancer(
        {"scene.json", "-o", "b.pfm", "--load-radiosity", "nothing.rad"}, files.folder.path());
    EXPECT_EQ(run.exitStatus, kBadInput) << run;
    EXPECT_NE(run.standardError.find("nothing.rad: error: cannot open"), std::string::npos) << run;
}

TEST(RadiosityRender, SolutionOptionsNeedTheRadiosityIntegrator) {
    const SolutionFiles files(smallScene());
    const RunResult run = runLancer(
        {"scene.json", "-o", "b.pfm", "--integrator", "whitted", "--save-radiosity", "s.rad"},
        files.folder.path());
    EXPECT_EQ(run.exitStatus, kBadInput) << run;
    EXPECT_NE(run.standardError.find("need --integrator radiosity"), std::string::npos) << run;
}

struct KeyErrorCase {
    std::string name;
    std::string radiosity;  // the "radiosity" block, on line 2 of the file
    int column;             // where the error is
    std::string mention;
};

class RadiosityKeyError : public testing::TestWithParam<KeyErrorCase> {};

TEST_P(RadiosityKeyError, NamesTheFileLineAndColumn) {
    const KeyErrorCase& c = GetParam();
    TempFolder folder;
    json scene = smallScene();
    scene.erase("radiosity");
    std::string text = scene.dump();
    text.insert(1, "\n\"radiosity\": " + c.radiosity + ",\n");
    folder.write("scene.json", text);
    const RunResult run = runLancer({"scene.json", "-o", "out.png"}, folder.path());
    EXPECT_EQ(run.exitStatus, kBadInput) << run;
    ASSERT_EQ(run.errorLines().size(), 1u) << run;
    EXPECT_EQ(
        run.errorLines()[0].rfind("scene.json:2:" + std::to_string(c.column) + ": error: ", 0), 0u)
        << run;
    EXPECT_NE(run.standardError.find(c.mention), std::string::npos) << run;
    EXPECT_FALSE(fs::exists(folder / "out.png"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RadiosityKeyError,
    testing::Values(
        KeyErrorCase{"MisspeltKey", R"({"patch_sise": 1})", 15, R"(did you mean "patch_size"?)"},
        KeyErrorCase{"NotAnObject", "3", 14, "must be an object"},
        KeyErrorCase{"NegativePatchSize", R"({"patch_size": -1})", 29, "greater than 0"},
        KeyErrorCase{"ThresholdOfOne", R"({"threshold": 1})", 28, "below 1"},
        KeyErrorCase{"NoVisibilityRays", R"({"visibility_rays": 0})", 34, "at least 1"},
        KeyErrorCase{"TooManyRefinedVisibilityRays", R"({"refined_visibility_rays": 2000})", 42,
                     "at most 1024"},
        KeyErrorCase{"TooManyLevels", R"({"subdivision_levels": 9})", 37, "at most 8"},
        KeyErrorCase{"FractionalShots", R"({"max_shots": 2.5})", 28, "whole number"},
        KeyErrorCase{"NoRefinementTolerance", R"({"refinement_tolerance": 0})", 39,
                     "greater than 0"},
        KeyErrorCase{"ClustersNotAFlag", R"({"clusters": 1})", 27, "must be true or false"},
        KeyErrorCase{"UnknownMethod", R"({"method": "hierarchal"})", 25, "radiosity method"},
        KeyErrorCase{"NegativeFinalGather", R"({"final_gather": -1})", 31, "at least 0"},
        KeyErrorCase{"TooLargeAFinalGather", R"({"final_gather": 5000})", 31, "at most 4096"},
        KeyErrorCase{"NegativeGlossySamples", R"({"glossy_samples": -1})", 33, "at least 0"},
        KeyErrorCase{"TooManyGlossySamples", R"({"glossy_samples": 5000})", 33, "at most 4096"},
        KeyErrorCase{"NegativeDirectSamples", R"({"direct_samples": -1})", 33, "at least 0"},
        KeyErrorCase{"TooManyDirectSamples", R"({"direct_samples": 5000})", 33, "at most 4096"}),
    CaseName{});

}  // namespace
}  // namespace lancer::test
