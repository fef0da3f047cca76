#include "lights/AreaLight.h"

#include <cmath>

#include "geometry/Shape.h"
#include "math/Float.h"

namespace lancer {

AreaLight::AreaLight(const Shape& shape, std::uint32_t primitive, const Color& radiance,
                     RadianceAt radianceAt)
    : shape_(shape),
      primitive_(primitive),
      radiance_(radiance),
      radianceAt_(std::move(radianceAt)) {}

LightSample AreaLight::sample(const Vec3& p, const Vec2& u) const {
    LightSample s;
    // Nothing for p on the light itself: no direction, no light.
    const std::optional<DirectionSample> towards = shape_.sample(primitive_, p, u);
    if (!towards) return s;
    s.position = towards->at.p;
    s.wi = towards->wi;
    s.pdf = towards->at.pdf;
    // A one-sided emitter seen from behind shows its dark back.
    const bool seesEmittingSide = shape_.emitsOnBothSides() || dot(towards->at.n, s.wi) < 0;
    if (!seesEmittingSide || !(s.pdf > 0) || !std::isfinite(s.pdf)) return s;
    s.irradiance = radiance(p, s) / s.pdf;
    return s;
}

Color AreaLight::radiance(const Vec3& p, const LightSample& s) const {
    if (!radianceAt_) return radiance_;
    // The point's uv come with a hit on the shape: the ray from p ends just past the sample.
    const Ray towards{p, s.position - p};
    const std::optional<Hit> onLight = shape_.intersect(towards, 1 + 1e-4f);
    return onLight ? radianceAt_(*onLight) : radiance_;
}

float AreaLight::pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const {
    return shape_.pdf(primitive_, p, wi, onLight);
}

Color AreaLight::power(float) const {
    return kPi * shape_.area(primitive_) * radiance_;
}

}  // namespace lancer
