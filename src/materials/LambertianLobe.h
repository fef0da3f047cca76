#pragma once

#include "materials/BsdfLobe.h"

namespace lancer {

// Ideal diffuse reflection of albedo kd, f = kd / pi, on whichever side wo is (surfaces are
// two-sided); sampled by cos(theta).
class LambertianLobe final : public BsdfLobe {
public:
    explicit LambertianLobe(const Color& albedo) : BsdfLobe(albedo, Kind::Diffuse) {}

    Color f(const Vec3& wo, const Vec3& wi) const override;
    float pdf(const Vec3& wo, const Vec3& wi) const override;
    std::optional<BsdfSample> sample(const Vec3& wo, float uChoice, const Vec2& u) const override;
};

}  // namespace lancer
