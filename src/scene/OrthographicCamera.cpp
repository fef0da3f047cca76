#include "scene/OrthographicCamera.h"

#include "util/Parameters.h"

namespace lancer {

OrthographicCamera::OrthographicCamera(const CameraFrame& frame, float height)
    : Camera(frame), height_(height) {}

std::vector<std::string> OrthographicCamera::keys() {
    return {"height", "aperture"};
}

std::unique_ptr<Camera> OrthographicCamera::create(const Parameters& parameters,
                                                   const CameraFrame& frame) {
    // "aperture": 0 is accepted, so that a perspective scene can switch type without an edit.
    if (parameters.has("aperture") && parameters.numberAbove("aperture", 0, true) > 0)
        parameters.fail("aperture",
                        "\"aperture\" must be 0 for an orthographic camera (it has no lens)");
    return std::make_unique<OrthographicCamera>(frame, parameters.numberAbove("height", 0, false));
}

std::optional<Ray> OrthographicCamera::generateRay(float px, float py, int width, int height,
                                                   const Vec2&) const {
    const CameraFrame& f = frame();
    const float halfHeight = height_ / 2;
    const float halfWidth = halfHeight * static_cast<float>(width) / static_cast<float>(height);
    const float sx = (2 * px / static_cast<float>(width) - 1) * halfWidth;
    const float sy = (1 - 2 * py / static_cast<float>(height)) * halfHeight;
    return Ray{f.position + sx * f.u + sy * f.v, -f.w};
}

RayCone OrthographicCamera::pixelCone(int, int height) const {
    return {height_ / static_cast<float>(height), 0};
}

std::unique_ptr<Camera> OrthographicCamera::orbited(const CameraFrame& frame,
                                                    float distanceScale) const {
    return std::make_unique<OrthographicCamera>(frame, height_ * distanceScale);
}

}  // namespace lancer
