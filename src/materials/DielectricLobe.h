#pragma once

#include "materials/BsdfLobe.h"

namespace lancer {

// A smooth dielectric boundary of weight kt (the scene's `transmission`) and index `ior` on the
// front side (+z) against 1 on the back: it reflects the Fresnel fraction F and refracts 1 - F
// (all of it reflected under total internal reflection), choosing one of the two with those
// probabilities. Refracted radiance is scaled by 1 / eta^2 (radiance is compressed entering a
// denser medium), as in pbrt and Mitsuba.
class DielectricLobe final : public BsdfLobe {
public:
    DielectricLobe(const Color& weight, float ior) : BsdfLobe(weight, Kind::Delta), ior_(ior) {}

    Color f(const Vec3&, const Vec3&) const override { return Color(0); }
    float pdf(const Vec3&, const Vec3&) const override { return 0; }
    // u.x chooses between reflection and refraction.
    std::optional<BsdfSample> sample(const Vec3& wo, float uChoice, const Vec2& u) const override;
    // kt F reflected, kt (1 - F) refracted (nothing under total internal reflection).
    SpecularSplit specularSplit(float cosThetaO, bool outside) const override;

private:
    float ior_;
};

}  // namespace lancer
