#include "scene/PerspectiveCamera.h"

#include <cmath>

#include "sampling/Sampling.h"
#include "util/Parameters.h"

namespace lancer {

PerspectiveCamera::PerspectiveCamera(const CameraFrame& frame, float vfovDegrees, float aperture,
                                     float focusDistance)
    : Camera(frame),
      vfovDegrees_(vfovDegrees),
      tanHalfVfov_(std::tan(radians(vfovDegrees) / 2)),
      aperture_(aperture),
      focusDistance_(focusDistance) {}

std::vector<std::string> PerspectiveCamera::keys() {
    return {"vfov", "aperture", "focus_distance"};
}

std::unique_ptr<Camera> PerspectiveCamera::create(const Parameters& parameters,
                                                  const CameraFrame& frame) {
    float vfov = 40;
    if (parameters.has("vfov")) {
        vfov = parameters.numberAbove("vfov", 0, false);
        if (vfov >= 180) parameters.fail("vfov", "\"vfov\" must be below 180 degrees");
    }
    const float aperture =
        parameters.has("aperture") ? parameters.numberAbove("aperture", 0, true) : 0;
    const float focusDistance = parameters.has("focus_distance")
                                    ? parameters.numberAbove("focus_distance", 0, false)
                                    : frame.distanceToLookAt();
    return std::make_unique<PerspectiveCamera>(frame, vfov, aperture, focusDistance);
}

std::optional<Ray> PerspectiveCamera::generateRay(float px, float py, int width, int height,
                                                  const Vec2& lensSample) const {
    const CameraFrame& f = frame();
    const float tanHalfHfov = tanHalfVfov_ * static_cast<float>(width) / static_cast<float>(height);
    const float sx = (2 * px / static_cast<float>(width) - 1) * tanHalfHfov;
    const float sy = (1 - 2 * py / static_cast<float>(height)) * tanHalfVfov_;
    const Vec3 direction = normalize(sx * f.u + sy * f.v - f.w);
    if (aperture_ <= 0) return Ray{f.position, direction};

    // Thin lens: start anywhere on the lens disc, aim where the pinhole ray meets the focal plane.
    const Vec3 focusPoint = f.position + (focusDistance_ / dot(direction, -f.w)) * direction;
    const Vec2 lens = aperture_ * sampleUniformDiskConcentric(lensSample);
    const Vec3 origin = f.position + lens.x * f.u + lens.y * f.v;
    return Ray{origin, normalize(focusPoint - origin)};
}

RayCone PerspectiveCamera::pixelCone(int, int height) const {
    return {0, 2 * tanHalfVfov_ / static_cast<float>(height)};
}

std::unique_ptr<Camera> PerspectiveCamera::orbited(const CameraFrame& frame,
                                                   float distanceScale) const {
    return std::make_unique<PerspectiveCamera>(frame, vfovDegrees_, aperture_,
                                               focusDistance_ * distanceScale);
}

}  // namespace lancer
