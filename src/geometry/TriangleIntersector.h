#pragma once

#include <cstdint>
#include <optional>

#include "geometry/PackHits.h"
#include "geometry/TriangleIntersection.h"
#include "geometry/TrianglePack.h"
#include "math/Float.h"
#include "math/Float4.h"
#include "math/Ray.h"
#include "math/Vec3.h"

namespace lancer {

// Watertight ray/triangle intersection (Woop, Benthin and Wald 2013, in pbrt's formulation): the
// triangle is moved into a frame where the ray starts at the origin and runs along +z, so that
// the test reduces to the signs of three 2D edge functions, which agree exactly along a shared
// edge. The t > 0 test is made conservative with a bound on the error of the computed t.
//
// What depends on the ray alone (the axis permutation and the shear) is computed once per ray,
// and four triangles are tested at once, each lane rounding exactly as the scalar test would:
// Triangle::intersect is this test on one lane.
class TriangleIntersector {
public:
    explicit TriangleIntersector(const Ray& ray) {
        // Permute so that the ray's largest component is z, then shear.
        kz_ = maxDimension(ray.direction);
        kx_ = (kz_ + 1) % 3;
        ky_ = (kx_ + 1) % 3;
        const Vec3 d = permute(ray.direction, kx_, ky_, kz_);
        canHit_ = d.z != 0;
        originX_ = Float4(ray.origin[kx_]);
        originY_ = Float4(ray.origin[ky_]);
        originZ_ = Float4(ray.origin[kz_]);
        shearX_ = Float4(-d.x / d.z);
        shearY_ = Float4(-d.y / d.z);
        shearZ_ = Float4(1.0f / d.z);
    }

    // False for a zero direction, which hits nothing.
    bool canHit() const { return canHit_; }

    // The lanes among `lanes` (a bit mask) that the ray hits with 0 < t < tMax, with their t and
    // barycentrics. Requires canHit().
    LANCER_ALWAYS_INLINE PackHits intersect(const TrianglePack& pack, int lanes, float tMax) const {
        PackHits hits;
        hits.lanes = 0;
        // Translate to the ray origin, in the permuted frame, then shear x and y; z is left in
        // world units for now.
        Float4 x[3], y[3], z[3];
        for (int i = 0; i < 3; ++i) {
            x[i] = Float4::load(pack.vertex[i][kx_]) - originX_;
            y[i] = Float4::load(pack.vertex[i][ky_]) - originY_;
            z[i] = Float4::load(pack.vertex[i][kz_]) - originZ_;
            x[i] = x[i] + shearX_ * z[i];
            y[i] = y[i] + shearY_ * z[i];
        }

        Float4 e[3] = {edgeFunction(x[1], y[1], x[2], y[2]), edgeFunction(x[2], y[2], x[0], y[0]),
                       edgeFunction(x[0], y[0], x[1], y[1])};
        const Float4 zero(0.0f);
        if (const int exactlyZero = (eq(e[0], zero) | eq(e[1], zero) | eq(e[2], zero)) & lanes)
            recomputeInDouble(exactlyZero, x, y, e);
        const int someNegative = lt(e[0], zero) | lt(e[1], zero) | lt(e[2], zero);
        const int somePositive = gt(e[0], zero) | gt(e[1], zero) | gt(e[2], zero);
        lanes &= ~(someNegative & somePositive);
        const Float4 det = e[0] + e[1] + e[2];
        lanes &= ne(det, zero);  // degenerate triangle, or a ray in its plane
        if (lanes == 0) return hits;

        // The rounding error of the sheared x and y grows with z in world units (the shear
        // factors are at most 1), so its bound takes z before it is scaled to ray units below.
        const Float4 maxZWorld = maxAbs(z);

        // t, still scaled by det; compared against the range without dividing.
        for (Float4& zi : z)
            zi = zi * shearZ_;
        const Float4 tScaled = e[0] * z[0] + e[1] * z[1] + e[2] * z[2];
        const Float4 tMaxScaled = Float4(tMax) * det;
        const int negative = lt(det, zero), positive = gt(det, zero);
        lanes &= ~(negative & (ge(tScaled, zero) | lt(tScaled, tMaxScaled)));
        lanes &= ~(positive & (le(tScaled, zero) | gt(tScaled, tMaxScaled)));
        if (lanes == 0) return hits;

        const Float4 invDet = Float4(1.0f) / det;
        const Float4 t = tScaled * invDet;
        lanes &= lt(t, Float4(tMax));

        // Reject t that is not certainly positive given the rounding errors above (pbrt 6.8.4).
        const Float4 maxZ = maxAbs(z), maxX = maxAbs(x), maxY = maxAbs(y);
        const Float4 deltaZ = Float4(gamma(3)) * maxZ;
        const Float4 deltaX = Float4(gamma(5)) * (maxX + maxZWorld);
        const Float4 deltaY = Float4(gamma(5)) * (maxY + maxZWorld);
        const Float4 deltaE =
            Float4(2.0f) * (Float4(gamma(2)) * maxX * maxY + deltaY * maxX + deltaX * maxY);
        const Float4 maxE = maxAbs(e);
        const Float4 deltaT = Float4(3.0f) *
                              (Float4(gamma(3)) * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) *
                              abs(invDet);
        lanes &= gt(t, deltaT);

        hits.lanes = lanes;
        t.store(hits.t);
        (e[0] * invDet).store(hits.b0);
        (e[1] * invDet).store(hits.b1);
        (e[2] * invDet).store(hits.b2);
        return hits;
    }

    // One triangle.
    std::optional<TriangleIntersection> intersect(const Vec3& v0, const Vec3& v1, const Vec3& v2,
                                                  float tMax) const {
        TrianglePack pack{};
        pack.set(0, v0, v1, v2);
        const PackHits hits = intersect(pack, 1, tMax);
        if (hits.lanes == 0) return std::nullopt;
        return hits.at(0);
    }

private:
    // The 2D edge function a.x * b.y - a.y * b.x.
    static Float4 edgeFunction(Float4 ax, Float4 ay, Float4 bx, Float4 by) {
        return ax * by - ay * bx;
    }

    // The edge functions of the given lanes recomputed in double, where float rounded them to
    // exactly zero: that is what makes the test watertight on shared edges (Woop et al. 2013).
    static void recomputeInDouble(int lanes, const Float4 (&x)[3], const Float4 (&y)[3],
                                  Float4 (&e)[3]);

    // maxComponent(abs(Vec3(v[0], v[1], v[2]))), lane by lane.
    static Float4 maxAbs(const Float4 (&v)[3]) { return max(abs(v[0]), max(abs(v[1]), abs(v[2]))); }

    int kx_, ky_, kz_;
    bool canHit_;
    Float4 originX_, originY_, originZ_;  // the ray origin, permuted
    Float4 shearX_, shearY_, shearZ_;
};

}  // namespace lancer
