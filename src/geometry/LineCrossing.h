#pragma once

#include <vector>

#include "geometry/SurfaceCrossing.h"

namespace lancer {

// Where the whole line of a ray (t of either sign) crosses the surface of a solid, and whether
// it enters the solid there (going the way of the ray) or leaves it: what CSG combines.
struct LineCrossing {
    SurfaceCrossing crossing;
    bool entering;
};

using LineCrossings = std::vector<LineCrossing>;

}  // namespace lancer
