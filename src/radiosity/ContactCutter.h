#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "math/Bounds3.h"
#include "math/Vec3.h"

namespace lancer {

// Cuts surface triangles along the contact lines of the objects standing on them. Where an object
// stands on a surface, the edges of its facets along its base lie in the surface's plane: an
// element straddling them averages the lit surface with the dark footprint, so light leaks under
// the object and the element's form factors add up to more than one. The cutter keeps every
// facet edge of the scene in a uniform grid, finds those lying in a triangle's plane and crossing
// its interior, and splits the triangle along them into convex pieces, each wholly inside or
// wholly outside the footprint.
class ContactCutter {
public:
    // A facet edge, with the size of the shape it belongs to (how far above the surface the
    // shape's inside can reach).
    struct Edge {
        Vec3 a, b;
        float reach;
    };
    // A convex piece of a triangle, counter-clockwise like it; `reach` is the largest of the
    // reaches of the edges that cut the triangle.
    struct Pieces {
        std::vector<std::vector<Vec3d>> polygons;
        float reach = 0;
    };

    // `tolerance`: how far from a plane an edge's ends may be for the edge to lie in it, and how
    // far inside a triangle an edge must reach to cross it.
    ContactCutter(std::vector<Edge> edges, float tolerance);

    // The triangle cut along the edges that lie in its plane and cross its interior: no polygons
    // when none does (the triangle is meshed as it is).
    Pieces cut(const std::array<Vec3, 3>& triangle) const;

private:
    // The edges whose boxes may overlap `box`, each once, in increasing order.
    std::vector<std::uint32_t> edgesNear(const Bounds3& box) const;
    // The grid cell holding p along each axis, clamped to the grid.
    std::array<int, 3> cellOf(const Vec3& p) const;

    std::vector<Edge> edges_;
    float tolerance_;
    Bounds3 gridBox_;
    std::array<int, 3> resolution_{1, 1, 1};
    Vec3 cellsPerUnit_;
    // The edges of cell c are cellEdges_[cellStart_[c] .. cellStart_[c + 1]).
    std::vector<std::uint32_t> cellStart_;
    std::vector<std::uint32_t> cellEdges_;
};

}  // namespace lancer
