// Normal and bump maps seen through the camera: the tangent frame of the contract on a plane, a
// triangle and an OBJ model (its MTL's norm and bump), checked against Lambert's law for the
// analytic normal under a directional light, in every integrator that shades from the map.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <numbers>
#include <sstream>
#include <utility>

#include "LancerRun.h"

namespace lancer::test {
namespace {

using json = nlohmann::json;
using Rgb = std::array<float, 3>;

struct Direction {
    double x, y, z;
};

double dotOf(const Direction& a, const Direction& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

Direction unit(const Direction& d) {
    const double length = std::sqrt(dotOf(d, d));
    return {d.x / length, d.y / length, d.z / length};
}

// A float PFM image (linear data, kept exactly) whose texel (x, y) is texel(x, y), row 0 the
// bottom one (as a PFM stores it and as uv's v = 0 is).
std::string pfm(int width, int height, const std::function<Rgb(int x, int y)>& texel) {
    std::ostringstream out;
    out << "PF\n" << width << " " << height << "\n-1\n";
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (const float c : texel(x, y)) {
                char bytes[4];
                std::memcpy(bytes, &c, 4);  // little-endian, as the scale -1 says
                out.write(bytes, 4);
            }
    return out.str();
}

std::string constantMap(Rgb c) {
    return pfm(4, 4, [c](int, int) { return c; });
}

constexpr double kAlbedo = 0.5;  // the surfaces' kd; the light's irradiance is 1
// A light from above, leaning towards +x and -z, so that tilts along either axis change its cosine.
const Direction kTowardsLight = unit({0.8, 2, -0.6});

// A material of albedo kAlbedo with `maps` (normal_map, bump_map...), lit by kTowardsLight, the
// camera straight above the point (0.5, 0, 0.5) seeing a square 0.7 wide; no ambient.
json litScene(const json& object, const json& maps) {
    json material = {{"diffuse", kAlbedo}};
    material.update(maps);
    json shape = object;
    shape["material"] = "mapped";
    return {{"render", {{"width", 16}, {"height", 16}, {"spp", 1}, {"max_depth", 0}}},
            {"camera",
             {{"position", {0.5, 2, 0.5}},
              {"look_at", {0.5, 0, 0.5}},
              {"up", {0, 0, -1}},
              {"vfov", 20}}},
            {"ambient", 0},
            {"background", 0},
            {"materials", {{"mapped", material}}},
            {"objects", {shape}},
            {"lights",
             {{{"type", "directional"},
               {"direction", {-kTowardsLight.x, -kTowardsLight.y, -kTowardsLight.z}},
               {"irradiance", 1}}}}};
}

// Every pixel of a render of a surface of constant normal is kd E cos(n, L) (Whitted's equation).
// The default tolerance covers float rounding of the frame and the normal (a few ulps of values
// near 0.5).
void expectUniform(const Image& image, double expected, const std::string& what,
                   double tolerance = 2e-5) {
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(image.at(x, y)[c], expected, tolerance)
                    << what << ", pixel " << x << ", " << y;
}

// A surface in the plane y = 0 facing up, whose u grows along uDirection and v along vDirection.
struct FlatSurface {
    std::string name;
    json object;
    Direction u, v;
};

void PrintTo(const FlatSurface& surface, std::ostream* out) {
    *out << surface.name;
}

std::vector<FlatSurface> flatSurfaces() {
    return {
        // The plane's uv are world (x, z).
        {"Plane",
         {{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}},
         {1, 0, 0},
         {0, 0, 1}},
        // Its uvs turn v towards -z, as an OBJ seen from above with -z up the image.
        {"Triangle",
         {{"type", "triangle"},
          {"vertices", {{-2, 0, 3}, {4, 0, 3}, {-2, 0, -3}}},
          {"uvs", {{0, 0}, {1, 0}, {0, 1}}}},
         {1, 0, 0},
         {0, 0, -1}},
    };
}

class CliNormalMap : public testing::TestWithParam<FlatSurface> {};

// n_ts = 2 c - 1 = (0.6, 0, 0.8): the normal leans towards +u, 0.6 T + 0.8 N.
TEST_P(CliNormalMap, TiltTowardsUGivesLambertOfTheTiltedNormal) {
    const FlatSurface& surface = GetParam();
    const TempFolder folder;
    const fs::path map = folder.write("tilt.pfm", constantMap({0.8f, 0.5f, 0.9f}));
    const Image image = renderScene(litScene(surface.object, {{"normal_map", map.string()}})).image;
    const Direction n{0.6 * surface.u.x, 0.8, 0.6 * surface.u.z};
    expectUniform(image, kAlbedo * dotOf(n, kTowardsLight), "tilt towards +u");
}

// Green is +v (OpenGL): (0, 0.6, 0.8) leans the normal towards +v. Read as DirectX's -v, the
// cosine would be 0.8 L.y - 0.6 L.v instead, which the light's slant along z tells apart.
TEST_P(CliNormalMap, GreenTiltsTowardsPlusV) {
    const FlatSurface& surface = GetParam();
    const TempFolder folder;
    const fs::path map = folder.write("tilt.pfm", constantMap({0.5f, 0.8f, 0.9f}));
    const Image image = renderScene(litScene(surface.object, {{"normal_map", map.string()}})).image;
    const Direction n{0, 0.8, 0.6 * surface.v.z};
    expectUniform(image, kAlbedo * dotOf(n, kTowardsLight), "tilt towards +v");
}

// The path tracer shades from the same frame: kd / pi E cos with one bounce (the light is a
// delta, so each sample is exact).
TEST_P(CliNormalMap, PathTracerSeesTheTiltedNormal) {
    const FlatSurface& surface = GetParam();
    const TempFolder folder;
    const fs::path map = folder.write("tilt.pfm", constantMap({0.8f, 0.5f, 0.9f}));
    json scene = litScene(surface.object, {{"normal_map", map.string()}});
    scene["render"]["integrator"] = "path";
    scene["render"]["max_depth"] = 1;
    const Image image = renderScene(scene).image;
    const Direction n{0.6 * surface.u.x, 0.8, 0.6 * surface.u.z};
    expectUniform(image, kAlbedo / std::numbers::pi * dotOf(n, kTowardsLight), "path");
}

// A bump map of height h = u (a ramp, exact under bilinear filtering between the texel centres)
// and bump_scale s: the surface rises s per unit of u, so its normal is N - s u-hat, normalised.
TEST_P(CliNormalMap, LinearBumpRampTiltsByItsSlope) {
    const FlatSurface& surface = GetParam();
    const TempFolder folder;
    constexpr int kWidth = 64;
    const fs::path map = folder.write("ramp.pfm", pfm(kWidth, 4, [](int x, int) {
                                          const float h = (static_cast<float>(x) + 0.5f) / kWidth;
                                          return Rgb{h, h, h};
                                      }));
    constexpr double kScale = 0.5;
    // The triangle's u runs over 6 units, so its slope per scene unit is a sixth of the plane's.
    const double slope = kScale / (surface.name == "Triangle" ? 6.0 : 1.0);
    const Image image =
        renderScene(litScene(surface.object, {{"bump_map", map.string()}, {"bump_scale", kScale}}))
            .image;
    // The camera sees u in [0.15, 0.85] (plane) or [0.36, 0.48] (triangle): inside the ramp.
    const Direction n = unit({-slope * surface.u.x, 1, -slope * surface.u.z});
    expectUniform(image, kAlbedo * dotOf(n, kTowardsLight), "ramp");

    // The path tracer has no footprint: its differences span 0.0005 in uv, over which heights
    // near 0.5 differ by 0.0005, known to a float's 6e-8 each: a slope within 2e-4 relative.
    json scene = litScene(surface.object, {{"bump_map", map.string()}, {"bump_scale", kScale}});
    scene["render"]["integrator"] = "path";
    scene["render"]["max_depth"] = 1;
    expectUniform(renderScene(scene).image, kAlbedo / std::numbers::pi * dotOf(n, kTowardsLight),
                  "ramp, path", 1e-4);
}

INSTANTIATE_TEST_SUITE_P(FlatSurfaces, CliNormalMap, testing::ValuesIn(flatSurfaces()), CaseName());

// A sphere's frame: u is longitude (dpdu along +x where the sphere faces +z), v latitude (dpdv
// along +y). The camera sees a patch 0.0035 wide around (0, 0, 1), over which the normal turns by
// 0.1 degrees: the tolerance covers that (the cosine's change is below 1e-3 for kd = 0.5).
TEST(CliNormalMapFlat, SphereTiltsInItsLongitudeAndLatitudeFrame) {
    const TempFolder folder;
    const Direction towardsLight = unit({0.5, 0.6, 1});
    json scene =
        litScene({{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}}, json::object());
    scene["camera"] = {{"position", {0, 0, 5}}, {"look_at", {0, 0, 0}}, {"vfov", 0.05}};
    scene["render"]["width"] = scene["render"]["height"] = 4;
    scene["lights"][0]["direction"] = {-towardsLight.x, -towardsLight.y, -towardsLight.z};
    for (const auto& [texel, normal] : {std::pair{Rgb{0.8f, 0.5f, 0.9f}, Direction{0.6, 0, 0.8}},
                                        std::pair{Rgb{0.5f, 0.8f, 0.9f}, Direction{0, 0.6, 0.8}}}) {
        const fs::path map = folder.write("tilt.pfm", constantMap(texel));
        scene["materials"]["mapped"]["normal_map"] = map.string();
        const Image image = renderScene(scene).image;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                EXPECT_NEAR(image.at(x, y)[0], kAlbedo * dotOf(normal, towardsLight), 1e-3)
                    << "pixel " << x << ", " << y << " of the map " << texel[0] << ", " << texel[1];
    }
}

// A map of constant (0.5, 0.5, 1) leaves every normal as it was: a sphere, a plane and a
// triangle, with mirror reflections between them, render as without it. The bound is float
// rounding: the mapped normal is normalize(N), within an ulp or two of N.
TEST(CliNormalMapFlat, NeutralMapChangesNothing) {
    const TempFolder folder;
    const fs::path map = folder.write("flat.pfm", constantMap({0.5f, 0.5f, 1}));
    json scene = {
        {"render", {{"width", 48}, {"height", 36}, {"spp", 1}, {"max_depth", 2}}},
        {"camera", {{"position", {0, 1.5, 5}}, {"look_at", {0, 0.7, 0}}}},
        {"materials",
         {{"shiny",
           {{"diffuse", 0.5}, {"specular", 0.4}, {"shininess", 40}, {"reflection", 0.3}}}}},
        {"objects",
         {{{"type", "sphere"}, {"center", {-0.8, 1, 0}}, {"radius", 1}, {"material", "shiny"}},
          {{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "shiny"}},
          {{"type", "triangle"},
           {"vertices", {{0.5, 0, -1}, {2, 0, -1}, {1.2, 2, -1}}},
           {"material", "shiny"}}}},
        {"lights", {{{"type", "point"}, {"position", {3, 5, 4}}, {"intensity", 40}}}}};
    const Image plain = renderScene(scene).image;
    scene["materials"]["shiny"]["normal_map"] = map.string();
    const Image mapped = renderScene(scene).image;
    EXPECT_LE(maxAbsoluteDifference(mapped, plain), 1e-5);
}

// A map leaning the normal almost flat along +u, seen from the -u side at a grazing angle: the
// mapped normal faces away from the camera. Bent back to the viewer's horizon it still catches
// the light from above (cosine about 0.96 here), where it would otherwise be black.
TEST(CliNormalMapFlat, NormalFacingAwayIsBentBackNotBlack) {
    const TempFolder folder;
    // n_ts = (0.995, 0, 0.1), nearly along +u.
    const fs::path map = folder.write("steep.pfm", constantMap({0.9975f, 0.5f, 0.55f}));
    json scene = litScene(flatSurfaces()[0].object, {{"normal_map", map.string()}});
    scene["camera"] = {{"position", {-3, 1, 0.5}}, {"look_at", {0.5, 0, 0.5}}, {"vfov", 10}};
    scene["lights"][0]["direction"] = {0, -1, 0};
    const Image image = renderScene(scene).image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            EXPECT_GT(image.at(x, y)[0], 0.05) << "pixel " << x << ", " << y;
}

// A bump map of one period of a sinusoid along u, h = (1 + sin(2 pi u)) / 2, on the plane lit
// from above and the +x side: at each pixel's centre the normal is N - h'(u) u-hat normalised,
// h' = s pi cos(2 pi u). The map is sampled at 256 texels and each pixel covers 1/45 of the
// period, averaged by a box filter over the pixel: the tolerance covers the bilinear
// interpolation's slope error (under 1% of the amplitude) and the second-order error of
// predicting the pixel's average by its centre.
TEST(CliNormalMapFlat, SinusoidalBumpsFollowTheAnalyticNormal) {
    const TempFolder folder;
    constexpr int kTexels = 256;
    const fs::path map =
        folder.write("waves.pfm", pfm(kTexels, 2, [](int x, int) {
                         const float h = static_cast<float>(
                             0.5 + 0.5 * std::sin(2 * std::numbers::pi * (x + 0.5) / kTexels));
                         return Rgb{h, h, h};
                     }));
    constexpr double kScale = 0.1;
    json scene =
        litScene(flatSurfaces()[0].object, {{"bump_map", map.string()}, {"bump_scale", kScale}});
    scene["render"]["width"] = 32;
    scene["render"]["height"] = 32;
    scene["render"]["spp"] = 16;
    scene["render"]["filter"] = {{"type", "box"}, {"radius", 0.5}};
    const Direction towardsLight = unit({1, 2, 0});
    scene["lights"][0]["direction"] = {-towardsLight.x, -towardsLight.y, -towardsLight.z};
    const Image image = renderScene(scene).image;
    // The camera formula: pixel x's centre sees world x = 0.5 + (2 (x + 0.5) / 32 - 1) tan_w 2,
    // from 0.15 to 0.85.
    const double tanW = std::tan(10 * std::numbers::pi / 180);
    for (int x = 0; x < image.width; ++x) {
        const double u = 0.5 + (2 * (x + 0.5) / image.width - 1) * tanW * 2;
        const double slope = kScale * std::numbers::pi * std::cos(2 * std::numbers::pi * u);
        const Direction n = unit({-slope, 1, 0});
        EXPECT_NEAR(image.at(x, 16)[0], kAlbedo * dotOf(n, towardsLight), 4e-3) << "pixel " << x;
    }
}

// An OBJ quad whose MTL names the maps: norm as a tangent-space normal map, bump with -bm as the
// bump map and its scale, both read as data (the PFM is float anyway; the mesh tests check that).
TEST(CliNormalMapFlat, ObjMaterialsTakeNormAndBumpMaps) {
    const TempFolder folder;
    folder.write("tilt.pfm", constantMap({0.8f, 0.5f, 0.9f}));
    folder.write("ramp.pfm", pfm(64, 4, [](int x, int) {
                     const float h = (static_cast<float>(x) + 0.5f) / 64;
                     return Rgb{h, h, h};
                 }));
    const std::string quad =
        "mtllib quad.mtl\nusemtl m\nv -2 0 3\nv 3 0 3\nv 3 0 -2\nv -2 0 -2\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
    const fs::path normalObj = folder.write("normal.obj", quad);
    folder.write("quad.mtl", "newmtl m\nKd 0.5 0.5 0.5\nillum 1\nnorm tilt.pfm\n");
    const fs::path bumpFolder = folder / "bump";
    fs::create_directories(bumpFolder);
    const fs::path bumpObj = folder.write("bump/bump.obj", quad);
    folder.write("bump/quad.mtl", "newmtl m\nKd 0.5 0.5 0.5\nillum 1\nbump -bm 2.5 ../ramp.pfm\n");

    json scene = litScene({{"type", "mesh"}, {"file", normalObj.string()}}, json::object());
    scene["objects"][0].erase("material");  // the MTL's
    expectUniform(renderScene(scene).image, kAlbedo * dotOf({0.6, 0.8, 0}, kTowardsLight), "norm");

    scene["objects"][0]["file"] = bumpObj.string();
    // u runs over 5 units: the slope is 2.5 / 5.
    expectUniform(renderScene(scene).image, kAlbedo * dotOf(unit({-0.5, 1, 0}), kTowardsLight),
                  "bump -bm");
}

}  // namespace
}  // namespace lancer::test
