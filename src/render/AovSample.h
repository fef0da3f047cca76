#pragma once

#include "math/Color.h"
#include "math/Vec3.h"

namespace lancer {

// What a camera ray finds for the auxiliary outputs (--aov): the diffuse colour of the first
// surface that is not a mirror or glass, the shading normal of the first hit (towards the
// camera) and its distance; all zero where the ray finds nothing.
struct AovSample {
    Color albedo;
    Vec3 normal;
    float depth = 0;
};

}  // namespace lancer
