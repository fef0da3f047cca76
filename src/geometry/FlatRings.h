#pragma once

#include <cstdint>
#include <vector>

#include "geometry/Tessellation.h"
#include "math/Vec3.h"

namespace lancer {

// The flat annulus between radii inner and outer (a full disk when inner is 0) about `center`, as
// `rings` rings of `segments` quads each (triangles about the centre of a full disk), added to
// `facets` as the given primitive. Point k of each circle lies at center + r direction(k), for
// the unit vectors direction(k), k in [0, segments), going counter-clockwise about the normal:
// shapes made of several pieces (a cone's caps and side) pass the same directions, so that the
// pieces share their rims' vertices bit for bit.
template <typename Direction>
void addFlatRings(const Vec3& center, float outer, float inner, int segments, int rings,
                  Direction&& direction, std::uint32_t primitive,
                  std::vector<Tessellation::Facet>& facets) {
    const auto at = [&](int ring, int segment) {
        const float r = ring == 0 ? outer
                                  : outer - (outer - inner) * static_cast<float>(ring) /
                                                static_cast<float>(rings);
        return center + r * direction(segment % segments);
    };
    for (int ring = 0; ring < rings; ++ring)
        for (int segment = 0; segment < segments; ++segment) {
            // Outer edge first, then inwards.
            const Vec3 o0 = at(ring, segment), o1 = at(ring, segment + 1);
            const Vec3 i0 = at(ring + 1, segment), i1 = at(ring + 1, segment + 1);
            facets.push_back({{o0, o1, i1}, primitive});
            // The innermost ring of a full disk closes on the centre: one triangle.
            if (ring + 1 < rings || inner > 0) facets.push_back({{o0, i1, i0}, primitive});
        }
}

}  // namespace lancer
