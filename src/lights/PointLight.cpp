#include "lights/PointLight.h"

namespace lancer {

PointLight::PointLight(const Vec3& position, const Color& intensity, bool inverseSquareFalloff)
    : position_(position), intensity_(intensity), inverseSquareFalloff_(inverseSquareFalloff) {}

LightSample PointLight::sample(const Vec3& p, const Vec2&) const {
    const Vec3 toLight = position_ - p;
    const float distanceSquared = lengthSquared(toLight);
    LightSample s;
    s.wi = toLight / std::sqrt(distanceSquared);
    s.irradiance = inverseSquareFalloff_ ? intensity_ / distanceSquared : intensity_;
    s.position = position_;
    return s;
}

}  // namespace lancer
