#pragma once

#include "materials/BsdfLobe.h"
#include "materials/Optics.h"

namespace lancer {

// A smooth conductor: a perfect mirror reflecting kr F_conductor(cos theta, eta, k) of the light
// (the scene's `reflection` with `metal` or `conductor`), on either side.
class ConductorLobe final : public BsdfLobe {
public:
    ConductorLobe(const Color& reflectance, const ConductorIor& ior)
        : BsdfLobe(reflectance, Kind::Delta), ior_(ior) {}

    Color f(const Vec3&, const Vec3&) const override { return Color(0); }
    float pdf(const Vec3&, const Vec3&) const override { return 0; }
    std::optional<BsdfSample> sample(const Vec3& wo, float uChoice, const Vec2& u) const override;
    SpecularSplit specularSplit(float cosThetaO, bool) const override {
        return {weight() * fresnelConductor(cosThetaO, ior_), Color(0)};
    }

private:
    ConductorIor ior_;
};

}  // namespace lancer
