#pragma once

#include "math/Vec3.h"

namespace lancer {

// An orthonormal basis (s, t, n): carries directions between world space and a local space in
// which n is the z axis, where BSDFs are simplest to write (cos theta = w.z).
struct Frame {
    Vec3 s, t, n;

    // A basis whose z axis is the unit vector n.
    static Frame fromZ(const Vec3& n) {
        Frame frame;
        frame.n = n;
        coordinateSystem(n, frame.s, frame.t);
        return frame;
    }

    Vec3 toLocal(const Vec3& w) const { return {dot(w, s), dot(w, t), dot(w, n)}; }
    Vec3 toWorld(const Vec3& w) const { return w.x * s + w.y * t + w.z * n; }
};

}  // namespace lancer
