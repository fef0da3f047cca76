// The disk, the first shape added through the Shape interface alone, end to end in the three
// integrators: seen directly it shows its emission (nothing through an annulus' hole), and as an
// emitter over a Lambertian floor it gives the closed-form irradiance of a disk in `path` (light
// sampling by area, weighted against BSDF rays) and in `radiosity` (its patches shoot).
//
// The floor, a disk of radius 1 on y = 0, has kd = 0.5 and the lamp, of radius R = 0.5 at height h
// = 1, faces down (it emits on both sides, like a plane). A floor point at distance rho from the
// axis receives E = pi L / 2 (1 - (h^2 + rho^2 - R^2) / sqrt((h^2 + rho^2 + R^2)^2 - 4 R^2 rho^2)),
// and shows kd E / pi in `path` and `radiosity`.

#include <gtest/gtest.h>

#include <cmath>

#include "ClosedForm.h"

namespace lancer::test {
namespace {

using nlohmann::json;

constexpr double kKd = 0.5;
constexpr double kRadiance = 2;
constexpr double kRadius = 0.5;
constexpr double kHeight = 1;

double diskIrradiance(double rho) {
    const double h2 = kHeight * kHeight, R2 = kRadius * kRadius, rho2 = rho * rho;
    const double root = std::sqrt((h2 + rho2 + R2) * (h2 + rho2 + R2) - 4 * R2 * rho2);
    return 3.14159265358979323846 * kRadiance / 2 * (1 - (h2 + rho2 - R2) / root);
}

// Looking straight down at the floor from just under the disk: 9 x 9 pixels over a square of
// about 0.3 on a side.
const CameraModel kFloorCamera{
    .position = {0, 0.95, 0},
    .lookAt = {0, 0, 0},
    .up = {0, 0, -1},
    .vfovDegrees = 2 * std::atan(0.15 / 0.95) * 180 / 3.14159265358979323846,
    .width = 9,
    .height = 9};

json diskOverFloor(const std::string& integrator, int spp) {
    return emitterOverFloor(
        json::parse(R"({ "type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1 })"),
        json::parse(
            R"({ "type": "disk", "center": [0, 1, 0], "normal": [0, -1, 0], "radius": 0.5 })"),
        kFloorCamera, integrator, spp);
}

PixelOracle floorUnderTheDisk() {
    return lambertianFloor(kKd,
                           [](const Vec3d& p) { return diskIrradiance(std::hypot(p.x, p.z)); });
}

TEST(CliDisk, AnEmissiveDiskLightsTheFloorAsTheClosedFormSaysInPath) {
    const Image image = renderScene(diskOverFloor("path", 1024)).image;
    EXPECT_EQ(expectPixelsMatch(image, kFloorCamera, floorUnderTheDisk(), 0.02, 0), 81);
}

TEST(CliDisk, AnEmissiveDiskLightsTheFloorAsTheClosedFormSaysInRadiosity) {
    // The floor's elements hold the irradiance at their probe points, interpolated: the closed
    // form varies by 6% over the view, and the solution follows it within 3%.
    json scene = diskOverFloor("radiosity", 1);
    scene["radiosity"] = {{"patch_size", 0.25}};
    const Image image = renderScene(scene).image;
    EXPECT_EQ(expectPixelsMatch(image, kFloorCamera, floorUnderTheDisk(), 0.03, 0), 81);
}

TEST(CliDisk, SeenDirectlyItShowsItsEmissionAndNothingThroughItsHole) {
    json scene = json::parse(R"({
      "background": 0.25,
      "materials": { "lamp": { "diffuse": 0, "emission": [1, 2, 3] } },
      "objects": [ { "type": "disk", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1,
                     "inner_radius": 0.5, "material": "lamp" } ]
    })");
    const CameraModel camera{.position = {0, 0, 3}, .lookAt = {0, 0, 0}, .width = 21, .height = 21};
    camera.placeIn(scene);
    scene["render"]["max_depth"] = 0;
    const Image image = renderScene(scene).image;
    const int checked = expectPixelsMatch(
        image, camera,
        [](const RayD& ray) -> std::optional<Radiance> {
            const Vec3d p = ray.at(intersectPlane(ray, Vec3d(0, 0, 0), Vec3d(0, 0, 1)).value());
            const double r = std::hypot(p.x, p.y);
            if (std::abs(r - 1) < 0.02 || std::abs(r - 0.5) < 0.02) return std::nullopt;  // edges
            if (r < 0.5 || r > 1) return Radiance{0.25, 0.25, 0.25};
            return Radiance{1, 2, 3};
        },
        0, 1e-6);
    EXPECT_GT(checked, 400);
}

}  // namespace
}  // namespace lancer::test
