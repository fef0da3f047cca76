#pragma once

#include <optional>

#include "materials/BsdfLobe.h"
#include "materials/GgxDistribution.h"
#include "materials/Optics.h"

namespace lancer {

// Rough reflection of weight kr (the scene's `reflection` with `roughness` alpha > 0), on either
// side: the single-scattering microfacet BRDF of Walter et al. 2007 with the GGX distribution
// and Smith's separable masking-shadowing, as Mitsuba's roughconductor,
//
//     f(wo, wi) = kr F(wi.h) D(h) G1(wo, h) G1(wi, h) / (4 |cos theta_o| |cos theta_i|)
//
// with h the half vector and F the conductor's Fresnel reflectance (1 without one: a rough
// mirror). Sampled from the normals visible from wo (Heitz 2018), so that the sample weight is
// kr F G1(wi, h) <= kr.
class RoughConductorLobe final : public BsdfLobe {
public:
    RoughConductorLobe(const Color& reflectance, float alpha, std::optional<ConductorIor> ior)
        : BsdfLobe(reflectance, Kind::Rough), distribution_(alpha), ior_(ior) {}

    Color f(const Vec3& wo, const Vec3& wi) const override;
    float pdf(const Vec3& wo, const Vec3& wi) const override;
    std::optional<BsdfSample> sample(const Vec3& wo, float uChoice, const Vec2& u) const override;
    std::size_t tracedRays(const Vec3& wo, const Vec2& u,
                           std::array<SpecularRay, 2>& rays) const override;

private:
    // A reflection about a normal h drawn from those visible from wo: wi, and wi and h on wo's
    // side turned up (where the lobe is written).
    struct Reflection {
        Vec3 wi, upper, h;
    };
    std::optional<Reflection> reflectVisible(const Vec3& wo, const Vec2& u) const;

    // kr F at the cosine between a direction and the microfacet normal.
    Color reflectance(float cosThetaH) const {
        return ior_ ? weight() * fresnelConductor(cosThetaH, *ior_) : weight();
    }

    GgxDistribution distribution_;
    std::optional<ConductorIor> ior_;
};

}  // namespace lancer
