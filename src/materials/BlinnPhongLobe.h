#pragma once

#include "materials/BsdfLobe.h"

namespace lancer {

// The Blinn-Phong highlight as an energy-conserving, reciprocal BRDF. With the half vector h of
// wo and wi and the normalized density of half vectors D(h) = (n + 1) / (2 pi) cos^n(theta_h)
// (which integrates to 1 over the hemisphere of h),
//
//     f(wo, wi) = ks D(h) / (4 (wo.h) max(cos theta_o, cos theta_i))
//
// Sampling h from D and reflecting wo about it gives wi the density D(h) / (4 wo.h) (the
// Jacobian of the reflection), so f cos(theta_i) / pdf = ks cos(theta_i) / max(cos theta_o,
// cos theta_i) <= ks: the albedo never exceeds ks, for any exponent and direction. This is the
// specular term of Ashikhmin and Shirley's model without its Fresnel factor; it is symmetric in
// wo and wi.
class BlinnPhongLobe final : public BsdfLobe {
public:
    BlinnPhongLobe(const Color& ks, float exponent)
        : BsdfLobe(ks, Kind::Glossy), exponent_(exponent) {}

    Color f(const Vec3& wo, const Vec3& wi) const override;
    float pdf(const Vec3& wo, const Vec3& wi) const override;
    std::optional<BsdfSample> sample(const Vec3& wo, float uChoice, const Vec2& u) const override;
    // The classic highlight ks max(0, n.h)^n, not normalized.
    Color localResponse(float cosThetaL, float cosThetaH) const override;

private:
    // D(h) / (4 wo.h) for h the half vector of wo and wi, which lie on the same side.
    float reflectedDensity(const Vec3& wo, const Vec3& wi) const;

    float exponent_;
};

}  // namespace lancer
