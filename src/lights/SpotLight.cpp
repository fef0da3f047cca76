#include "lights/SpotLight.h"

#include <algorithm>

#include "lights/PointLight.h"

#include <cmath>

#include "math/Float.h"

namespace lancer {

std::unique_ptr<Light> SpotLight::create(const Parameters& parameters) {
    const Vec3 position = parameters.point("position");
    Vec3 direction;
    if (parameters.has("direction") && parameters.has("look_at"))
        parameters.fail("look_at", "a spot light takes \"direction\" or \"look_at\", not both");
    if (parameters.has("direction")) {
        direction = parameters.direction("direction");
    } else if (parameters.has("look_at")) {
        direction = parameters.point("look_at") - position;
        if (!(lengthSquared(direction) > 0) || !isFinite(normalize(direction)))
            parameters.fail("look_at",
                            "a spot light's \"look_at\" must differ from its \"position\"");
    } else {
        parameters.fail("direction", "a spot light needs \"direction\" or \"look_at\"");
    }
    const Color intensity = parameters.color("intensity");
    // pbrt's defaults: a 30 degree cone fading over its outer 5 degrees.
    float coneAngle = 30;
    if (parameters.has("cone_angle")) {
        coneAngle = parameters.numberAbove("cone_angle", 0, false);
        if (coneAngle > 180)
            parameters.fail("cone_angle", "\"cone_angle\" must be at most 180 degrees");
    }
    float coneFalloff = std::min(5.0f, coneAngle);
    if (parameters.has("cone_falloff")) {
        coneFalloff = parameters.numberAbove("cone_falloff", 0, true);
        if (coneFalloff > coneAngle)
            parameters.fail("cone_falloff", "\"cone_falloff\" must not exceed \"cone_angle\"");
    }
    return std::make_unique<SpotLight>(position, direction, intensity, coneAngle, coneFalloff,
                                       PointLight::readInverseSquareFalloff(parameters));
}

namespace {

// 0 below edge0, 1 above edge1, Hermite-smooth between; a step at edge0 when the edges meet.
float smoothStep(float x, float edge0, float edge1) {
    if (edge0 == edge1) return x < edge0 ? 0.0f : 1.0f;
    const float t = clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3 - 2 * t);
}

}  // namespace

SpotLight::SpotLight(const Vec3& position, const Vec3& direction, const Color& intensity,
                     float coneAngleDegrees, float coneFalloffDegrees, bool inverseSquareFalloff)
    : position_(position),
      direction_(normalize(direction)),
      intensity_(intensity),
      cosConeAngle_(std::cos(radians(coneAngleDegrees))),
      cosFalloffStart_(std::cos(radians(coneAngleDegrees - coneFalloffDegrees))),
      inverseSquareFalloff_(inverseSquareFalloff) {}

float SpotLight::coneFactor(const Vec3& w) const {
    return smoothStep(dot(direction_, w), cosConeAngle_, cosFalloffStart_);
}

LightSample SpotLight::sample(const Vec3& p, const Vec2&) const {
    const Vec3 toLight = position_ - p;
    const float distanceSquared = lengthSquared(toLight);
    LightSample s;
    s.position = position_;
    if (!(distanceSquared > 0)) return s;
    s.wi = toLight / std::sqrt(distanceSquared);
    const Color intensity = coneFactor(-s.wi) * intensity_;
    s.irradiance = inverseSquareFalloff_ ? intensity / distanceSquared : intensity;
    return s;
}

// The intensity integrated over the sphere of directions: 2 pi (1 - cos) over the full-intensity
// cap, and half the solid angle of the ring where the smoothstep (symmetric about its midpoint)
// fades it out.
Color SpotLight::power(float) const {
    return 2 * kPi * ((1 - cosFalloffStart_) + (cosFalloffStart_ - cosConeAngle_) / 2) * intensity_;
}

}  // namespace lancer
