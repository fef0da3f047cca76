#pragma once

#include <string>
#include <vector>

#include "scene/Camera.h"

namespace lancer {

class Parameters;

// The contract's camera: a pinhole, or a thin lens when aperture > 0.
class PerspectiveCamera final : public Camera {
public:
    PerspectiveCamera(const CameraFrame& frame, float vfovDegrees, float aperture = 0,
                      float focusDistance = 1);

    static std::vector<std::string> keys();
    static std::unique_ptr<Camera> create(const Parameters& parameters, const CameraFrame& frame);

    std::optional<Ray> generateRay(float px, float py, int width, int height,
                                   const Vec2& lensSample) const override;
    bool usesLensSample() const override { return aperture_ > 0; }
    // The angle between the rays through neighbouring pixel centres near the image centre.
    RayCone pixelCone(int width, int height) const override;
    std::unique_ptr<Camera> orbited(const CameraFrame& frame, float distanceScale) const override;

    float vfovDegrees() const { return vfovDegrees_; }
    float aperture() const { return aperture_; }
    float focusDistance() const { return focusDistance_; }

private:
    float vfovDegrees_;
    float tanHalfVfov_;
    float aperture_;
    float focusDistance_;
};

}  // namespace lancer
