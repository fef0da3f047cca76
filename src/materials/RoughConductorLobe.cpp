#include "materials/RoughConductorLobe.h"

#include <cmath>

namespace lancer {

namespace {

// The lobe is written for wo on the upper side; from the lower side, both directions are turned
// over (the surface is two-sided).
Vec3 upperSide(const Vec3& w, bool flip) {
    return flip ? -w : w;
}

}  // namespace

Color RoughConductorLobe::f(const Vec3& wo, const Vec3& wi) const {
    if (wo.z * wi.z <= 0) return Color(0);
    const bool flip = wo.z < 0;
    const Vec3 o = upperSide(wo, flip), i = upperSide(wi, flip);
    const Vec3 h = normalize(o + i);
    const float d = distribution_.density(h);
    if (d == 0) return Color(0);
    const float g = distribution_.smithG(o, i, h);
    return reflectance(dot(i, h)) * (d * g / (4 * o.z * i.z));
}

float RoughConductorLobe::pdf(const Vec3& wo, const Vec3& wi) const {
    if (wo.z * wi.z <= 0) return 0;
    const bool flip = wo.z < 0;
    const Vec3 o = upperSide(wo, flip), i = upperSide(wi, flip);
    const Vec3 h = normalize(o + i);
    // The Jacobian of the reflection about h: dw_h / dw_i = 1 / (4 wo.h).
    const float oDotH = dot(o, h);
    if (oDotH <= 0) return 0;
    return distribution_.visibleDensity(o, h) / (4 * oDotH);
}

std::optional<RoughConductorLobe::Reflection> RoughConductorLobe::reflectVisible(
    const Vec3& wo, const Vec2& u) const {
    if (wo.z == 0) return std::nullopt;
    const bool flip = wo.z < 0;
    const Vec3 o = upperSide(wo, flip);
    const Vec3 h = distribution_.sampleVisible(o, u);
    const Vec3 i = normalize(reflect(o, h));
    if (i.z <= 0) return std::nullopt;  // reflected into the surface: masked, no light
    return Reflection{upperSide(i, flip), i, h};
}

std::optional<BsdfSample> RoughConductorLobe::sample(const Vec3& wo, float, const Vec2& u) const {
    const std::optional<Reflection> r = reflectVisible(wo, u);
    if (!r) return std::nullopt;
    BsdfSample s;
    s.wi = r->wi;
    s.pdf = pdf(wo, s.wi);
    if (!(s.pdf > 0)) return std::nullopt;
    s.f = f(wo, s.wi);
    return s;
}

std::size_t RoughConductorLobe::tracedRays(const Vec3& wo, const Vec2& u,
                                           std::array<SpecularRay, 2>& rays) const {
    const std::optional<Reflection> r = reflectVisible(wo, u);
    if (!r) return 0;
    // f cos / pdf = kr F G1(wo) G1(wi) / G1(wo).
    rays[0] = {r->wi, reflectance(dot(r->upper, r->h)) * distribution_.smithG1(r->upper, r->h)};
    return 1;
}

}  // namespace lancer
