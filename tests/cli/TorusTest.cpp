// The torus end to end: in `whitted`, every pixel of a Lambertian torus shows the shading of
// the normal that an independent double-precision model of the surface gives (a march of its
// exact distance), with its shadows on itself, seen from outside under a directional light and
// from inside the tube by a point light there; and an emissive torus lights the floor under it
// as the integral of its solid angle says, in `path` and `radiosity`. (Its errors are in
// ErrorTest.)

#include <gtest/gtest.h>

#include <cmath>

#include "ClosedForm.h"

namespace lancer::test {
namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

// The torus R, r about the unit axis through `center`, and what a ray meets of it, in double.
struct TorusModel {
    Vec3d center;
    Vec3d axis;
    double R, r;

    double distance(const Vec3d& p) const {
        const Vec3d local = p - center;
        const double z = dot(local, axis);
        return std::hypot(length(local - z * axis) - R, z) - r;
    }
    Vec3d outwardNormal(const Vec3d& p) const {
        const Vec3d local = p - center;
        const Vec3d core = R * normalize(local - dot(local, axis) * axis);
        return normalize(local - core);
    }

    // The first crossing of the surface along the ray between s = start and s = end, by a march
    // of the 1-Lipschitz distance (steps of 0.9 |distance|, so none jumps over the surface) and
    // bisection; `nearMiss` is set when the ray passes within `margin` of the surface without
    // crossing it there (a local minimum of |distance|), where rounding could decide otherwise.
    std::optional<double> crossing(const RayD& ray, double start, double end, double margin,
                                   bool& nearMiss) const {
        double s = start, d = distance(ray.at(s));
        const bool inside = d < 0;
        bool approaching = false;
        while (s < end) {
            const double next = s + std::max(0.9 * std::abs(d), 1e-7);
            const double nextD = distance(ray.at(next));
            if ((nextD < 0) != inside) {
                double lo = s, hi = next;
                for (int i = 0; i < 60; ++i) {
                    const double mid = 0.5 * (lo + hi);
                    ((distance(ray.at(mid)) < 0) == inside ? lo : hi) = mid;
                }
                return 0.5 * (lo + hi);
            }
            if (approaching && std::abs(nextD) > std::abs(d) && std::abs(d) < margin)
                nearMiss = true;
            approaching = std::abs(nextD) < std::abs(d);
            s = next;
            d = nextD;
        }
        return std::nullopt;
    }
};

// What a pixel of a Lambertian torus of reflectance 0.8, in a scene of background 0.1 and no
// ambient term, shows: light from `towardsLight(p)` of irradiance `irradiance(p)`, blocked by the
// torus itself; unchecked within rounding distance of a silhouette or a shadow's edge.
PixelOracle lambertianTorus(const TorusModel& torus,
                            const std::function<Vec3d(const Vec3d&)>& towardsLight,
                            const std::function<double(const Vec3d&)>& lightDistance,
                            double irradiance) {
    return [=](const RayD& ray) -> std::optional<Radiance> {
        constexpr double kMargin = 0.01;
        bool nearMiss = false;
        const std::optional<double> t = torus.crossing(ray, 0, 20, kMargin, nearMiss);
        if (nearMiss) return std::nullopt;
        if (!t) return Radiance{0.1, 0.1, 0.1};
        const Vec3d p = ray.at(*t);
        Vec3d n = torus.outwardNormal(p);
        if (std::abs(dot(n, ray.direction)) < 0.05) return std::nullopt;  // grazing
        if (dot(n, ray.direction) > 0) n = -n;  // seen from inside: shaded on the side seen
        const Vec3d l = towardsLight(p);
        const double cosine = dot(n, l);
        if (cosine <= 0) return Radiance{0, 0, 0};
        if (cosine < 0.02) return std::nullopt;  // the shadow ray grazes its own surface
        const RayD shadow{p, l};
        const bool blocked =
            torus.crossing(shadow, 1e-6, lightDistance(p), kMargin, nearMiss).has_value();
        if (nearMiss) return std::nullopt;
        const double L = blocked ? 0 : 0.8 * irradiance * cosine;
        return Radiance{L, L, L};
    };
}

TEST(CliTorus, EachPixelOfATorusShowsTheShadingOfItsClosedFormNormal) {
    // Tilted, scaled by 1.5 about the origin and moved, lit from above: the ring shadows itself.
    json scene = json::parse(R"({
      "background": 0.1, "ambient": 0,
      "materials": { "white": { "diffuse": 0.8 } },
      "objects": [ { "type": "torus", "major_radius": 1, "minor_radius": 0.4,
                     "center": [0.1, 0, -0.1], "axis": [0.4, 1, 0.3], "material": "white",
                     "transform": { "scale": 1.5, "translate": [0, -0.3, 0] } } ],
      "lights": [ { "type": "directional", "direction": [-1, -2, -1.5], "irradiance": 3 } ]
    })");
    const CameraModel camera{
        .position = {3, 3.5, 4}, .lookAt = {0, -0.3, 0}, .width = 40, .height = 30};
    camera.placeIn(scene);
    scene["render"]["max_depth"] = 0;
    const Image image = renderScene(scene).image;
    const TorusModel torus{1.5 * Vec3d(0.1, 0, -0.1) + Vec3d(0, -0.3, 0),
                           normalize(Vec3d(0.4, 1, 0.3)), 1.5, 0.6};
    const Vec3d towardsLight = normalize(Vec3d(1, 2, 1.5));
    const int checked = expectPixelsMatch(image, camera,
                                          lambertianTorus(
                                              torus, [&](const Vec3d&) { return towardsLight; },
                                              [](const Vec3d&) { return 20.0; }, 3),
                                          1e-4, 1e-5);
    EXPECT_GT(checked, 1000);
}

TEST(CliTorus, FromInsideTheTubeEachPixelShowsTheShadingOfItsClosedFormNormal) {
    // The camera on the core circle, looking along the tube, lit by a point light inside it: the
    // wall ahead, and the bend of the tube hiding part of it from the light.
    json scene = json::parse(R"({
      "background": 0.1, "ambient": 0,
      "materials": { "white": { "diffuse": 0.8 } },
      "objects": [ { "type": "torus", "major_radius": 1, "minor_radius": 0.4,
                     "material": "white" } ],
      "lights": [ { "type": "point", "position": [0.9, 0.15, 0.25], "intensity": 2,
                    "falloff": "none" } ]
    })");
    const CameraModel camera{.position = {1, 0, 0},
                             .lookAt = {1.3, 0.05, -1},
                             .vfovDegrees = 70,
                             .width = 40,
                             .height = 30};
    camera.placeIn(scene);
    scene["render"]["max_depth"] = 0;
    const Image image = renderScene(scene).image;
    const TorusModel torus{Vec3d(0, 0, 0), Vec3d(0, 1, 0), 1, 0.4};
    const Vec3d light(0.9, 0.15, 0.25);
    const int checked =
        expectPixelsMatch(image, camera,
                          lambertianTorus(
                              torus, [&](const Vec3d& p) { return normalize(light - p); },
                              [&](const Vec3d& p) { return length(light - p); }, 2),
                          1e-4, 1e-5);
    EXPECT_GT(checked, 1000);
}

// A torus of radiance 2 lying flat at height 1 (R = 0.6, r = 0.25) over a floor of reflectance
// 0.5; the camera looks down at the floor under it, through the hole.
const CameraModel kFloorCamera{.position = {0, 0.5, 0},
                               .lookAt = {0, 0, 0},
                               .up = {0, 0, -1},
                               .vfovDegrees = 2 * std::atan(0.7 / 0.5) * 180 / kPi,
                               .width = 7,
                               .height = 7};

json lampOverFloor(const std::string& integrator, int spp) {
    return emitterOverFloor(
        json::parse(
            R"({ "type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1.2 })"),
        json::parse(
            R"({ "type": "torus", "center": [0, 1, 0], "major_radius": 0.6, "minor_radius": 0.25 })"),
        kFloorCamera, integrator, spp);
}

// The floor's radiance 0.5 E / pi, where E = 2 pi times the fraction of cosine-distributed
// directions from the floor point that meet the torus (every such direction sees its outside,
// of radiance 2): Malley's method over a stratified grid of directions.
PixelOracle floorUnderTheLamp() {
    const TorusModel torus{Vec3d(0, 1, 0), Vec3d(0, 1, 0), 0.6, 0.25};
    return [torus](const RayD& ray) -> std::optional<Radiance> {
        const Vec3d p = ray.at(intersectPlane(ray, Vec3d(0, 0, 0), Vec3d(0, 1, 0)).value());
        constexpr int kGrid = 160;
        int hits = 0;
        for (int i = 0; i < kGrid; ++i)
            for (int j = 0; j < kGrid; ++j) {
                const double radius = std::sqrt((i + 0.5) / kGrid),
                             angle = 2 * kPi * (j + 0.5) / kGrid;
                const Vec3d w(radius * std::cos(angle),
                              std::sqrt(std::max(0.0, 1 - radius * radius)),
                              radius * std::sin(angle));
                // Only directions through the torus's bounding sphere (radius 0.85) can meet it.
                const Vec3d toCenter = torus.center - p;
                const double along = dot(toCenter, w);
                if (lengthSquared(toCenter - along * w) > 0.85 * 0.85) continue;
                bool nearMiss = false;
                if (torus.crossing({p, w}, std::max(0.0, along - 0.86), along + 0.86, 0, nearMiss))
                    ++hits;
            }
        const double E = 2 * kPi * hits / (kGrid * kGrid);
        const double L = 0.5 * E / kPi;
        return Radiance{L, L, L};
    };
}

TEST(CliTorus, AnEmissiveTorusLightsTheFloorUnderItInPath) {
    const Image image = renderScene(lampOverFloor("path", 4096)).image;
    EXPECT_EQ(expectPixelsMatch(image, kFloorCamera, floorUnderTheLamp(), 0.02, 0), 49);
}

TEST(CliTorus, AnEmissiveTorusLightsTheFloorUnderItInRadiosity) {
    json scene = lampOverFloor("radiosity", 1);
    // Coarse elements: the torus alone is some 300 patches that all shoot.
    scene["radiosity"] = {{"patch_size", 0.5}, {"element_size", 0.5}, {"subdivision_levels", 1}};
    const Image image = renderScene(scene).image;
    // Radiosity shoots from the facets, chords of the tube (9 of them around it here) whose area
    // and solid angle fall short of the torus's by some 4%: within 7%, where path is within 2%.
    EXPECT_EQ(expectPixelsMatch(image, kFloorCamera, floorUnderTheLamp(), 0.07, 0), 49);
}

}  // namespace
}  // namespace lancer::test
