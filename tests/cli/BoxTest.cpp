// The box end to end: seen under a directional light in `whitted`, each face shows the Lambertian
// shading of its own outward normal (axis-aligned, and turned by its transform); as an emitter
// over a Lambertian floor it gives the closed-form irradiance of its faces in `path` (light
// sampling by area, one light per face) and in `radiosity` (its patches shoot). (Its errors are
// in ErrorTest.)
//
// The lamp is the box [-0.5, 0.5] x [1, 1.5] x [-0.5, 0.5] of radiance L, the floor beside it a
// disk on y = 0 of kd = 0.5. A floor point p receives from each face whose outer side it is on the
// irradiance of a Lambertian polygon (Lambert's formula), and shows kd E / pi.

#include <gtest/gtest.h>

#include <cmath>

#include "ClosedForm.h"

namespace lancer::test {
namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;
constexpr double kKd = 0.5;
constexpr double kRadiance = 2;
const Vec3d kLampMin(-0.5, 1, -0.5), kLampMax(0.5, 1.5, 0.5);

double lampIrradiance(const Vec3d& p) {
    return kRadiance * boxIrradiance(p, Vec3d(0, 1, 0), kLampMin, kLampMax);
}

// Looking straight down at the floor from inside the lamp's shadow-free side: 9 x 9 pixels over
// a square beside the lamp, where floor points see its bottom and one or two side faces.
const CameraModel kFloorCamera{.position = {1.2, 0.9, 0.3},
                               .lookAt = {1.2, 0, 0.3},
                               .up = {0, 0, -1},
                               .vfovDegrees = 2 * std::atan(0.4 / 0.9) * 180 / kPi,
                               .width = 9,
                               .height = 9};

json lampOverFloor(const std::string& integrator, int spp) {
    return emitterOverFloor(
        json::parse(
            R"({ "type": "disk", "center": [1.2, 0, 0.3], "normal": [0, 1, 0], "radius": 0.6 })"),
        json::parse(R"({ "type": "box", "min": [-0.5, 1, -0.5], "max": [0.5, 1.5, 0.5] })"),
        kFloorCamera, integrator, spp);
}

PixelOracle floorBesideTheLamp() {
    return lambertianFloor(kKd, lampIrradiance);
}

// Six lights, one per face, of which three light the view: 16384 samples bring the noise to 1%.
TEST(CliBox, AnEmissiveBoxLightsTheFloorAsItsFacesClosedFormsSayInPath) {
    const Image image = renderScene(lampOverFloor("path", 16384)).image;
    EXPECT_EQ(expectPixelsMatch(image, kFloorCamera, floorBesideTheLamp(), 0.02, 0), 81);
}

TEST(CliBox, AnEmissiveBoxLightsTheFloorAsItsFacesClosedFormsSayInRadiosity) {
    json scene = lampOverFloor("radiosity", 1);
    scene["radiosity"] = {{"patch_size", 0.25}};
    const Image image = renderScene(scene).image;
    EXPECT_EQ(expectPixelsMatch(image, kFloorCamera, floorBesideTheLamp(), 0.03, 0), 81);
}

// The nearest t > 0 where the ray meets the box [lo, hi] and the outward normal there, in double.
std::optional<std::pair<double, Vec3d>> intersectBox(const RayD& ray, const Vec3d& lo,
                                                     const Vec3d& hi) {
    double tEnter = 0, tExit = 1e30;
    Vec3d normal;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = ray.direction[axis], o = ray.origin[axis];
        if (d == 0) {
            if (o < lo[axis] || o > hi[axis]) return std::nullopt;
            continue;
        }
        const double t0 = (lo[axis] - o) / d, t1 = (hi[axis] - o) / d;
        const double tNear = std::min(t0, t1), tFar = std::max(t0, t1);
        if (tNear > tEnter) {
            tEnter = tNear;
            normal = Vec3d(0, 0, 0);
            normal[axis] = d < 0 ? 1 : -1;
        }
        tExit = std::min(tExit, tFar);
    }
    if (tEnter > tExit || tEnter == 0) return std::nullopt;
    return std::pair{tEnter, normal};
}

TEST(CliBox, EachFaceIsShadedByItsOwnOutwardNormalUnderItsTransform) {
    // The box [-1, 1]^3, turned 30 degrees about y, lit by a directional light from above right.
    json scene = json::parse(R"({
      "background": 0.1, "ambient": 0,
      "materials": { "white": { "diffuse": 0.8 } },
      "objects": [ { "type": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "material": "white",
                     "transform": { "rotate": [0, 1, 0, 30] } } ],
      "lights": [ { "type": "directional", "direction": [-1, -2, -1.5], "irradiance": 3 } ]
    })");
    const CameraModel camera{
        .position = {3, 2.5, 4}, .lookAt = {0, 0, 0}, .width = 40, .height = 30};
    camera.placeIn(scene);
    scene["render"]["max_depth"] = 0;
    const Image image = renderScene(scene).image;
    const double c = std::cos(30 * kPi / 180), s = std::sin(30 * kPi / 180);
    // Into the box's own frame: the inverse rotation about y.
    const auto toBox = [&](const Vec3d& v) {
        return Vec3d(c * v.x - s * v.z, v.y, s * v.x + c * v.z);
    };
    const auto toWorld = [&](const Vec3d& v) {
        return Vec3d(c * v.x + s * v.z, v.y, -s * v.x + c * v.z);
    };
    const Vec3d towardsLight = normalize(Vec3d(1, 2, 1.5));
    const int checked = expectPixelsMatch(
        image, camera,
        [&](const RayD& ray) -> std::optional<Radiance> {
            const RayD local{toBox(ray.origin), toBox(ray.direction)};
            const auto hit = intersectBox(local, Vec3d(-1, -1, -1), Vec3d(1, 1, 1));
            // Silhouettes and edges: within a pixel of two faces' planes, or of missing it.
            for (const double grow : {-0.04, 0.04}) {
                const auto other = intersectBox(local, Vec3d(-1 - grow, -1 - grow, -1 - grow),
                                                Vec3d(1 + grow, 1 + grow, 1 + grow));
                if (other.has_value() != hit.has_value() || (hit && other->second != hit->second))
                    return std::nullopt;
            }
            if (!hit) return Radiance{0.1, 0.1, 0.1};
            const double cosine = std::max(0.0, dot(toWorld(hit->second), towardsLight));
            const double L = 0.8 * 3 * cosine;
            return Radiance{L, L, L};
        },
        1e-4, 1e-5);
    EXPECT_GT(checked, 700);
}

}  // namespace
}  // namespace lancer::test
