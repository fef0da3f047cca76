#include "geometry/Shape.h"

#include <cmath>

namespace lancer {

float Shape::areaPdf(std::uint32_t primitive, const Hit&) const {
    return 1 / area(primitive);
}

float Shape::areaToSolidAngle(float areaPdf, float distanceSquared, float cosSurface) {
    const float cosine = std::abs(cosSurface);
    return cosine > 0 ? areaPdf * distanceSquared / cosine : 0;
}

std::optional<ShapeSample> Shape::sample(std::uint32_t primitive, const Vec3& reference,
                                         const Vec2& u) const {
    std::optional<ShapeSample> s = sample(primitive, u);
    if (!s) return std::nullopt;
    const Vec3 toSurface = s->p - reference;
    const float distanceSquared = lengthSquared(toSurface);
    if (!(distanceSquared > 0)) return std::nullopt;  // the reference point itself
    s->pdf = areaToSolidAngle(s->pdf, distanceSquared,
                              dot(s->n, toSurface) / std::sqrt(distanceSquared));
    if (!(s->pdf > 0) || !std::isfinite(s->pdf)) return std::nullopt;
    return s;
}

float Shape::pdf(std::uint32_t primitive, const Vec3& reference, const Vec3& wi,
                 const Hit& onSurface) const {
    return areaToSolidAngle(areaPdf(primitive, onSurface), lengthSquared(onSurface.p - reference),
                            dot(onSurface.ng, wi));
}

}  // namespace lancer
