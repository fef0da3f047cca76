#pragma once

#include "math/Ray.h"
#include "math/Vec2.h"

namespace lancer {

// The scene format's camera: a pinhole, or a thin lens when aperture > 0. It does not know the
// image size; each ray is asked for with it, so the same camera serves any resolution.
class Camera {
public:
    Camera() = default;
    Camera(const Vec3& position, const Vec3& lookAt, const Vec3& up, float vfovDegrees,
           float aperture = 0, float focusDistance = 1);

    // The ray through image point (px, py) of a width x height image, in pixel units from the
    // top-left corner, y downwards. lensSample in [0,1)^2 picks the point on the lens.
    Ray generateRay(float px, float py, int width, int height, const Vec2& lensSample) const;

    // The angle between the rays through neighbouring pixel centres, near the image centre: how
    // fast a pixel's footprint grows with distance, for texture filtering.
    float pixelSpreadAngle(int height) const {
        return 2 * tanHalfVfov_ / static_cast<float>(height);
    }

    // The parameters it was made from, to make a moved copy (the window's orbit).
    const Vec3& position() const { return position_; }
    const Vec3& lookAt() const { return lookAt_; }
    const Vec3& up() const { return up_; }
    float vfovDegrees() const { return vfovDegrees_; }
    float aperture() const { return aperture_; }
    float focusDistance() const { return focusDistance_; }

private:
    Vec3 position_;
    Vec3 lookAt_;
    Vec3 up_{0, 1, 0};
    float vfovDegrees_ = 90;
    Vec3 u_, v_, w_;  // right, up, and backwards (w points from the scene towards the camera)
    float tanHalfVfov_ = 1;
    float aperture_ = 0;
    float focusDistance_ = 1;
};

}  // namespace lancer
