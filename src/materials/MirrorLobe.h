#pragma once

#include "materials/BsdfLobe.h"

namespace lancer {

// A perfect mirror reflecting the fraction kr of the light (the scene's `reflection`), on either
// side.
class MirrorLobe final : public BsdfLobe {
public:
    explicit MirrorLobe(const Color& reflectance) : BsdfLobe(reflectance, Kind::Delta) {}

    Color f(const Vec3&, const Vec3&) const override { return Color(0); }
    float pdf(const Vec3&, const Vec3&) const override { return 0; }
    std::optional<BsdfSample> sample(const Vec3& wo, float uChoice, const Vec2& u) const override;
    SpecularSplit specularSplit(float, bool) const override { return {weight(), Color(0)}; }
};

}  // namespace lancer
