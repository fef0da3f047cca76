#include "lights/DirectionalLight.h"

namespace lancer {

DirectionalLight::DirectionalLight(const Vec3& direction, const Color& irradiance)
    : towardsLight_(-normalize(direction)), irradiance_(irradiance) {}

LightSample DirectionalLight::sample(const Vec3&, const Vec2&) const {
    LightSample s;
    s.wi = towardsLight_;
    s.irradiance = irradiance_;
    s.atInfinity = true;
    return s;
}

}  // namespace lancer
