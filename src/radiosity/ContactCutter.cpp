#include "radiosity/ContactCutter.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <utility>

#include "geometry/ConvexPolygon.h"

namespace lancer {

namespace {

// At most this many cells along an axis: a facet as large as the scene (a clipped plane's) is
// filed in at most this cubed cells.
constexpr int kMaxResolution = 128;

// Whether the segment ab reaches more than `tolerance` into the convex polygon (counter-clockwise
// about n), clipped to the polygon shrunk by `tolerance` (Liang-Barsky): an edge running along
// the polygon's side, or only touching it, does not cross it.
bool crossesInterior(std::span<const Vec3d> polygon, const Vec3d& n, const Vec3d& a, const Vec3d& b,
                     double tolerance) {
    double t0 = 0, t1 = 1;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec3d& p = polygon[i];
        const Vec3d inward = cross(n, polygon[(i + 1) % polygon.size()] - p);
        const double sideLength = length(inward);
        if (!(sideLength > 0)) continue;
        const double da = dot(inward, a - p) / sideLength - tolerance;
        const double db = dot(inward, b - p) / sideLength - tolerance;
        if (da < 0 && db < 0) return false;
        if (da < 0)
            t0 = std::max(t0, da / (da - db));
        else if (db < 0)
            t1 = std::min(t1, da / (da - db));
    }
    return (t1 - t0) * length(b - a) > tolerance;
}

// The polygon without the corners that repeat the one before them (a clip through a corner
// gives it twice).
std::vector<Vec3d> withoutRepeats(std::vector<Vec3d> polygon) {
    std::vector<Vec3d> kept;
    for (const Vec3d& p : polygon)
        if (kept.empty() || !(p == kept.back())) kept.push_back(p);
    while (kept.size() > 1 && kept.front() == kept.back())
        kept.pop_back();
    return kept;
}

// Calls visit(a, b) for the segments ab where a facet meets the plane through p0 of unit normal n:
// its edges, if it lies in the plane; else the part of it within `tolerance` of the plane, if that
// is a segment (an edge lying in the plane, or the facet's section by the plane when it crosses
// it).
template <typename Visit>
void forEachSegmentInPlane(const std::array<Vec3, 3>& facet, const Vec3d& p0, const Vec3d& n,
                           double tolerance, Visit&& visit) {
    std::array<Vec3d, 3> corners;
    std::array<double, 3> height;
    for (int k = 0; k < 3; ++k) {
        corners[k] = Vec3d(facet[k]);
        height[k] = dot(corners[k] - p0, n);
    }
    const auto inPlane = [&](int k) { return std::abs(height[k]) <= tolerance; };
    if (inPlane(0) && inPlane(1) && inPlane(2)) {
        for (int k = 0; k < 3; ++k)
            visit(corners[k], corners[(k + 1) % 3]);
        return;
    }
    // Corners in the plane and crossings of edges from one side to the other: two make a segment.
    std::array<Vec3d, 3> points;
    int found = 0;
    for (int k = 0; k < 3; ++k) {
        const int next = (k + 1) % 3;
        if (inPlane(k)) points[found++] = corners[k];
        if (!inPlane(k) && !inPlane(next) && (height[k] > 0) != (height[next] > 0))
            points[found++] = corners[k] + (height[k] / (height[k] - height[next])) *
                                               (corners[next] - corners[k]);
    }
    if (found == 2) visit(points[0], points[1]);
}

// The parts of a convex polygon on either side of a line.
using Sides = std::array<std::vector<Vec3d>, 2>;

// The parts of a convex polygon (counter-clockwise about n) on either side of the line of the
// segment ab: nothing if the segment is no longer than the tolerance in the plane, or the line
// leaves one side empty.
std::optional<Sides> sidesOfLine(std::span<const Vec3d> polygon, const Vec3d& n, const Vec3d& a,
                                 const Vec3d& b, double tolerance) {
    // The segment's line in the plane, as the plane through it perpendicular to the polygon.
    const Vec3d across = cross(n, b - a);
    const double acrossLength = length(across);
    if (!(acrossLength > tolerance)) return std::nullopt;
    const Vec3d side = across / acrossLength;
    const double offset = dot(side, a);
    std::vector<Vec3d> left = withoutRepeats(clipPolygon(polygon, side, offset));
    std::vector<Vec3d> right = withoutRepeats(clipPolygon(polygon, -side, -offset));
    if (left.size() < 3 || right.size() < 3) return std::nullopt;
    return Sides{std::move(left), std::move(right)};
}

// The parts of a convex polygon on either side of the line of the segment ab: nothing when the
// segment does not cross its interior, which a cut along it then leaves whole. (Apart from
// sidesOfLine so that the usual answer, no crossing, is found inline.)
std::optional<Sides> splitAlong(std::span<const Vec3d> polygon, const Vec3d& n, const Vec3d& a,
                                const Vec3d& b, double tolerance) {
    if (!crossesInterior(polygon, n, a, b, tolerance)) return std::nullopt;
    return sidesOfLine(polygon, n, a, b, tolerance);
}

// Splits the pieces that the segment ab crosses along its line. Only those pieces: the line stops
// where the pieces the segment crosses do.
void cutAlong(std::vector<std::vector<Vec3d>>& pieces, const Vec3d& n, const Vec3d& a,
              const Vec3d& b, double tolerance) {
    std::vector<std::vector<Vec3d>> next;
    for (std::vector<Vec3d>& polygon : pieces) {
        if (auto sides = splitAlong(polygon, n, a, b, tolerance)) {
            next.push_back(std::move((*sides)[0]));
            next.push_back(std::move((*sides)[1]));
        } else {
            next.push_back(std::move(polygon));
        }
    }
    pieces = std::move(next);
}

// Whether a segment ab of a facet reaching `facetReach` makes `reach`, the largest reach of the
// facets found to cut the polygon so far (nothing before the first), larger: it cuts the polygon
// and its facet reaches further.
bool reachesFurther(const std::optional<float>& reach, float facetReach,
                    std::span<const Vec3d> polygon, const Vec3d& n, const Vec3d& a, const Vec3d& b,
                    double tolerance) {
    return (!reach || facetReach > *reach) && splitAlong(polygon, n, a, b, tolerance);
}

}  // namespace

ContactCutter::ContactCutter(std::vector<Facet> facets, float tolerance)
    : facets_(std::move(facets)), tolerance_(tolerance) {
    for (const Facet& f : facets_)
        for (const Vec3& p : f.corners)
            gridBox_ = merge(gridBox_, p);
    if (facets_.empty()) return;
    gridBox_ = Bounds3(gridBox_.min - Vec3(tolerance_), gridBox_.max + Vec3(tolerance_));
    // About one facet per 8 cells: a model's facets fill a small part of the room's box.
    const int side = std::clamp(
        static_cast<int>(2 * std::cbrt(static_cast<double>(facets_.size()))), 1, kMaxResolution);
    for (int i = 0; i < 3; ++i) {
        resolution_[i] = side;
        cellsPerUnit_[i] = static_cast<float>(side) / std::max(gridBox_.diagonal()[i], 1e-30f);
    }
    // Each facet is filed in the cells its box (widened by the tolerance) overlaps: counted, then
    // placed, so that the cells' lists are one array.
    cellStart_.assign(static_cast<std::size_t>(side) * side * side + 1, 0);
    const auto forEachCell = [&](const Facet& f, auto&& visit) {
        const Bounds3 box = merge(Bounds3(f.corners[0], f.corners[1]), f.corners[2]);
        const std::array<int, 3> lo = cellOf(box.min - Vec3(tolerance_)),
                                 hi = cellOf(box.max + Vec3(tolerance_));
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x)
                    visit((static_cast<std::size_t>(z) * side + y) * side + x);
    };
    for (const Facet& f : facets_)
        forEachCell(f, [&](std::size_t cell) { ++cellStart_[cell + 1]; });
    for (std::size_t c = 1; c < cellStart_.size(); ++c)
        cellStart_[c] += cellStart_[c - 1];
    cellFacets_.resize(cellStart_.back());
    std::vector<std::uint32_t> filled(cellStart_.begin(), cellStart_.end() - 1);
    for (std::uint32_t i = 0; i < facets_.size(); ++i)
        forEachCell(facets_[i], [&](std::size_t cell) { cellFacets_[filled[cell]++] = i; });
}

std::array<int, 3> ContactCutter::cellOf(const Vec3& p) const {
    std::array<int, 3> cell{};
    for (int i = 0; i < 3; ++i)
        cell[i] = std::clamp(static_cast<int>((p[i] - gridBox_.min[i]) * cellsPerUnit_[i]), 0,
                             resolution_[i] - 1);
    return cell;
}

std::vector<std::uint32_t> ContactCutter::facetsNear(const Bounds3& box) const {
    std::vector<std::uint32_t> near;
    if (facets_.empty()) return near;
    const std::array<int, 3> lo = cellOf(box.min), hi = cellOf(box.max);
    for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y)
            for (int x = lo[0]; x <= hi[0]; ++x) {
                const std::size_t cell =
                    (static_cast<std::size_t>(z) * resolution_[1] + y) * resolution_[0] + x;
                near.insert(near.end(), cellFacets_.begin() + cellStart_[cell],
                            cellFacets_.begin() + cellStart_[cell + 1]);
            }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    return near;
}

template <typename Visit>
void ContactCutter::forEachSegmentInPlaneOf(std::span<const Vec3d> polygon, const Vec3d& normal,
                                            Visit&& visit) const {
    Bounds3 box;
    for (const Vec3d& p : polygon)
        box = merge(box, Vec3(p));
    for (const std::uint32_t i : facetsNear(box))
        forEachSegmentInPlane(
            facets_[i].corners, polygon[0], normal, tolerance_,
            [&](const Vec3d& a, const Vec3d& b) { visit(a, b, facets_[i].reach); });
}

std::optional<float> ContactCutter::cuttingReach(std::span<const Vec3d> polygon,
                                                 const Vec3d& normal) const {
    std::optional<float> reach;
    forEachSegmentInPlaneOf(polygon, normal, [&](const Vec3d& a, const Vec3d& b, float facetReach) {
        if (reachesFurther(reach, facetReach, polygon, normal, a, b, tolerance_))
            reach = facetReach;
    });
    return reach;
}

ContactCutter::Pieces ContactCutter::cut(std::span<const Vec3d> polygon,
                                         const Vec3d& normal) const {
    std::optional<float> reach;
    // No pieces until a segment cuts the polygon (most never are); it is whole until then, so
    // that segment splits it: there are at least two pieces.
    std::vector<std::vector<Vec3d>> pieces;
    forEachSegmentInPlaneOf(polygon, normal, [&](const Vec3d& a, const Vec3d& b, float facetReach) {
        if (reachesFurther(reach, facetReach, polygon, normal, a, b, tolerance_))
            reach = facetReach;
        if (!reach) return;
        if (pieces.empty()) pieces = {std::vector<Vec3d>(polygon.begin(), polygon.end())};
        cutAlong(pieces, normal, a, b, tolerance_);
    });
    if (!reach) return {};
    return {std::move(pieces), *reach};
}

}  // namespace lancer
