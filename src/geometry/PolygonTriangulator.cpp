#include "geometry/PolygonTriangulator.h"

namespace lancer {

namespace {

struct Point2 {
    double x = 0, y = 0;
    bool operator==(const Point2&) const = default;
};

// Twice the signed area of the triangle abc: positive when it turns counter-clockwise.
double orientation(const Point2& a, const Point2& b, const Point2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Inside or on the border of the counter-clockwise triangle abc.
bool inTriangle(const Point2& a, const Point2& b, const Point2& c, const Point2& p) {
    return orientation(a, b, p) >= 0 && orientation(b, c, p) >= 0 && orientation(c, a, p) >= 0;
}

// The corners of a polygon in the plane it (nearly) lies in, turning counter-clockwise: projected
// along the largest component of its Newell normal.
std::vector<Point2> projectPolygon(std::span<const Vec3> corners) {
    Vec3d normal;
    for (std::size_t i = 0; i < corners.size(); ++i)
        normal += cross(Vec3d(corners[i]), Vec3d(corners[(i + 1) % corners.size()]));
    const int axis = maxDimension(normal);
    const double flip = normal[axis] < 0 ? -1 : 1;
    std::vector<Point2> points;
    points.reserve(corners.size());
    for (const Vec3& c : corners)
        points.push_back({double(c[(axis + 1) % 3]), flip * double(c[(axis + 2) % 3])});
    return points;
}

}  // namespace

void PolygonTriangulator::triangulate(std::span<const Vec3> corners,
                                      std::vector<CornerTriple>& triangles) {
    const std::size_t n = corners.size();
    triangles.clear();
    if (n == 3) {
        triangles.push_back({0, 1, 2});
        return;
    }
    const std::vector<Point2> p = projectPolygon(corners);
    std::vector<std::size_t> prev(n), next(n);
    for (std::size_t i = 0; i < n; ++i) {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    // The corner b between a and c is an ear when it is convex and no reflex corner lies in abc
    // (a convex corner inside abc would come with a reflex one).
    const auto isEar = [&](std::size_t a, std::size_t b, std::size_t c) {
        if (orientation(p[a], p[b], p[c]) <= 0) return false;
        for (std::size_t i = next[c]; i != a; i = next[i]) {
            if (p[i] == p[a] || p[i] == p[b] || p[i] == p[c]) continue;
            if (inTriangle(p[a], p[b], p[c], p[i]) &&
                orientation(p[prev[i]], p[i], p[next[i]]) <= 0)
                return false;
        }
        return true;
    };
    triangles.reserve(n - 2);
    std::size_t remaining = n, corner = 0, failures = 0;
    while (remaining > 3) {
        const std::size_t a = prev[corner], c = next[corner];
        // After a whole round without an ear the polygon is not simple: clip anyway, so that
        // the loop ends.
        if (failures >= remaining || isEar(a, corner, c)) {
            triangles.push_back({a, corner, c});
            next[a] = c;
            prev[c] = a;
            --remaining;
            failures = 0;
        } else {
            ++failures;
        }
        corner = c;
    }
    triangles.push_back({prev[corner], corner, next[corner]});
}

}  // namespace lancer
