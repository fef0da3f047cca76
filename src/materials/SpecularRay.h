#pragma once

#include "math/Color.h"
#include "math/Vec3.h"

namespace lancer {

// A ray that Whitted traces from a hit, and the weight of the radiance it brings back.
struct SpecularRay {
    Vec3 direction;  // unit, away from the surface
    Color weight;
};

}  // namespace lancer
