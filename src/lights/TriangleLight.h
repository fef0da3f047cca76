#pragma once

#include <array>

#include "lights/Light.h"

namespace lancer {

// An emissive triangle sampled as a light: radiance `radiance` leaves its front side (where
// `front` points: the side (v1 - v0) x (v2 - v0) faces, or an instanced face's transformed
// normal), nothing its back. Points are drawn uniformly over its area.
class TriangleLight final : public Light {
public:
    TriangleLight(const std::array<Vec3, 3>& vertices, const Vec3& front, const Color& radiance);

    LightSample sample(const Vec3& p, const Vec2& u) const override;
    bool isDelta() const override { return false; }
    float pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const override;
    Color power(float sceneRadius) const override;

private:
    // The solid-angle density of reaching `onLight` from p by area sampling; 0 from behind.
    float solidAnglePdf(const Vec3& p, const Vec3& onLight) const;

    std::array<Vec3, 3> vertices_;
    Vec3 normal_;  // unit, on the emitting side
    float area_;
    Color radiance_;
};

}  // namespace lancer
