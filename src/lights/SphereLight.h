#pragma once

#include "geometry/Sphere.h"
#include "lights/Light.h"

namespace lancer {

// A spherical area light emitting `radiance` from every point of its surface, on both sides (so a
// point inside it is lit too). Its surface is `surface`, a Sphere of the scene (which outlives the
// light). From outside it is sampled uniformly within the cone it subtends, from inside uniformly
// by area.
class SphereLight final : public Light {
public:
    SphereLight(const Sphere& surface, const Color& radiance);

    LightSample sample(const Vec3& p, const Vec2& u) const override;
    bool isDelta() const override { return false; }
    float pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const override;
    Color power(float sceneRadius) const override;

    const Sphere& surface() const { return surface_; }
    const Color& radiance() const { return radiance_; }

private:
    // 1 - cos(theta_max) of the cone the sphere subtends from p, where p is outside it.
    double oneMinusCosConeAngle(const Vec3& p) const;
    // The density of directions sampled uniformly within that cone: 1 / (2 pi (1 - cos)).
    float coneDensity(const Vec3& p) const;
    float surfaceArea() const;

    const Sphere& surface_;
    Color radiance_;
};

}  // namespace lancer
