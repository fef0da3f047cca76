#pragma once

#include <string>
#include <vector>

#include "scene/Camera.h"

namespace lancer {

class Parameters;

// A 360 x 180 degree panorama in the environment map's latitude-longitude layout, in the
// camera's frame: the image centre looks along -w, the top row along v, so that a render from
// a camera looking along -z with up +y is an environment map of what it sees.
class LatLongCamera final : public Camera {
public:
    explicit LatLongCamera(const CameraFrame& frame) : Camera(frame) {}

    static std::vector<std::string> keys() { return {}; }
    static std::unique_ptr<Camera> create(const Parameters& parameters, const CameraFrame& frame);

    std::optional<Ray> generateRay(float px, float py, int width, int height,
                                   const Vec2& lensSample) const override;
    // The angle between neighbouring rows (across, rows are sin(theta) as far apart as at the
    // equator, so near the poles textures are filtered more than needed).
    RayCone pixelCone(int width, int height) const override;
    std::unique_ptr<Camera> orbited(const CameraFrame& frame, float distanceScale) const override;
};

}  // namespace lancer
