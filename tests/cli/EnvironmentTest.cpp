// The environment light end to end: a map with one bright texel (PFM or EXR) is seen in the
// direction the contract's mapping says (and turned by "rotate"); a Lambertian floor (an infinite
// plane: rays that miss it leave the scene) under a map shows kd E / pi in `path` and `radiosity`
// and kd E in `whitted`, E integrated numerically from the same map; a white sphere under a
// constant map is as bright as the map (a white furnace), as under the same `background`.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ClosedForm.h"
#include "LancerRun.h"
#include "PfmFile.h"
#include "TempFolder.h"
#include "io/ImageWriter.h"

namespace lancer::test {
namespace {

using nlohmann::json;

constexpr double kPiD = std::numbers::pi;

// The unit direction of texel (x, y)'s centre in a width x height map, by the contract's
// u = 0.5 + atan2(d.x, -d.z) / (2 pi), v = acos(d.y) / pi inverted.
Vec3d texelDirection(double x, double y, int width, int height) {
    const double phi = ((x + 0.5) / width - 0.5) * 2 * kPiD, theta = (y + 0.5) / height * kPiD;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

// A scene with nothing but the environment (written into `folder`) and a camera looking along
// `direction` with a narrow view: the centre pixel of the 3 x 3 image looks exactly along it.
json lookingAlong(const Vec3d& direction, const fs::path& map, const std::string& integrator) {
    return {
        {"render",
         {{"width", 3}, {"height", 3}, {"spp", 1}, {"max_depth", 0}, {"integrator", integrator}}},
        {"camera",
         {{"position", {0, 0, 0}},
          {"look_at", {direction.x, direction.y, direction.z}},
          {"vfov", 1}}},
        {"environment", {{"file", map.string()}, {"intensity", 2}}}};
}

double centreGreen(const json& scene) {
    return renderScene(scene).image.at(1, 1)[1];
}

// The map as a PFM and as an OpenEXR file (written by the program's own ImageWriter, as 32-bit
// float, which holds the texels exactly): the same texel is seen in the same direction.
TEST(CliEnvironment, OneBrightTexelIsSeenWhereTheMappingSaysAndTurnedByRotate) {
    const TempFolder folder;
    constexpr int kW = 16, kH = 8;
    lancer::Image map(kW, kH, Color(0));
    map.at(11, 3) = Color(5, 6, 7);  // just left of +x, a little above the horizon
    writePfm(map, folder / "map.pfm");
    ImageWriter::write(map, folder / "map.exr");
    const Vec3d d = texelDirection(11, 3, kW, kH);
    for (const char* file : {"map.pfm", "map.exr"})
        for (const std::string integrator : {"whitted", "path"}) {
            SCOPED_TRACE(integrator + " " + file);
            // Exactly at the texel's centre the bilinear lookup is the texel: 6, times intensity 2.
            EXPECT_NEAR(centreGreen(lookingAlong(d, folder / file, integrator)), 12, 1e-3);
            EXPECT_EQ(centreGreen(lookingAlong(-1.0 * d, folder / file, integrator)), 0);
            // Turned 90 degrees counter-clockwise seen from above, (x, y, z) goes to (z, y, -x).
            json turned = lookingAlong({d.z, d.y, -d.x}, folder / file, integrator);
            turned["environment"]["rotate"] = 90;
            EXPECT_NEAR(centreGreen(turned), 12, 1e-3);
            json unturned = lookingAlong(d, folder / file, integrator);
            unturned["environment"]["rotate"] = 90;
            EXPECT_EQ(centreGreen(unturned), 0);
        }
}

// An 8-bit map holds sRGB-encoded colour: a binary PPM whose every texel is 128 is seen as
// ((128 / 255 + 0.055) / 1.055)^2.4 = 0.2158605 everywhere, times the intensity.
TEST(CliEnvironment, AnEightBitMapIsSrgbDecoded) {
    const TempFolder folder;
    folder.write("map.ppm", "P6\n4 2\n255\n" + std::string(4 * 2 * 3, static_cast<char>(128)));
    const double decoded = std::pow((128 / 255.0 + 0.055) / 1.055, 2.4);
    for (const Vec3d& d : {Vec3d(0, 0, -1), Vec3d(0.6, 0.8, 0), Vec3d(0.1, -1, 0)})
        EXPECT_NEAR(centreGreen(lookingAlong(d, folder / "map.ppm", "whitted")), 2 * decoded, 1e-5);
}

// A negative texel (a float map may hold one) would make the sampling density negative and
// subtract light: the map is refused with one line naming the scene's "file" value. (Infinite
// and NaN texels are read as 0 by the image reader, as for textures.)
TEST(CliEnvironment, AMapWithANegativeTexelIsRefused) {
    for (const float bad : {-1.0f, -1e-30f}) {
        const TempFolder folder;
        lancer::Image map(4, 2, Color(1));
        map.at(1, 0).g = bad;
        writePfm(map, folder / "map.pfm");
        folder.write("scene.json", R"({ "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1] },
  "environment": { "file": "map.pfm" } })");
        const RunResult run = runLancer({"scene.json", "-o", "out.png"}, folder.path());
        EXPECT_EQ(run.exitStatus, 2) << run;
        ASSERT_EQ(run.errorLines().size(), 1u) << run;
        EXPECT_EQ(run.errorLines()[0],
                  "scene.json:2:28: error: the environment map's texel (1, 0) is not a finite, "
                  "non-negative colour");
    }
}

// Reflections and refractions that leave the scene see the map too: a mirror floor (y = 0) seen
// along d mirrored in it shows the texel, times its reflectance 0.5; a glass slab of parallel
// faces (the ray leaves it along the direction it entered) seen from below along d shows it
// times the slab's Fresnel transmittance.
TEST(CliEnvironment, ReflectionsAndRefractionsSeeTheMap) {
    const TempFolder folder;
    constexpr int kW = 16, kH = 8;
    lancer::Image map(kW, kH, Color(0));
    map.at(11, 3) = Color(5, 6, 7);
    writePfm(map, folder / "map.pfm");
    const Vec3d d = texelDirection(11, 3, kW, kH);
    for (const std::string integrator : {"whitted", "path"}) {
        SCOPED_TRACE(integrator);
        json mirror = lookingAlong({d.x, -d.y, d.z}, folder / "map.pfm", integrator);
        mirror["camera"]["position"] = {0, 1, 0};
        mirror["camera"]["look_at"] = {d.x, 1 - d.y, d.z};
        mirror["render"]["max_depth"] = 2;
        mirror["materials"] = {{"mirror", {{"diffuse", 0}, {"reflection", 0.5}}}};
        mirror["objects"] = {{{"type", "plane"},
                              {"point", {0, 0, 0}},
                              {"normal", {0, 1, 0}},
                              {"material", "mirror"}}};
        EXPECT_NEAR(centreGreen(mirror), 0.5 * 12, 1e-3);
    }
    // Through glass: each face passes 1 - F of the light, F the dielectric Fresnel reflectance
    // (ior 1.5) at the slab's angle of incidence (the rays reflected inside leave downwards, where
    // the map is black). Whitted splits the ray at each face; the path tracer picks reflection or
    // refraction by F, so its centre pixel averages 65536 samples (a standard error of 0.5%:
    // within 2%), over a view narrowed so that the map does not vary across the pixel.
    const double cosI = std::abs(d.y), sinT = std::sqrt(1 - cosI * cosI) / 1.5;
    const double cosT = std::sqrt(1 - sinT * sinT);
    const double rs = (cosI - 1.5 * cosT) / (cosI + 1.5 * cosT);
    const double rp = (1.5 * cosI - cosT) / (1.5 * cosI + cosT);
    const double passed = std::pow(1 - (rs * rs + rp * rp) / 2, 2);
    double through[2] = {0, 0};
    int i = 0;
    for (const std::string integrator : {"whitted", "path"}) {
        json glass = lookingAlong(d, folder / "map.pfm", integrator);
        glass["camera"]["vfov"] = 0.001;
        glass["render"]["spp"] = integrator == "path" ? 65536 : 1;
        glass["camera"]["position"] = {0, -1, 0};
        glass["camera"]["look_at"] = {d.x, d.y - 1, d.z};
        glass["render"]["max_depth"] = 3;
        glass["materials"] = {{"glass", {{"diffuse", 0}, {"transmission", 1}, {"ior", 1.5}}}};
        glass["objects"] = {{{"type", "box"},
                             {"min", {-50, -0.5, -50}},
                             {"max", {50, -0.3, 50}},
                             {"material", "glass"}}};
        through[i++] = centreGreen(glass);
    }
    EXPECT_NEAR(through[0], passed * 12, 1e-3 * 12);
    EXPECT_NEAR(through[1], passed * 12, 0.02 * passed * 12);
}

// --- A Lambertian floor under a map -------------------------------------------------------------

// A sky: a gradient from a pale horizon to a blue zenith and a ground colour below it, and a 2 x 2
// patch of texels 200 times brighter (a "sun", 40 degrees up), on a 32 x 16 map.
lancer::Image skyMap() {
    constexpr int kW = 32, kH = 16;
    lancer::Image map(kW, kH);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const float up =
                std::cos(std::numbers::pi_v<float> * (static_cast<float>(y) + 0.5f) / kH);
            map.at(x, y) =
                up < 0 ? Color(0.3f, 0.25f, 0.2f) : Color(0.8f - 0.5f * up, 0.9f - 0.4f * up, 1.0f);
        }
    for (int y = 3; y <= 4; ++y)
        for (int x = 20; x <= 21; ++x)
            map.at(x, y) = Color(200, 180, 150);
    return map;
}

// The map as the contract reads it, in double: bilinear between texel centres, u wrapping
// around, v clamped at the poles.
Radiance lookUp(const lancer::Image& map, double u, double v) {
    const int w = map.width(), h = map.height();
    const double x = u * w - 0.5, y = v * h - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y), fx = x - x0, fy = y - y0;
    const auto texel = [&](int tx, int ty) {
        const Color& c = map.at(((tx % w) + w) % w, std::clamp(ty, 0, h - 1));
        return Radiance{c.r, c.g, c.b};
    };
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    return (1 - fy) * ((1 - fx) * texel(ix, iy) + fx * texel(ix + 1, iy)) +
           fy * ((1 - fx) * texel(ix, iy + 1) + fx * texel(ix + 1, iy + 1));
}

// The irradiance on an upward surface: the integral of L cos over the upper hemisphere, by the
// midpoint rule on a grid 64 times finer than the map each way, over (u, v) with
// dw = 2 pi^2 sin(theta) du dv.
Radiance upwardIrradiance(const lancer::Image& map) {
    const int w = map.width() * 64, h = map.height() * 64;
    Radiance E;
    for (int y = 0; y < h / 2; ++y) {
        const double v = (y + 0.5) / h, theta = v * kPiD;
        const double weight = std::cos(theta) * 2 * kPiD * kPiD * std::sin(theta) / (double(w) * h);
        for (int x = 0; x < w; ++x)
            E = E + weight * lookUp(map, (x + 0.5) / w, v);
    }
    return E;
}

// Looking down at the floor y = 0 from a height of 1, at an angle, every pixel on the floor.
const CameraModel kDownCamera{.position = {0, 1, 0.5},
                              .lookAt = {0, 0, 0},
                              .up = {0, 0, -1},
                              .vfovDegrees = 30,
                              .width = 12,
                              .height = 12};

json floorUnderTheSky(const fs::path& map, const std::string& integrator, int spp, int samples) {
    json scene = {{"render", {{"integrator", integrator}, {"max_depth", 4}}},
                  {"environment", {{"file", map.string()}, {"samples", samples}}},
                  {"materials", {{"floor", {{"diffuse", 0.5}, {"specular", 0}}}}},
                  {"objects",
                   {{{"type", "plane"},
                     {"point", {0, 0, 0}},
                     {"normal", {0, 1, 0}},
                     {"material", "floor"}}}}};
    kDownCamera.placeIn(scene);
    scene["render"]["spp"] = spp;
    return scene;
}

// The image's mean against `expected`, channel by channel, within `relative`; and every pixel
// within `pixelRelative` (the noise of one pixel's samples).
void expectUniformImage(const Image& image, const Radiance& expected, double relative,
                        double pixelRelative) {
    const double want[3] = {expected.r, expected.g, expected.b};
    for (int c = 0; c < 3; ++c) {
        double sum = 0, worst = 0;
        for (const Image::Rgb& p : image.pixels) {
            sum += p[c];
            worst = std::max(worst, std::abs(p[c] / want[c] - 1));
        }
        const double mean = sum / static_cast<double>(image.pixels.size());
        EXPECT_NEAR(mean, want[c], relative * want[c]) << "the image's mean, channel " << c;
        EXPECT_LE(worst, pixelRelative) << "the farthest pixel's relative error, channel " << c
                                        << " (the mean is off by " << mean / want[c] - 1 << ")";
    }
}

class CliEnvironmentFloor : public testing::Test {
protected:
    void SetUp() override {
        writePfm(skyMap(), folder_ / "sky.pfm");
        irradiance_ = upwardIrradiance(skyMap());
    }
    fs::path map() const { return folder_ / "sky.pfm"; }
    Radiance lambertian(double kd) const { return kd * irradiance_; }

    TempFolder folder_;
    Radiance irradiance_;
};

// The tolerances are about three times the farthest pixel's error measured over the 144 pixels,
// and for the mean (measured within 0.1%) about four standard errors.

// 256 samples per pixel, each a light sample and a BSDF sample weighted by MIS (the farthest
// pixel measured 2.6% off): the mean within 0.5%, each pixel within 8%.
TEST_F(CliEnvironmentFloor, PathShowsKdEOverPi) {
    const Image image = renderScene(floorUnderTheSky(map(), "path", 256, 1)).image;
    expectUniformImage(image, lambertian(0.5 / kPiD), 0.005, 0.08);
}

// 1024 importance-sampled shadow rays per shading point, one sample per pixel (the farthest
// pixel measured 2.4% off): the mean within 0.5%, each pixel within 8%.
TEST_F(CliEnvironmentFloor, WhittedShowsKdE) {
    const Image image = renderScene(floorUnderTheSky(map(), "whitted", 1, 1024)).image;
    expectUniformImage(image, lambertian(0.5), 0.005, 0.08);
}

// Every element (and vertex) gathers the environment with 1024 importance-sampled rays; the image
// interpolates their values (the farthest pixel measured 1.8% off): the mean within 0.5%, each
// pixel within 6%. Both methods: the environment shoots into the hierarchy as into the patches.
TEST_F(CliEnvironmentFloor, RadiosityShowsKdEOverPi) {
    for (const char* method : {"progressive", "hierarchical"}) {
        SCOPED_TRACE(method);
        json scene = floorUnderTheSky(map(), "radiosity", 1, 1024);
        scene["radiosity"] = {{"patch_size", 0.5}, {"method", method}};
        const Image image = renderScene(scene).image;
        expectUniformImage(image, lambertian(0.5 / kPiD), 0.005, 0.06);
    }
}

// --- The white furnace --------------------------------------------------------------------------

// A white Lambertian sphere under a constant environment L reflects L in every direction; the
// same scene with `background` L instead must agree (the background lights only the rays that
// escape after a bounce, the environment is also sampled: the same expectation).
TEST(CliEnvironment, AWhiteSphereUnderAConstantMapIsAsBrightAsTheMapAndTheSameBackground) {
    const TempFolder folder;
    writePfm(lancer::Image(4, 2, Color(0.5f, 0.25f, 1)), folder / "constant.pfm");
    json scene = {
        {"render", {{"integrator", "path"}, {"max_depth", 8}}},
        {"environment", {{"file", (folder / "constant.pfm").string()}}},
        {"materials", {{"white", {{"diffuse", 1}}}}},
        {"objects",
         {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", "white"}}}}};
    const CameraModel camera{
        .position = {0, 0, 2.5}, .lookAt = {0, 0, 0}, .vfovDegrees = 40, .width = 10, .height = 10};
    camera.placeIn(scene);
    scene["render"]["spp"] = 64;
    // Every pixel sees the sphere (or, in the corners, the map), whose radiance is L: 64 samples
    // of MIS keep each pixel within 8% (2.8% measured) and the mean within 0.5% (0.06%).
    const Image underMap = renderScene(scene).image;
    expectUniformImage(underMap, {0.5, 0.25, 1}, 0.005, 0.08);
    scene.erase("environment");
    scene["background"] = {0.5, 0.25, 1};
    // Only BSDF rays find the background: cosine-sampled from a white Lambertian surface, every
    // one carries L exactly.
    const Image underBackground = renderScene(scene).image;
    expectUniformImage(underBackground, {0.5, 0.25, 1}, 1e-5, 1e-5);
}

}  // namespace
}  // namespace lancer::test
