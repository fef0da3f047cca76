#pragma once

#include "math/Vec3.h"

namespace lancer {

// Where a camera stands and where it looks, with the orthonormal frame every camera type
// builds its rays in: u to the right, v up, w backwards (from the scene towards the camera).
struct CameraFrame {
    Vec3 position;
    Vec3 lookAt;
    Vec3 up{0, 1, 0};
    Vec3 u, v, w;

    CameraFrame() = default;
    CameraFrame(const Vec3& position_, const Vec3& lookAt_, const Vec3& up_)
        : position(position_), lookAt(lookAt_), up(up_), w(normalize(position_ - lookAt_)) {
        u = normalize(cross(up_, w));
        v = cross(w, u);
    }

    float distanceToLookAt() const { return length(position - lookAt); }
    // A direction given in the frame's (u, v, w) coordinates, in world space.
    Vec3 toWorld(const Vec3& local) const { return local.x * u + local.y * v + local.z * w; }
};

}  // namespace lancer
