#pragma once

#include "math/Color.h"
#include "math/Vec3.h"

namespace lancer {

// What a light delivers to a point: from which direction, how much, and from where.
struct LightSample {
    Vec3 wi;           // unit direction from the point towards the light
    Color irradiance;  // E_l: irradiance on a surface facing the light, before occlusion. For a
                       // light with an extent, the one-sample estimate radiance / pdf.
    Vec3 position;     // the point on the light (meaningless when atInfinity)
    bool atInfinity = false;
    float pdf = 0;  // solid-angle density of wi as seen from the point; 0 for delta lights
};

}  // namespace lancer
