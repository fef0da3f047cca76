#pragma once

#include "math/Color.h"

namespace lancer {

// How a delta lobe shares the light it scatters between the mirror direction and, for a
// refracting lobe, the direction refracted with index ratio eta: Whitted's recursive rays.
struct SpecularSplit {
    Color reflected;
    Color refracted;
    float eta = 1;  // index beyond the surface over index on the viewer's side
};

}  // namespace lancer
