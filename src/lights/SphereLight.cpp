#include "lights/SphereLight.h"

#include <cmath>
#include <numbers>

#include "geometry/Hit.h"
#include "math/Float.h"

namespace lancer {

namespace {

// Points within rounding error of the surface (hit points on the light itself, from inside or
// out) count as inside: from there the light seen is the whole sphere, which area sampling
// covers, while the cone would shrink to the point itself.
bool isInside(const Vec3& p, const Sphere& sphere) {
    const double reach = sphere.radius() + 2 * length(Vec3d(gamma(3) * abs(p)));
    return lengthSquared(Vec3d(p) - Vec3d(sphere.center())) <= reach * reach;
}

}  // namespace

SphereLight::SphereLight(const Sphere& surface, const Color& radiance)
    : surface_(surface), radiance_(radiance) {}

float SphereLight::surfaceArea() const {
    return 4 * kPi * surface_.radius() * surface_.radius();
}

double SphereLight::oneMinusCosConeAngle(const Vec3& p) const {
    const double r = surface_.radius();
    const double sin2ThetaMax = r * r / lengthSquared(Vec3d(p) - Vec3d(surface_.center()));
    // 1 - cos written as sin^2 / (1 + cos): no cancellation for small, distant spheres.
    return sin2ThetaMax / (1 + std::sqrt(std::max(0.0, 1 - sin2ThetaMax)));
}

float SphereLight::coneDensity(const Vec3& p) const {
    return static_cast<float>(1 / (2 * std::numbers::pi * oneMinusCosConeAngle(p)));
}

LightSample SphereLight::sample(const Vec3& p, const Vec2& u) const {
    const Vec3d center(surface_.center());
    const double r = surface_.radius();
    const double twoPi = 2 * std::numbers::pi;
    const double phi = twoPi * u.y;
    LightSample s;
    if (isInside(p, surface_)) {
        // Uniform over the surface, converted to solid angle (both sides emit).
        const double z = 1 - 2 * static_cast<double>(u.x);
        const double ring = std::sqrt(std::max(0.0, 1 - z * z));
        const Vec3d normal(ring * std::cos(phi), ring * std::sin(phi), z);
        s.position = Vec3(center + r * normal);
        const Vec3 toLight = s.position - p;
        const float distanceSquared = lengthSquared(toLight);
        if (!(distanceSquared > 0)) return s;
        s.wi = toLight / std::sqrt(distanceSquared);
        s.pdf = areaToSolidAngleDensity(surfaceArea(), distanceSquared, dot(Vec3(normal), s.wi));
        if (s.pdf > 0) s.irradiance = radiance_ / s.pdf;
        return s;
    }

    // Uniform within the cone: 1 - cos(theta) uniform in [0, 1 - cos(theta_max)].
    const Vec3d toCenter = center - Vec3d(p);
    const Vec3d axis = normalize(toCenter);
    const double oneMinusCosTheta = u.x * oneMinusCosConeAngle(p);
    const double cosTheta = 1 - oneMinusCosTheta;
    const double sinTheta = std::sqrt(std::max(0.0, oneMinusCosTheta * (2 - oneMinusCosTheta)));
    Vec3d a, b;
    coordinateSystem(axis, a, b);
    const Vec3d wi = cosTheta * axis + sinTheta * (std::cos(phi) * a + std::sin(phi) * b);
    // Where that direction enters the sphere; at the cone's edge rounding may make the ray graze
    // past it, so the discriminant is clamped to the tangent point.
    const double along = dot(wi, toCenter);
    const double offAxisSquared = lengthSquared(toCenter - along * wi);
    const double t = along - std::sqrt(std::max(0.0, r * r - offAxisSquared));
    s.wi = Vec3(wi);
    s.position = Vec3(Vec3d(p) + t * wi);
    s.pdf = coneDensity(p);
    s.irradiance = radiance_ / s.pdf;
    return s;
}

float SphereLight::pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const {
    if (isInside(p, surface_))
        return areaToSolidAngleDensity(surfaceArea(), lengthSquared(onLight.p - p),
                                       dot(onLight.ng, wi));
    return coneDensity(p);
}

// Every point of a Lambertian emitter sends pi L per unit area.
Color SphereLight::power(float) const {
    return kPi * surfaceArea() * radiance_;
}

}  // namespace lancer
