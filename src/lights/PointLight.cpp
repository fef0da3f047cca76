#include "lights/PointLight.h"

#include "math/Float.h"

namespace lancer {

bool PointLight::readInverseSquareFalloff(const Parameters& parameters) {
    return !parameters.has("falloff") ||
           parameters.choice("falloff", {"inverse_square", "none"}) == 0;
}

std::unique_ptr<Light> PointLight::create(const Parameters& parameters) {
    return std::make_unique<PointLight>(parameters.point("position"), parameters.color("intensity"),
                                        readInverseSquareFalloff(parameters));
}

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

// Without inverse-square falloff the power is infinite in principle; the same 4 pi I is used.
Color PointLight::power(float) const {
    return 4 * kPi * intensity_;
}

}  // namespace lancer
