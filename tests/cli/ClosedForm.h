#pragma once

// Independent, double-precision models of what the contract says a render must show: the camera
// formula, ray/shape intersections, Blinn-Phong terms. The analytic tests compare lancer's images
// with these, pixel by pixel.

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "LancerRun.h"
#include "math/Vec3.h"

namespace lancer::test {

struct RayD {
    Vec3d origin;
    Vec3d direction;  // unit length

    Vec3d at(double t) const { return origin + t * direction; }
};

// Linear RGB in double precision.
struct Radiance {
    double r = 0, g = 0, b = 0;

    static Radiance fromJson(const nlohmann::json& value);  // a number (grey) or [r, g, b]
};
inline Radiance operator+(const Radiance& a, const Radiance& b) {
    return {a.r + b.r, a.g + b.g, a.b + b.b};
}
inline Radiance operator*(const Radiance& a, const Radiance& b) {
    return {a.r * b.r, a.g * b.g, a.b * b.b};
}
inline Radiance operator*(double s, const Radiance& a) {
    return {s * a.r, s * a.g, s * a.b};
}

Vec3d vec3FromJson(const nlohmann::json& xyz);

// What a light of the contract delivers at a point: its unoccluded irradiance E_l (point light:
// intensity / d^2, or intensity with "falloff": "none"; directional: irradiance) and the unit
// direction L towards it.
struct Incident {
    Radiance irradiance;
    Vec3d towardsLight;
};
Incident incidentLight(const nlohmann::json& light, const Vec3d& p);

// The irradiance that a Lambertian polygon of radiance 1 gives a surface at p with unit normal n:
// the integral of cos over the solid angle the polygon subtends, by Lambert's formula
// (1/2) |sum_i theta_i n . normalize(v_i x v_i+1)|, where v_i are the vertices as seen from p and
// theta_i the angle between v_i and v_i+1. The polygon must lie wholly above p's tangent plane.
double polygonIrradiance(const Vec3d& p, const Vec3d& n, const std::vector<Vec3d>& vertices);

// The irradiance that the box [lo, hi] of radiance 1 gives a surface at p with unit normal n,
// from the faces whose outer side p is on (which must lie wholly above p's tangent plane).
double boxIrradiance(const Vec3d& p, const Vec3d& n, const Vec3d& lo, const Vec3d& hi);

// The pinhole camera of the contract: w = normalize(position - look_at), u = normalize(up x w),
// v = w x u, and the ray through image point (px, py) has direction
// normalize((2 px / width - 1) tan_w u + (1 - 2 py / height) tan_h v - w).
struct CameraModel {
    Vec3d position;
    Vec3d lookAt;
    Vec3d up{0, 1, 0};
    double vfovDegrees = 40;
    int width = 32;
    int height = 24;

    // With one sample per pixel, lancer's only sample goes through the pixel's centre.
    RayD rayThroughPixelCentre(int i, int j) const;
    // Sets the scene's "camera" and its "render" size, with one sample per pixel.
    void placeIn(nlohmann::json& scene) const;
};

// The nearest t > 0 where the ray meets the shape, if it does.
std::optional<double> intersectPlane(const RayD& ray, const Vec3d& point, const Vec3d& normal);
std::optional<double> intersectSphere(const RayD& ray, const Vec3d& center, double radius);

// The distance from `point` to the segment [a, b].
double distanceToSegment(const Vec3d& point, const Vec3d& a, const Vec3d& b);
// The distance from `point` to the ray's line (for silhouette margins).
double distanceToLine(const Vec3d& point, const RayD& ray);

// What the pixel whose centre ray is `ray` must hold; no value for a pixel that the test leaves
// unchecked because it lies within rounding distance of an edge (a silhouette, a shadow border).
using PixelOracle = std::function<std::optional<Radiance>(const RayD& ray)>;

// The scene of an emitter over a floor, as the shape tests light it: `floor` and `lamp` (objects
// without their materials) get a Lambertian floor of albedo 0.5 and a lamp of radiance 2 that
// reflects nothing, on black; the camera placed, direct light only (max_depth 1).
nlohmann::json emitterOverFloor(const nlohmann::json& floor, const nlohmann::json& lamp,
                                const CameraModel& camera, const std::string& integrator, int spp);

// What a Lambertian floor on y = 0 of albedo kd shows where it receives the irradiance E(p):
// kd E / pi.
PixelOracle lambertianFloor(double kd, std::function<double(const Vec3d& p)> irradiance);

// Checks each pixel of a linear image against the oracle: |rendered - expected| <= absolute +
// relative * |expected| in every channel. Reports the first few mismatches with their
// coordinates and returns how many pixels were checked.
int expectPixelsMatch(const Image& image, const CameraModel& camera, const PixelOracle& expected,
                      double relative, double absolute);

}  // namespace lancer::test
