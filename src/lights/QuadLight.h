#pragma once

#include "geometry/Quad.h"
#include "lights/Light.h"

namespace lancer {

// The contract's "quad" area light: a parallelogram emitting `radiance` from its front side (the
// side edge1 x edge2 faces) and nothing from the back. Its surface is `surface`, a Quad of the
// scene (which outlives the light), sampled uniformly by area.
class QuadLight final : public Light {
public:
    QuadLight(const Quad& surface, const Color& radiance);

    LightSample sample(const Vec3& p, const Vec2& u) const override;
    bool isDelta() const override { return false; }
    float pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const override;
    Color power(float sceneRadius) const override;

    const Quad& surface() const { return surface_; }
    const Color& radiance() const { return radiance_; }

private:
    const Quad& surface_;
    Color radiance_;
};

}  // namespace lancer
