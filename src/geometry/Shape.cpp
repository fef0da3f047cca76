#include "geometry/Shape.h"

#include <cmath>

namespace lancer {

bool Shape::contains(const Vec3& p) const {
    // Along a direction unlikely to run along an edge or a face of a modelled solid; inside
    // where more crossings behind p enter than leave.
    const Ray line{p, Vec3(0.5773f, 0.6019f, 0.5519f)};
    thread_local LineCrossings crossings;  // (crossLine never asks contains)
    crossings.clear();
    crossLine(line, crossings);
    int depth = 0;
    for (const LineCrossing& c : crossings) {
        if (c.crossing.t >= 0) break;
        depth += c.entering ? 1 : -1;
    }
    return depth > 0;
}

void Shape::crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const {
    if (!isSolid()) {
        if (const std::optional<SurfaceCrossing> crossing = cross(ray, tMax))
            crossings.push_back(*crossing);
        return;
    }
    thread_local LineCrossings line;  // (crossLine never asks crossSegment)
    line.clear();
    crossLine(ray, line);
    for (const LineCrossing& c : line)
        if (c.crossing.t > 0 && c.crossing.t < tMax) crossings.push_back(c.crossing);
}

float Shape::areaPdf(std::uint32_t primitive, const Hit&) const {
    return 1 / area(primitive);
}

float Shape::areaToSolidAngle(float areaPdf, float distanceSquared, float cosSurface) {
    const float cosine = std::abs(cosSurface);
    return cosine > 0 ? areaPdf * distanceSquared / cosine : 0;
}

std::optional<DirectionSample> Shape::seenFrom(const Vec3& reference, const ShapeSample& at) {
    const Vec3 toSurface = at.p - reference;
    const float distanceSquared = lengthSquared(toSurface);
    if (!(distanceSquared > 0)) return std::nullopt;  // the reference point itself
    return DirectionSample{at, toSurface / std::sqrt(distanceSquared)};
}

std::optional<DirectionSample> Shape::sample(std::uint32_t primitive, const Vec3& reference,
                                             const Vec2& u) const {
    const std::optional<ShapeSample> onSurface = sample(primitive, u);
    if (!onSurface) return std::nullopt;
    std::optional<DirectionSample> s = seenFrom(reference, *onSurface);
    if (!s) return std::nullopt;
    // The cosine at the surface from the unnormalized direction (shared with seenFrom's work).
    const Vec3 toSurface = s->at.p - reference;
    const float distanceSquared = lengthSquared(toSurface);
    s->at.pdf = areaToSolidAngle(s->at.pdf, distanceSquared,
                                 dot(s->at.n, toSurface) / std::sqrt(distanceSquared));
    if (!(s->at.pdf > 0) || !std::isfinite(s->at.pdf)) return std::nullopt;
    return s;
}

float Shape::pdf(std::uint32_t primitive, const Vec3& reference, const Vec3& wi,
                 const Hit& onSurface) const {
    return areaToSolidAngle(areaPdf(primitive, onSurface), lengthSquared(onSurface.p - reference),
                            dot(onSurface.ng, wi));
}

}  // namespace lancer
