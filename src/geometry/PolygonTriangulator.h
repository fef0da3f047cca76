#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "math/Vec3.h"

namespace lancer {

// Cuts the faces of polygon meshes (as OBJ files write them) into triangles.
class PolygonTriangulator {
public:
    // A triangle given by three indices into the polygon's corners.
    using CornerTriple = std::array<std::size_t, 3>;

    // Splits a polygon, convex or not, into triangles by ear clipping; the triangles keep the
    // polygon's winding. Holes joined to the outline by a two-way bridge edge (as some exporters
    // write them) work: a corner's duplicate does not block an ear. A self-intersecting or
    // degenerate polygon, which has no proper triangulation, still gives n - 2 triangles. They
    // replace what `triangles` held, in its storage: a loader that keeps one vector for all its
    // faces allocates nothing per triangle or quad once the vector has grown.
    static void triangulate(std::span<const Vec3> corners, std::vector<CornerTriple>& triangles);
};

}  // namespace lancer
