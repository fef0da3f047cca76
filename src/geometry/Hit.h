#pragma once

#include "geometry/Ray.h"
#include "math/Vec2.h"
#include "math/Vec3.h"

namespace lancer {

class Shape;

// The intersection record: where a ray met a surface, and what a shader needs to know about it.
struct Hit {
    float t = kInfinity;  // ray parameter of the hit
    Vec3 p;               // the hit point
    Vec3 pError;          // bound on the absolute error of p, per component
    Vec3 ng;              // unit geometric normal on the shape's true side (outside / front)
    Vec3 ns;              // unit shading normal, in the same hemisphere as ng
    Vec2 uv;              // surface coordinates, for textures
    const Shape* shape = nullptr;

    // True when the ray arrived from the side ng points to.
    bool frontFace(const Ray& ray) const { return dot(ray.direction, ng) < 0; }

    // A ray leaving the surface in direction `dir`.
    Ray spawnRay(const Vec3& dir) const { return {offsetRayOrigin(p, pError, ng, dir), dir}; }

    // A ray leaving the surface towards `target`, which it reaches at t = 1.
    Ray spawnRayTo(const Vec3& target) const {
        const Vec3 origin = offsetRayOrigin(p, pError, ng, target - p);
        return {origin, target - origin};
    }
};

// Rays towards a point stop this short of it (as a fraction of the segment), so that a light
// sitting on a surface is not shadowed by that surface.
constexpr float kShadowEpsilon = 1e-4f;

}  // namespace lancer
