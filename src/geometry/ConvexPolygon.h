#pragma once

#include <span>
#include <vector>

#include "math/Vec3.h"

namespace lancer {

// The part of a convex polygon where dot(normal, x) >= offset (one Sutherland-Hodgman step): clips
// infinite planes to the scene's box.
inline std::vector<Vec3d> clipPolygon(std::span<const Vec3d> polygon, const Vec3d& normal,
                                      double offset) {
    std::vector<Vec3d> clipped;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3d& a = polygon[i];
        const Vec3d& b = polygon[(i + 1) % n];
        const double da = dot(normal, a) - offset;
        const double db = dot(normal, b) - offset;
        if (da >= 0) clipped.push_back(a);
        if ((da >= 0) != (db >= 0)) clipped.push_back(a + (da / (da - db)) * (b - a));
    }
    return clipped.size() >= 3 ? clipped : std::vector<Vec3d>{};
}

}  // namespace lancer
