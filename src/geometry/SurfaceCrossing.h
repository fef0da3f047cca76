#pragma once

#include <cstdint>
#include <vector>

namespace lancer {

// Where a ray crosses a shape's surface, as the first phase of an intersection finds it: enough
// to compare crossings and for the shape to build the complete record of the nearest one.
struct SurfaceCrossing {
    double t;                      // along the ray that was tested
    double tShape;                 // along the ray in the shape's own space (an instance's)
    std::uint32_t primitive = 0;   // which primitive was crossed
    float b0 = 0, b1 = 0, b2 = 0;  // the shape's own numbers there (a triangle's barycentrics)
};

using SurfaceCrossings = std::vector<SurfaceCrossing>;

}  // namespace lancer
