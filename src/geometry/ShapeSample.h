#pragma once

#include "math/Vec3.h"

namespace lancer {

// A point picked on a shape's surface.
struct ShapeSample {
    Vec3 p;     // the point
    Vec3 n;     // the unit geometric normal there, on the shape's front (outside) side
    float pdf;  // its density: per unit area, or per unit solid angle seen from a reference point
};

}  // namespace lancer
