#pragma once

#include <string>
#include <vector>

#include "scene/Camera.h"

namespace lancer {

class Parameters;

// An equidistant (angular) fisheye: the circle inscribed in the image sees `fov` degrees across
// (up to 360), the angle from the view direction growing in proportion to the distance from the
// image centre. Outside the circle there is no ray: black.
class FisheyeCamera final : public Camera {
public:
    FisheyeCamera(const CameraFrame& frame, float fovDegrees);

    static std::vector<std::string> keys();
    static std::unique_ptr<Camera> create(const Parameters& parameters, const CameraFrame& frame);

    std::optional<Ray> generateRay(float px, float py, int width, int height,
                                   const Vec2& lensSample) const override;
    // The angle between neighbouring pixels along a radius (the same everywhere; across a radius
    // it is sin(theta) / theta of that, so away from the centre textures are filtered a little
    // more than needed).
    RayCone pixelCone(int width, int height) const override;
    std::unique_ptr<Camera> orbited(const CameraFrame& frame, float distanceScale) const override;

    float fovDegrees() const { return fovDegrees_; }

private:
    float fovDegrees_;
};

}  // namespace lancer
