#include "scene/LatLongCamera.h"

#include <cmath>

#include "math/Float.h"

namespace lancer {

std::unique_ptr<Camera> LatLongCamera::create(const Parameters&, const CameraFrame& frame) {
    return std::make_unique<LatLongCamera>(frame);
}

std::optional<Ray> LatLongCamera::generateRay(float px, float py, int width, int height,
                                              const Vec2&) const {
    // The inverse of u = 0.5 + atan2(d.x, -d.z) / (2 pi), v = acos(d.y) / pi.
    const float phi = 2 * kPi * (px / static_cast<float>(width) - 0.5f);
    const float theta = kPi * py / static_cast<float>(height);
    const float sinTheta = std::sin(theta);
    const Vec3 local(sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi));
    return Ray{frame().position, normalize(frame().toWorld(local))};
}

RayCone LatLongCamera::pixelCone(int, int height) const {
    return {0, kPi / static_cast<float>(height)};
}

std::unique_ptr<Camera> LatLongCamera::orbited(const CameraFrame& frame, float) const {
    return std::make_unique<LatLongCamera>(frame);
}

}  // namespace lancer
