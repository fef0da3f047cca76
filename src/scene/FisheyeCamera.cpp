#include "scene/FisheyeCamera.h"

#include <algorithm>
#include <cmath>

#include "math/Float.h"
#include "util/Parameters.h"

namespace lancer {

namespace {

// The radius of the circle inscribed in the image, in pixels.
float circleRadius(int width, int height) {
    return 0.5f * static_cast<float>(std::min(width, height));
}

}  // namespace

FisheyeCamera::FisheyeCamera(const CameraFrame& frame, float fovDegrees)
    : Camera(frame), fovDegrees_(fovDegrees) {}

std::vector<std::string> FisheyeCamera::keys() {
    return {"fov"};
}

std::unique_ptr<Camera> FisheyeCamera::create(const Parameters& parameters,
                                              const CameraFrame& frame) {
    float fov = 180;
    if (parameters.has("fov")) {
        fov = parameters.numberAbove("fov", 0, false);
        if (fov > 360) parameters.fail("fov", "\"fov\" must be at most 360 degrees");
    }
    return std::make_unique<FisheyeCamera>(frame, fov);
}

std::optional<Ray> FisheyeCamera::generateRay(float px, float py, int width, int height,
                                              const Vec2&) const {
    const float radius = circleRadius(width, height);
    const float x = (px - 0.5f * static_cast<float>(width)) / radius;
    const float y = (0.5f * static_cast<float>(height) - py) / radius;
    const float r = std::sqrt(x * x + y * y);
    if (r > 1) return std::nullopt;
    const float theta = r * radians(fovDegrees_) / 2;
    // sin(theta) / r tends to the half field of view in radians at the centre.
    const float sinOverR = r > 0 ? std::sin(theta) / r : radians(fovDegrees_) / 2;
    const CameraFrame& f = frame();
    return Ray{f.position,
               normalize(f.toWorld(Vec3(sinOverR * x, sinOverR * y, -std::cos(theta))))};
}

RayCone FisheyeCamera::pixelCone(int width, int height) const {
    return {0, radians(fovDegrees_) / 2 / circleRadius(width, height)};
}

std::unique_ptr<Camera> FisheyeCamera::orbited(const CameraFrame& frame, float) const {
    return std::make_unique<FisheyeCamera>(frame, fovDegrees_);
}

}  // namespace lancer
