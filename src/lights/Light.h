#pragma once

#include "math/Color.h"
#include "math/Vec2.h"
#include "math/Vec3.h"

namespace lancer {

// What a light delivers to a point: from which direction, how much, and from where.
struct LightSample {
    Vec3 wi;           // unit direction from the point towards the light
    Color irradiance;  // E_l: irradiance on a surface facing the light, before occlusion
    Vec3 position;     // the point on the light (meaningless when atInfinity)
    bool atInfinity = false;
};

// A light source, sampled from a point being shaded.
class Light {
public:
    virtual ~Light() = default;

    // A sample of the light as seen from p; u in [0,1)^2 picks a point on lights with an extent.
    virtual LightSample sample(const Vec3& p, const Vec2& u) const = 0;

    // A delta light (a point or a direction) is one sample exactly: u is ignored.
    virtual bool isDelta() const = 0;
};

}  // namespace lancer
