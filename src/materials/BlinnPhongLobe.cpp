#include "materials/BlinnPhongLobe.h"

#include <algorithm>
#include <cmath>

#include "math/Float.h"

namespace lancer {

float BlinnPhongLobe::reflectedDensity(const Vec3& wo, const Vec3& wi) const {
    Vec3 h = wo + wi;
    const float lengthSq = lengthSquared(h);
    if (!(lengthSq > 0)) return 0;
    h = h / std::sqrt(lengthSq);
    // Both on the lower side: the lobe of the back face, mirrored.
    const float cosThetaH = std::abs(h.z);
    const float woDotH = dot(wo, h);
    if (woDotH <= 0) return 0;
    const float d = (exponent_ + 1) / (2 * kPi) * std::pow(cosThetaH, exponent_);
    return d / (4 * woDotH);
}

Color BlinnPhongLobe::f(const Vec3& wo, const Vec3& wi) const {
    if (wo.z * wi.z <= 0) return Color(0);
    return weight() * (reflectedDensity(wo, wi) / std::max(std::abs(wo.z), std::abs(wi.z)));
}

float BlinnPhongLobe::pdf(const Vec3& wo, const Vec3& wi) const {
    if (wo.z * wi.z <= 0) return 0;
    return reflectedDensity(wo, wi);
}

Color BlinnPhongLobe::localResponse(float, float cosThetaH) const {
    return weight() * std::pow(std::max(0.0f, cosThetaH), exponent_);
}

std::optional<BsdfSample> BlinnPhongLobe::sample(const Vec3& wo, float, const Vec2& u) const {
    if (wo.z == 0) return std::nullopt;
    // h with density D(h): cos(theta_h) = u^(1 / (n + 1)) inverts the cumulative distribution
    // of cos(theta_h), whose density is (n + 1) cos^n.
    const float cosThetaH = std::pow(u.x, 1 / (exponent_ + 1));
    const float sinThetaH = std::sqrt(std::max(0.0f, 1 - cosThetaH * cosThetaH));
    const float phi = 2 * kPi * u.y;
    Vec3 h(sinThetaH * std::cos(phi), sinThetaH * std::sin(phi), cosThetaH);
    if (wo.z < 0) h.z = -h.z;
    const Vec3 wi = reflect(wo, h);
    if (wo.z * wi.z <= 0) return std::nullopt;  // reflected below the surface: no light there
    BsdfSample s;
    s.wi = normalize(wi);
    s.pdf = pdf(wo, s.wi);
    if (!(s.pdf > 0)) return std::nullopt;
    s.f = f(wo, s.wi);
    return s;
}

}  // namespace lancer
