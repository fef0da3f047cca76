#pragma once

#include <cmath>
#include <cstdint>

#include "math/Float.h"
#include "math/Ray.h"
#include "math/Vec2.h"
#include "math/Vec3.h"

namespace lancer {

class Material;
class Shape;

// The intersection record: where a ray met a surface, and what a shader needs to know about it.
struct Hit {
    float t = kInfinity;  // ray parameter of the hit
    Vec3 p;               // the hit point
    Vec3 pError;          // per-component error bound of p; it bounds p's distance from the
                          // surface (what offsetting spawned rays needs), not its drift along it
    Vec3 ng;              // unit geometric normal on the shape's true side (outside / front)
    Vec3 ns;              // unit shading normal, in the same hemisphere as ng
    Vec3 dpdu, dpdv;      // how p moves with u and with v along the surface
    // How uv changes from this pixel to the next one right (x) and down (y): the footprint that
    // texture filtering averages over. Zero when unknown (point sampling).
    float dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
    // The shape of the scene that was hit: an instance rather than the shape it places.
    const Shape* shape = nullptr;
    // Which triangle of a mesh was hit (0 for shapes that are one primitive): with `shape`, it
    // names an emissive face's light.
    std::uint32_t primitive = 0;
    const Material* material = nullptr;

    // The record of a point found in double precision and rounded to float, p (whose error is
    // then within gamma(2) |p|), with the same geometric and shading normal n: the analytic
    // shapes' start. The rest of the record is theirs to set.
    static Hit atRoundedPoint(double t, const Vec3& p, const Vec3& n) {
        Hit hit;
        hit.t = static_cast<float>(t);
        hit.p = p;
        hit.pError = gamma(2) * abs(p);
        hit.ng = n;
        hit.ns = n;
        return hit;
    }

    // Sets the uv footprint from the footprint of a pixel on the surface, dpdx and dpdy (how p
    // moves from pixel to pixel), by solving dpdx = dudx dpdu + dvdx dpdv in the least-squares
    // sense (the two sides need not be exactly coplanar), and likewise for y.
    void setUvFootprint(const Vec3& dpdx, const Vec3& dpdy) {
        const float a00 = dot(dpdu, dpdu), a01 = dot(dpdu, dpdv), a11 = dot(dpdv, dpdv);
        const float det = a00 * a11 - a01 * a01;
        if (!(std::abs(det) > 0)) return;
        const float invDet = 1 / det;
        const auto solve = [&](const Vec3& dp, float& du, float& dv) {
            const float b0 = dot(dpdu, dp), b1 = dot(dpdv, dp);
            // Far beyond any texture's size: a footprint that large is as blurred as it gets.
            constexpr float kLimit = 1e8f;
            du = clamp((a11 * b0 - a01 * b1) * invDet, -kLimit, kLimit);
            dv = clamp((a00 * b1 - a01 * b0) * invDet, -kLimit, kLimit);
        };
        solve(dpdx, dudx, dvdx);
        solve(dpdy, dudy, dvdy);
    }

    // The surface coordinates, for textures.
    Vec2 uv() const;
    void setUv(const Vec2& uv) {
        uv_ = uv;
        uvShape_ = nullptr;
    }
    // Leaves the surface coordinates to owner->uvAt(local), worked out only if uv() is asked:
    // for shapes whose uv costs trigonometry (spheres, disks, cones), which most hits'
    // materials never read (nothing is textured on them). `local` is whatever point of its own
    // the shape needs; outer shapes (instances, csg) pass the record on with it untouched. Like
    // `shape` and `material`, it needs the shape to outlive the record.
    void deferUv(const Shape* owner, const Vec3& local) {
        uvShape_ = owner;
        uvLocal_ = local;
    }

    // True when the ray arrived from the side ng points to.
    bool frontFace(const Ray& ray) const { return dot(ray.direction, ng) < 0; }
    // True when the ray meets the side the surface emits from, if its material emits: its front,
    // or either side of a shape that emits on both (Shape::emitsOnBothSides).
    bool seesEmittingSide(const Ray& ray) const;

    // A ray leaving the surface in direction `dir`.
    Ray spawnRay(const Vec3& dir) const { return {offsetRayOrigin(p, pError, ng, dir), dir}; }

    // A ray leaving the surface towards `target`, which it reaches at t = 1.
    Ray spawnRayTo(const Vec3& target) const {
        const Vec3 origin = offsetRayOrigin(p, pError, ng, target - p);
        return {origin, target - origin};
    }

private:
    Vec2 uv_;
    const Shape* uvShape_ = nullptr;  // set when uv is deferred
    Vec3 uvLocal_;
};

// Rays towards a point stop this short of it (as a fraction of the segment), so that a light
// sitting on a surface is not shadowed by that surface.
constexpr float kShadowEpsilon = 1e-4f;

}  // namespace lancer
