// Cylinders and cones end to end: under a directional light in `whitted`, every pixel of a
// Lambertian cone shows the shading of the normal that the closed form of its surface gives
// (side and cap, under a transform); and a closed emissive cylinder lights the floor under it by
// its bottom cap alone (its side faces away from points under it), as the closed form of a disk
// says, in `path` and `radiosity`. (Their errors are in ErrorTest.)

#include <gtest/gtest.h>

#include <cmath>

#include "ClosedForm.h"

namespace lancer::test {
namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

// Under a cylinder of radius R = 0.5 whose bottom cap, of radiance 2, is at h = 1 (as DiskTest).
double capIrradiance(double rho) {
    const double h2 = 1, R2 = 0.25, rho2 = rho * rho;
    const double root = std::sqrt((h2 + rho2 + R2) * (h2 + rho2 + R2) - 4 * R2 * rho2);
    return kPi * 2 / 2 * (1 - (h2 + rho2 - R2) / root);
}

const CameraModel kFloorCamera{.position = {0, 0.95, 0},
                               .lookAt = {0, 0, 0},
                               .up = {0, 0, -1},
                               .vfovDegrees = 2 * std::atan(0.15 / 0.95) * 180 / kPi,
                               .width = 9,
                               .height = 9};

json lampOverFloor(const std::string& integrator, int spp) {
    return emitterOverFloor(
        json::parse(R"({ "type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1 })"),
        json::parse(
            R"({ "type": "cylinder", "base": [0, 1, 0], "top": [0, 1.5, 0], "radius": 0.5 })"),
        kFloorCamera, integrator, spp);
}

PixelOracle floorUnderTheLamp() {
    return lambertianFloor(0.5, [](const Vec3d& p) { return capIrradiance(std::hypot(p.x, p.z)); });
}

TEST(CliCone, AnEmissiveCylinderLightsTheFloorUnderItByItsCapInPath) {
    // Three lights (side and caps), of which one reaches the view.
    const Image image = renderScene(lampOverFloor("path", 4096)).image;
    EXPECT_EQ(expectPixelsMatch(image, kFloorCamera, floorUnderTheLamp(), 0.02, 0), 81);
}

TEST(CliCone, AnEmissiveCylinderLightsTheFloorUnderItByItsCapInRadiosity) {
    json scene = lampOverFloor("radiosity", 1);
    scene["radiosity"] = {{"patch_size", 0.25}};
    const Image image = renderScene(scene).image;
    EXPECT_EQ(expectPixelsMatch(image, kFloorCamera, floorUnderTheLamp(), 0.03, 0), 81);
}

// Where a ray meets the truncated cone x^2 + z^2 = (1 - y / 2)^2, 0 <= y <= 1, closed by its
// caps, and the outward normal there, in double; nothing within `margin` of a rim or a
// silhouette.
struct ConeHit {
    double t;
    Vec3d normal;
};
std::optional<ConeHit> intersectCone(const RayD& ray, double margin, bool& nearAnEdge) {
    nearAnEdge = false;
    std::optional<ConeHit> nearest;
    const auto consider = [&](double t, const Vec3d& n) {
        if (t > 0 && (!nearest || t < nearest->t)) nearest = ConeHit{t, n};
    };
    // The side: x^2 + z^2 - (1 - y/2)^2 = 0.
    const Vec3d o = ray.origin, d = ray.direction;
    const double a = d.x * d.x + d.z * d.z - d.y * d.y / 4;
    const double b = o.x * d.x + o.z * d.z + d.y * (1 - o.y / 2) / 2;
    const double c = o.x * o.x + o.z * o.z - (1 - o.y / 2) * (1 - o.y / 2);
    const double disc = b * b - a * c;
    if (disc >= 0) {
        for (const double t : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a}) {
            const Vec3d p = ray.at(t);
            if (p.y < -margin || p.y > 1 + margin) continue;
            if (p.y < margin || p.y > 1 - margin) nearAnEdge = true;
            consider(t, normalize(Vec3d(p.x, (1 - p.y / 2) / 2, p.z)));
        }
        if (std::abs(disc) < margin) nearAnEdge = true;
    }
    for (const auto& [y, r, ny] : {std::tuple{0.0, 1.0, -1.0}, {1.0, 0.5, 1.0}}) {
        const std::optional<double> t = intersectPlane(ray, Vec3d(0, y, 0), Vec3d(0, ny, 0));
        if (!t) continue;
        const Vec3d p = ray.at(*t);
        const double rho = std::hypot(p.x, p.z);
        if (std::abs(rho - r) < margin) nearAnEdge = true;
        if (rho < r) consider(*t, Vec3d(0, ny, 0));
    }
    return nearest;
}

TEST(CliCone, EachPixelOfAConeShowsTheShadingOfItsClosedFormNormal) {
    // The cone above, scaled by 1.5 about the origin and moved to y = -0.75, lit from above.
    json scene = json::parse(R"({
      "background": 0.1, "ambient": 0,
      "materials": { "white": { "diffuse": 0.8 } },
      "objects": [ { "type": "cone", "base": [0, 0, 0], "base_radius": 1, "top": [0, 1, 0],
                     "top_radius": 0.5, "material": "white",
                     "transform": { "scale": 1.5, "translate": [0, -0.75, 0] } } ],
      "lights": [ { "type": "directional", "direction": [-1, -2, -1.5], "irradiance": 3 } ]
    })");
    const CameraModel camera{
        .position = {3, 2.5, 4}, .lookAt = {0, 0, 0}, .width = 40, .height = 30};
    camera.placeIn(scene);
    scene["render"]["max_depth"] = 0;
    const Image image = renderScene(scene).image;
    const Vec3d towardsLight = normalize(Vec3d(1, 2, 1.5));
    const int checked = expectPixelsMatch(
        image, camera,
        [&](const RayD& ray) -> std::optional<Radiance> {
            // Into the cone's own space: undo the move, then the scale (t is unchanged when
            // the direction is scaled too, so the normal is what matters).
            const RayD local{(1 / 1.5) * (ray.origin - Vec3d(0, -0.75, 0)), ray.direction};
            bool nearAnEdge = false;
            const std::optional<ConeHit> hit = intersectCone(local, 0.03, nearAnEdge);
            if (nearAnEdge) return std::nullopt;
            if (!hit) return Radiance{0.1, 0.1, 0.1};
            const double L = 0.8 * 3 * std::max(0.0, dot(hit->normal, towardsLight));
            return Radiance{L, L, L};
        },
        1e-4, 1e-5);
    EXPECT_GT(checked, 700);
}

}  // namespace
}  // namespace lancer::test
