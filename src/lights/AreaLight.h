#pragma once

#include <cstdint>
#include <functional>

#include "lights/Light.h"

namespace lancer {

class Shape;

// A surface that emits `radiance` uniformly (a Lambertian emitter): one primitive of any shape,
// on its front side only or on both, as the shape says. The scene file's "quad" and "sphere"
// lights and every emissive surface are area lights over their shape, sampled as the shape
// samples itself (by area, or better where the shape knows how: the cone a sphere subtends).
class AreaLight final : public Light {
public:
    // The radiance that a textured emitter sends from a point of its surface.
    using RadianceAt = std::function<Color(const Hit&)>;

    // The shape outlives the light. `radiance` is the mean (all of it for a uniform emitter);
    // `radianceAt`, if given, the radiance at each point, found by a ray to the point sampled.
    AreaLight(const Shape& shape, std::uint32_t primitive, const Color& radiance,
              RadianceAt radianceAt = nullptr);

    LightSample sample(const Vec3& p, const Vec2& u) const override;
    bool isDelta() const override { return false; }
    float pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const override;
    // pi L per unit area: what a Lambertian emitter sends from one side.
    Color power(float sceneRadius) const override;

    const Shape& shape() const { return shape_; }
    const Color& radiance() const { return radiance_; }

private:
    // The radiance the sample s, seen from p, receives from.
    Color radiance(const Vec3& p, const LightSample& s) const;

    const Shape& shape_;
    std::uint32_t primitive_;
    Color radiance_;
    RadianceAt radianceAt_;
};

}  // namespace lancer
