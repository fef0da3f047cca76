#pragma once

#include "math/Color.h"
#include "math/Vec3.h"

namespace lancer {

// A direction drawn from a BSDF (or one of its lobes) for a given outgoing direction wo.
struct BsdfSample {
    Vec3 wi;        // unit incident direction (where light comes from)
    Color f;        // the BSDF's value for (wo, wi); for a delta lobe, its weight / |cos theta_i|
    float pdf = 0;  // solid-angle density of wi; for a delta lobe, the probability of choosing it
    bool isDelta = false;
    // eta^2 of a refraction (index beyond the surface over index before it, squared), else 1:
    // radiance is compressed by 1/eta^2 entering a denser medium (Russian roulette undoes it).
    float etaSquared = 1;
};

}  // namespace lancer
