#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/TessellationRequest.h"
#include "math/Bounds3.h"
#include "math/Vec3.h"

namespace lancer {

// A shape's surface as flat triangles (for radiosity), each counter-clockwise seen from the
// shape's front, with the primitive it belongs to.
struct Tessellation {
    struct Facet {
        std::array<Vec3, 3> corners;
        std::uint32_t primitive;
    };
    std::vector<Facet> facets;
    // Whether the facets only approximate a curved surface (chords of a sphere): points on them
    // are then moved onto the true surface, which lies within probeDistance of them.
    bool curved = false;
    float probeDistance = 0;
};

}  // namespace lancer
