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
        const std::optional<double> t = lineParameter(ray, origin, n);
        if (!t || !(*t > 0 && *t < tMax)) return std::nullopt;
        return at(ray, origin, n, *t);
    }

    // Where the ray's whole line crosses the plane (t of either sign); nothing when parallel.
    static std::optional<double> lineParameter(const Ray& ray, const Vec3d& origin,
                                               const Vec3d& n) {
        const double denominator = dot(n, Vec3d(ray.direction));
        if (denominator == 0) return std::nullopt;  // parallel: never meets the plane
        return dot(n, origin - Vec3d(ray.origin)) / denominator;
    }

    // The crossing at a t that find() or lineParameter() returned.
    static PlaneCrossing at(const Ray& ray, const Vec3d& origin, const Vec3d& n, double t) {
        Vec3d q = Vec3d(ray.origin) + t * Vec3d(ray.direction) - origin;
        q -= (dot(n, q) / dot(n, n)) * n;
        return PlaneCrossing{t, q};
    }
};

}  // namespace lancer
