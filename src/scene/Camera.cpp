#include "scene/Camera.h"

#include <cmath>

#include "sampling/Sampling.h"

namespace lancer {

Camera::Camera(const Vec3& position, const Vec3& lookAt, const Vec3& up, float vfovDegrees,
               float aperture, float focusDistance)
    : position_(position),
      lookAt_(lookAt),
      up_(up),
      vfovDegrees_(vfovDegrees),
      w_(normalize(position - lookAt)),
      tanHalfVfov_(std::tan(radians(vfovDegrees) / 2)),
      aperture_(aperture),
      focusDistance_(focusDistance) {
    u_ = normalize(cross(up, w_));
    v_ = cross(w_, u_);
}

Ray Camera::generateRay(float px, float py, int width, int height, const Vec2& lensSample) const {
    const float tanHalfHfov = tanHalfVfov_ * static_cast<float>(width) / static_cast<float>(height);
    const float sx = (2 * px / static_cast<float>(width) - 1) * tanHalfHfov;
    const float sy = (1 - 2 * py / static_cast<float>(height)) * tanHalfVfov_;
    const Vec3 direction = normalize(sx * u_ + sy * v_ - w_);
    if (aperture_ <= 0) return {position_, direction};

    // Thin lens: start anywhere on the lens disc, aim where the pinhole ray meets the focal plane.
    const Vec3 focusPoint = position_ + (focusDistance_ / dot(direction, -w_)) * direction;
    const Vec2 lens = aperture_ * sampleUniformDiskConcentric(lensSample);
    const Vec3 origin = position_ + lens.x * u_ + lens.y * v_;
    return {origin, normalize(focusPoint - origin)};
}

}  // namespace lancer
