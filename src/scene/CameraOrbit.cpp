#include "scene/CameraOrbit.h"

#include <algorithm>
#include <cmath>

#include "math/Float.h"

namespace lancer {

namespace {

// Short of the poles, where the view direction would be parallel to up.
constexpr float kMaxPitch = radians(89);
constexpr float kMinDistanceScale = 0.01f, kMaxDistanceScale = 100;

}  // namespace

CameraOrbit::CameraOrbit(const Camera& original)
    : original_(original.orbited(original.frame(), 1)) {
    const Vec3 offset = original.position() - original.lookAt();
    distance_ = length(offset);
    up_ = normalize(original.up());
    // The camera rejects an up parallel to the viewing direction, so offset has a horizontal part.
    front_ = normalize(offset - dot(offset, up_) * up_);
    side_ = cross(up_, front_);
    pitch_ = std::asin(clamp(dot(offset, up_) / distance_, -1.0f, 1.0f));
}

void CameraOrbit::rotate(float yaw, float pitch) {
    yaw_ += yaw;
    pitch_ = clamp(pitch_ + pitch, -kMaxPitch, kMaxPitch);
}

void CameraOrbit::zoom(float factor) {
    distanceScale_ = clamp(distanceScale_ * factor, kMinDistanceScale, kMaxDistanceScale);
}

std::unique_ptr<Camera> CameraOrbit::camera() const {
    const Vec3 direction = std::cos(pitch_) * (std::cos(yaw_) * front_ + std::sin(yaw_) * side_) +
                           std::sin(pitch_) * up_;
    const Vec3& lookAt = original_->lookAt();
    return original_->orbited(
        CameraFrame(lookAt + (distance_ * distanceScale_) * direction, lookAt, original_->up()),
        distanceScale_);
}

}  // namespace lancer
