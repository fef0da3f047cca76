#pragma once

#include <optional>

#include "math/Ray.h"
#include "math/Vec3.h"

namespace lancer {

// Where a ray crosses the plane through `origin` with normal n (any length), with 0 < t < tMax:
// the flat shapes' common first step. In double precision: the sign of t must be exact for a ray
// spawned just off the surface, and the point is projected back onto the plane, so that what
// remains is the rounding to float.
struct PlaneCrossing {
    double t;
    Vec3d offset;  // the point crossed, relative to `origin`, in the plane

    static std::optional<PlaneCrossing> find(const Ray& ray, const Vec3d& origin, const Vec3d& n,
                                             float tMax) {
        const Vec3d d(ray.direction);
        const double denominator = dot(n, d);
        if (denominator == 0) return std::nullopt;  // parallel: never meets the plane
        const Vec3d o(ray.origin);
        const double t = dot(n, origin - o) / denominator;
        if (!(t > 0 && t < tMax)) return std::nullopt;
        return at(ray, origin, n, t);
    }

    // The crossing at a t that find() returned.
    static PlaneCrossing at(const Ray& ray, const Vec3d& origin, const Vec3d& n, double t) {
        Vec3d q = Vec3d(ray.origin) + t * Vec3d(ray.direction) - origin;
        q -= (dot(n, q) / dot(n, n)) * n;
        return PlaneCrossing{t, q};
    }
};

}  // namespace lancer
