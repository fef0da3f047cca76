#include "materials/RoughDielectricLobe.h"

#include <cmath>

#include "materials/Optics.h"

namespace lancer {

std::optional<RoughDielectricLobe::Configuration> RoughDielectricLobe::configuration(
    const Vec3& wo, const Vec3& wi) const {
    if (wo.z == 0 || wi.z == 0) return std::nullopt;
    Configuration c;
    // From the lower side, both directions are turned over and the indices swap.
    const bool flip = wo.z < 0;
    c.wo = flip ? -wo : wo;
    c.wi = flip ? -wi : wi;
    c.etaBeyond = flip ? 1 / ior_ : ior_;
    c.reflection = c.wi.z > 0;
    c.eta = c.reflection ? 1 : c.etaBeyond;
    const Vec3 sum = c.wo + c.eta * c.wi;
    const float lengthSq = lengthSquared(sum);
    if (!(lengthSq > 0)) return std::nullopt;
    c.h = sum / std::sqrt(lengthSq);
    if (c.h.z < 0) c.h = -c.h;
    // Microfacets seen from their back by either direction scatter nothing.
    if (dot(c.wo, c.h) <= 0 || dot(c.wi, c.h) * c.wi.z <= 0) return std::nullopt;
    c.fresnel = fresnelDielectric(dot(c.wo, c.h), c.etaBeyond);
    return c;
}

Color RoughDielectricLobe::f(const Vec3& wo, const Vec3& wi) const {
    const std::optional<Configuration> c = configuration(wo, wi);
    if (!c) return Color(0);
    const float d = distribution_.density(c->h);
    const float g = distribution_.smithG(c->wo, c->wi, c->h);
    const float cosProduct = std::abs(c->wo.z * c->wi.z);
    if (c->reflection) return weight() * (c->fresnel * d * g / (4 * cosProduct));
    const float oDotH = dot(c->wo, c->h), iDotH = dot(c->wi, c->h);
    const float denominator = oDotH + c->eta * iDotH;
    return weight() * ((1 - c->fresnel) * d * g * std::abs(iDotH * oDotH) /
                       (cosProduct * denominator * denominator));
}

float RoughDielectricLobe::pdf(const Vec3& wo, const Vec3& wi) const {
    const std::optional<Configuration> c = configuration(wo, wi);
    if (!c) return 0;
    const float visible = distribution_.visibleDensity(c->wo, c->h);
    const float oDotH = dot(c->wo, c->h);
    if (c->reflection) return c->fresnel * visible / (4 * oDotH);
    // dw_h / dw_i of the refraction (Walter et al. 2007, eq. 17).
    const float iDotH = dot(c->wi, c->h);
    const float denominator = oDotH + c->eta * iDotH;
    return (1 - c->fresnel) * visible * c->eta * c->eta * std::abs(iDotH) /
           (denominator * denominator);
}

RoughDielectricLobe::VisibleNormal RoughDielectricLobe::drawNormal(const Vec3& wo,
                                                                   const Vec2& u) const {
    VisibleNormal n;
    n.flip = wo.z < 0;
    n.wo = n.flip ? -wo : wo;
    n.etaBeyond = n.flip ? 1 / ior_ : ior_;
    n.h = distribution_.sampleVisible(n.wo, u);
    n.fresnel = fresnelDielectric(dot(n.wo, n.h), n.etaBeyond);
    return n;
}

std::optional<BsdfSample> RoughDielectricLobe::sample(const Vec3& wo, float uChoice,
                                                      const Vec2& u) const {
    if (wo.z == 0) return std::nullopt;
    const VisibleNormal n = drawNormal(wo, u);
    const Vec3 &o = n.wo, &h = n.h;
    const float etaBeyond = n.etaBeyond, F = n.fresnel;
    Vec3 i;
    BsdfSample s;
    if (uChoice < F) {
        i = normalize(reflect(o, h));
        if (i.z <= 0) return std::nullopt;
    } else {
        const std::optional<Vec3> refracted = refract(o, h, etaBeyond);
        if (!refracted) return std::nullopt;  // F = 1 there: never reached
        i = normalize(*refracted);
        if (i.z >= 0) return std::nullopt;
        s.etaSquared = etaBeyond * etaBeyond;
    }
    s.wi = n.flip ? -i : i;
    s.pdf = pdf(wo, s.wi);
    if (!(s.pdf > 0)) return std::nullopt;
    s.f = f(wo, s.wi);
    return s;
}

std::size_t RoughDielectricLobe::tracedRays(const Vec3& wo, const Vec2& u,
                                            std::array<SpecularRay, 2>& rays) const {
    if (wo.z == 0) return 0;
    const VisibleNormal n = drawNormal(wo, u);
    std::size_t count = 0;
    const auto trace = [&](const Vec3& i, float share) {
        const float g1 = distribution_.smithG1(i, n.h);
        if (share > 0 && g1 > 0) rays[count++] = {n.flip ? -i : i, weight() * (share * g1)};
    };
    const Vec3 reflected = normalize(reflect(n.wo, n.h));
    if (reflected.z > 0) trace(reflected, n.fresnel);
    if (const std::optional<Vec3> refracted = refract(n.wo, n.h, n.etaBeyond)) {
        const Vec3 i = normalize(*refracted);
        if (i.z < 0) trace(i, 1 - n.fresnel);
    }
    return count;
}

}  // namespace lancer
