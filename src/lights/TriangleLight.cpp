#include "lights/TriangleLight.h"

#include <cmath>

#include "geometry/Hit.h"
#include "math/Float.h"

namespace lancer {

TriangleLight::TriangleLight(const std::array<Vec3, 3>& vertices, const Vec3& front,
                             const Color& radiance)
    : vertices_(vertices), radiance_(radiance) {
    const Vec3 n = cross(vertices[1] - vertices[0], vertices[2] - vertices[0]);
    area_ = 0.5f * length(n);
    normal_ = normalize(n);
    if (dot(normal_, front) < 0) normal_ = -normal_;
}

float TriangleLight::solidAnglePdf(const Vec3& p, const Vec3& onLight) const {
    const Vec3 toLight = onLight - p;
    const float distanceSquared = lengthSquared(toLight);
    const float cosLight = -dot(normal_, toLight) / std::sqrt(distanceSquared);
    if (!(cosLight > 0)) return 0;  // seen from behind: it sends nothing that way
    return areaToSolidAngleDensity(area_, distanceSquared, cosLight);
}

LightSample TriangleLight::sample(const Vec3& p, const Vec2& u) const {
    // Uniform over the area (pbrt's square-root warp of the unit square onto barycentrics).
    const float su0 = std::sqrt(u.x);
    const float b0 = 1 - su0, b1 = u.y * su0;
    LightSample s;
    s.position = b0 * vertices_[0] + b1 * vertices_[1] + (1 - b0 - b1) * vertices_[2];
    s.wi = normalize(s.position - p);
    s.pdf = solidAnglePdf(p, s.position);
    if (s.pdf > 0 && std::isfinite(s.pdf))
        s.irradiance = radiance_ / s.pdf;
    else
        s.pdf = 0;
    return s;
}

float TriangleLight::pdf(const Vec3& p, const Vec3&, const Hit& onLight) const {
    return solidAnglePdf(p, onLight.p);
}

Color TriangleLight::power(float) const {
    return kPi * area_ * radiance_;
}

}  // namespace lancer
