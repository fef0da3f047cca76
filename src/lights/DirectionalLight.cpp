#include "lights/DirectionalLight.h"

#include "math/Float.h"

namespace lancer {

std::unique_ptr<Light> DirectionalLight::create(const Parameters& parameters) {
    return std::make_unique<DirectionalLight>(parameters.direction("direction"),
                                              parameters.color("irradiance"));
}

DirectionalLight::DirectionalLight(const Vec3& direction, const Color& irradiance)
    : towardsLight_(-normalize(direction)), irradiance_(irradiance) {}

LightSample DirectionalLight::sample(const Vec3&, const Vec2&) const {
    LightSample s;
    s.wi = towardsLight_;
    s.irradiance = irradiance_;
    s.atInfinity = true;
    return s;
}

// The light that crosses a disc as wide as the scene.
Color DirectionalLight::power(float sceneRadius) const {
    return kPi * sceneRadius * sceneRadius * irradiance_;
}

}  // namespace lancer
