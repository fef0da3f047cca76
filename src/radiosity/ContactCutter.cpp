#include "radiosity/ContactCutter.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/ConvexPolygon.h"

namespace lancer {

namespace {

// At most this many cells along an axis: an edge as long as the scene (a clipped plane's) is
// filed in at most this squared cells.
constexpr int kMaxResolution = 64;

// Whether the segment ab reaches more than `tolerance` into the convex polygon (counter-clockwise
// about n), clipped to the polygon shrunk by `tolerance` (Liang-Barsky): an edge running along
// the polygon's side, or only touching it, does not cross it.
bool crossesInterior(const std::vector<Vec3d>& polygon, const Vec3d& n, const Vec3d& a,
                     const Vec3d& b, double tolerance) {
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

}  // namespace

ContactCutter::ContactCutter(std::vector<Edge> edges, float tolerance)
    : edges_(std::move(edges)), tolerance_(tolerance) {
    for (const Edge& e : edges_)
        gridBox_ = merge(merge(gridBox_, e.a), e.b);
    if (edges_.empty()) return;
    gridBox_ = Bounds3(gridBox_.min - Vec3(tolerance_), gridBox_.max + Vec3(tolerance_));
    // About one edge per cell.
    const int side = std::clamp(static_cast<int>(std::cbrt(static_cast<double>(edges_.size()))), 1,
                                kMaxResolution);
    for (int i = 0; i < 3; ++i) {
        resolution_[i] = side;
        cellsPerUnit_[i] = static_cast<float>(side) / std::max(gridBox_.diagonal()[i], 1e-30f);
    }
    // Each edge is filed in the cells its box (widened by the tolerance) overlaps: counted, then
    // placed, so that the cells' lists are one array.
    cellStart_.assign(static_cast<std::size_t>(side) * side * side + 1, 0);
    const auto forEachCell = [&](const Edge& e, auto&& visit) {
        const Bounds3 box(min(e.a, e.b) - Vec3(tolerance_), max(e.a, e.b) + Vec3(tolerance_));
        const std::array<int, 3> lo = cellOf(box.min), hi = cellOf(box.max);
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x)
                    visit((static_cast<std::size_t>(z) * side + y) * side + x);
    };
    for (const Edge& e : edges_)
        forEachCell(e, [&](std::size_t cell) { ++cellStart_[cell + 1]; });
    for (std::size_t c = 1; c < cellStart_.size(); ++c)
        cellStart_[c] += cellStart_[c - 1];
    cellEdges_.resize(cellStart_.back());
    std::vector<std::uint32_t> filled(cellStart_.begin(), cellStart_.end() - 1);
    for (std::uint32_t i = 0; i < edges_.size(); ++i)
        forEachCell(edges_[i], [&](std::size_t cell) { cellEdges_[filled[cell]++] = i; });
}

std::array<int, 3> ContactCutter::cellOf(const Vec3& p) const {
    std::array<int, 3> cell{};
    for (int i = 0; i < 3; ++i)
        cell[i] = std::clamp(static_cast<int>((p[i] - gridBox_.min[i]) * cellsPerUnit_[i]), 0,
                             resolution_[i] - 1);
    return cell;
}

std::vector<std::uint32_t> ContactCutter::edgesNear(const Bounds3& box) const {
    std::vector<std::uint32_t> near;
    if (edges_.empty()) return near;
    const std::array<int, 3> lo = cellOf(box.min), hi = cellOf(box.max);
    for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y)
            for (int x = lo[0]; x <= hi[0]; ++x) {
                const std::size_t cell =
                    (static_cast<std::size_t>(z) * resolution_[1] + y) * resolution_[0] + x;
                near.insert(near.end(), cellEdges_.begin() + cellStart_[cell],
                            cellEdges_.begin() + cellStart_[cell + 1]);
            }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    return near;
}

ContactCutter::Pieces ContactCutter::cut(const std::array<Vec3, 3>& triangle) const {
    const Vec3d p0(triangle[0]);
    Vec3d n = cross(Vec3d(triangle[1]) - p0, Vec3d(triangle[2]) - p0);
    const double doubleArea = length(n);
    if (!(doubleArea > 0)) return {};
    n = n / doubleArea;
    const Bounds3 box = merge(Bounds3(triangle[0], triangle[1]), triangle[2]);
    const double tolerance = tolerance_;
    Pieces pieces;
    pieces.polygons = {{p0, Vec3d(triangle[1]), Vec3d(triangle[2])}};
    for (const std::uint32_t i : edgesNear(box)) {
        const Edge& edge = edges_[i];
        const Vec3d a(edge.a), b(edge.b);
        if (std::abs(dot(a - p0, n)) > tolerance || std::abs(dot(b - p0, n)) > tolerance) continue;
        // The edge's line in the plane, as the plane through it perpendicular to the triangle.
        const Vec3d across = cross(n, b - a);
        const double acrossLength = length(across);
        if (!(acrossLength > tolerance)) continue;
        const Vec3d side = across / acrossLength;
        const double offset = dot(side, a);
        // Only the pieces the edge crosses are split: the line stops where the edge's pieces do.
        std::vector<std::vector<Vec3d>> next;
        for (std::vector<Vec3d>& polygon : pieces.polygons) {
            if (crossesInterior(polygon, n, a, b, tolerance)) {
                std::vector<Vec3d> left = withoutRepeats(clipPolygon(polygon, side, offset));
                std::vector<Vec3d> right = withoutRepeats(clipPolygon(polygon, -side, -offset));
                if (left.size() >= 3 && right.size() >= 3) {
                    next.push_back(std::move(left));
                    next.push_back(std::move(right));
                    pieces.reach = std::max(pieces.reach, edge.reach);
                    continue;
                }
            }
            next.push_back(std::move(polygon));
        }
        pieces.polygons = std::move(next);
    }
    if (pieces.polygons.size() == 1) return {};
    return pieces;
}

}  // namespace lancer
