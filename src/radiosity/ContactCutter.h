#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "math/Bounds3.h"
#include "math/Vec3.h"

namespace lancer {

// Cuts surfaces along the contact lines of the objects standing on them. Where an object
// stands on a surface, the edges of its facets along its base lie in the surface's plane (or, if
// it is sunk a little into it, its facets cross the plane): an element straddling that line
// averages the lit surface with the dark footprint, so light leaks under the object and the
// element's form factors add up to more than one. The cutter keeps every facet of the scene in a
// uniform grid, finds the segments where they meet a polygon's plane (their edges lying in it,
// or their sections by it) that cross its interior, and splits the polygon along them into
// convex pieces, each wholly inside or wholly outside the footprint. Whether a polygon is cut at
// all, and how far the cutting shapes reach, is found without making the pieces.
class ContactCutter {
public:
    // A facet, with the size of the shape it belongs to (how far above the surface the shape's
    // inside can reach).
    struct Facet {
        std::array<Vec3, 3> corners;
        float reach;
    };
    // Convex pieces of a polygon, counter-clockwise like it; `reach` is the largest of the
    // reaches of the facets that cut the polygon (a segment of theirs crosses its interior: all
    // the facets along one line count, not only the first to cut along it).
    struct Pieces {
        std::vector<std::vector<Vec3d>> polygons;
        float reach = 0;
    };

    // `tolerance`: how far from a plane a corner may be for it to lie in the plane, and how far
    // inside a polygon a segment must reach to cross it.
    ContactCutter(std::vector<Facet> facets, float tolerance);

    // A convex polygon (counter-clockwise about its unit normal) cut along the segments where the
    // facets meet its plane, those that cross its interior: no polygons when none does.
    Pieces cut(std::span<const Vec3d> polygon, const Vec3d& normal) const;
    // The largest reach of the facets that cut the polygon, as `cut` gives it but without making
    // the pieces: nothing where `cut` gives no polygons.
    std::optional<float> cuttingReach(std::span<const Vec3d> polygon, const Vec3d& normal) const;

private:
    // Calls visit(a, b, reach) for each segment ab where a facet near a polygon meets its plane,
    // with the facet's reach.
    template <typename Visit>
    void forEachSegmentInPlaneOf(std::span<const Vec3d> polygon, const Vec3d& normal,
                                 Visit&& visit) const;
    // The facets whose boxes may overlap `box`, each once, in increasing order.
    std::vector<std::uint32_t> facetsNear(const Bounds3& box) const;
    // The grid cell holding p along each axis, clamped to the grid.
    std::array<int, 3> cellOf(const Vec3& p) const;

    std::vector<Facet> facets_;
    float tolerance_;
    Bounds3 gridBox_;
    std::array<int, 3> resolution_{1, 1, 1};
    Vec3 cellsPerUnit_;
    // The facets of cell c are cellFacets_[cellStart_[c] .. cellStart_[c + 1]).
    std::vector<std::uint32_t> cellStart_;
    std::vector<std::uint32_t> cellFacets_;
};

}  // namespace lancer
