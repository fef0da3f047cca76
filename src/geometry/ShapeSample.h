#pragma once

#include "math/Vec3.h"

namespace lancer {

// A point picked on a shape's surface.
struct ShapeSample {
    Vec3 p;     // the point
    Vec3 n;     // the unit geometric normal there, on the shape's front (outside) side
    float pdf;  // its density: per unit area, or per unit solid angle seen from a reference point
};

// A point of a shape sampled as seen from a reference point: the point, with its density per unit
// solid angle, and the unit direction from the reference point to it (which a light's sample
// needs too: worked out once).
struct DirectionSample {
    ShapeSample at;
    Vec3 wi;
};

}  // namespace lancer
