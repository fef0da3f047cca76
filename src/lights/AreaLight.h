#pragma once

#include <cstdint>

#include "lights/Light.h"

namespace lancer {

class Shape;

// A surface that emits `radiance` uniformly (a Lambertian emitter): one primitive of any shape,
// on its front side only or on both, as the shape says. The scene file's "quad" and "sphere"
// lights and every emissive surface are area lights over their shape, sampled as the shape
// samples itself (by area, or better where the shape knows how: the cone a sphere subtends).
class AreaLight final : public Light {
public:
    // The shape outlives the light.
    AreaLight(const Shape& shape, std::uint32_t primitive, const Color& radiance);

    LightSample sample(const Vec3& p, const Vec2& u) const override;
    bool isDelta() const override { return false; }
    float pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const override;
    // pi L per unit area: what a Lambertian emitter sends from one side.
    Color power(float sceneRadius) const override;

    const Shape& shape() const { return shape_; }
    const Color& radiance() const { return radiance_; }

private:
    const Shape& shape_;
    std::uint32_t primitive_;
    Color radiance_;
};

}  // namespace lancer
