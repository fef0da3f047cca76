#pragma once

#include "math/Float.h"
#include "math/Vec3.h"

namespace lancer {

// A half-line origin + t * direction, t >= 0. The direction need not be unit length: a shadow
// ray towards a point uses the full segment as its direction so that the point is at t = 1.
struct Ray {
    Vec3 origin;
    Vec3 direction;

    Vec3 at(float t) const { return origin + t * direction; }
};

// Moves a computed surface point p, whose error is bounded by pError component-wise, off the
// surface along the geometric normal n, to the side that direction w leaves towards, far enough
// that a ray spawned there cannot find the surface it starts on again (pbrt's error-bounded
// offset, used instead of a scene-scale-dependent epsilon).
LANCER_ALWAYS_INLINE Vec3 offsetRayOrigin(const Vec3& p, const Vec3& pError, const Vec3& n,
                                          const Vec3& w) {
    const float d = dot(abs(n), pError);
    Vec3 offset = d * n;
    if (dot(w, n) < 0) offset = -offset;
    Vec3 po = p + offset;
    // The addition itself rounds: push each coordinate one more ulp away from the surface.
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0)
            po[i] = nextFloatUp(po[i]);
        else if (offset[i] < 0)
            po[i] = nextFloatDown(po[i]);
    }
    return po;
}

}  // namespace lancer
