#pragma once

#include "materials/BsdfLobe.h"
#include "materials/GgxDistribution.h"

namespace lancer {

// A rough dielectric boundary of weight kt (the scene's `transmission` with `roughness` alpha >
// 0) and index `ior` on the front side (+z) against 1 on the back: the single-scattering
// microfacet BSDF of Walter et al. 2007 with the GGX distribution and Smith's separable
// masking-shadowing, as Mitsuba's roughdielectric. With eta the index on wi's side over that on
// wo's, the reflection is as RoughConductorLobe's with the dielectric Fresnel F, and the
// refraction
//
//     f(wo, wi) = kt (1 - F(wo.h)) D(h) G1(wo, h) G1(wi, h) |wi.h| |wo.h|
//                 / (|cos theta_i| |cos theta_o| (wo.h + eta wi.h)^2)
//
// about the generalised half vector h ~ wo + eta wi; this includes radiance's 1 / eta^2, as the
// smooth DielectricLobe. Sampled from the normals visible from wo (Heitz 2018), choosing the
// reflection with probability F.
class RoughDielectricLobe final : public BsdfLobe {
public:
    RoughDielectricLobe(const Color& weight, float ior, float alpha)
        : BsdfLobe(weight, Kind::Rough), ior_(ior), distribution_(alpha) {}

    Color f(const Vec3& wo, const Vec3& wi) const override;
    float pdf(const Vec3& wo, const Vec3& wi) const override;
    // uChoice chooses between reflection and refraction.
    std::optional<BsdfSample> sample(const Vec3& wo, float uChoice, const Vec2& u) const override;
    bool readsChoice() const override { return true; }
    // The reflection and the refraction about one visible normal, weighted kt F G1(wi) and
    // kt (1 - F) G1(wi).
    std::size_t tracedRays(const Vec3& wo, const Vec2& u,
                           std::array<SpecularRay, 2>& rays) const override;

private:
    // What f and pdf share for a pair of directions, with wo turned to the upper side.
    struct Configuration {
        Vec3 wo, wi, h;
        float eta;        // index on wi's side over index on wo's (1 for a reflection)
        float etaBeyond;  // index beyond the boundary over index on wo's side
        float fresnel;    // F(wo.h)
        bool reflection;
    };
    std::optional<Configuration> configuration(const Vec3& wo, const Vec3& wi) const;
    // A normal drawn from those visible from wo (wo.z != 0), with wo turned to the upper side.
    struct VisibleNormal {
        Vec3 wo, h;
        float etaBeyond;  // index beyond the boundary over index on wo's side
        float fresnel;    // F(wo.h)
        bool flip;        // wo was on the lower side
    };
    VisibleNormal drawNormal(const Vec3& wo, const Vec2& u) const;

    float ior_;
    GgxDistribution distribution_;
};

}  // namespace lancer
