#pragma once

#include <string>
#include <vector>

#include "scene/Camera.h"

namespace lancer {

class Parameters;

// Parallel rays along -w from the plane through the position: a view `height` scene units high
// (and as wide as the image's aspect ratio makes it), where distance changes no size.
class OrthographicCamera final : public Camera {
public:
    OrthographicCamera(const CameraFrame& frame, float height);

    static std::vector<std::string> keys();
    static std::unique_ptr<Camera> create(const Parameters& parameters, const CameraFrame& frame);

    std::optional<Ray> generateRay(float px, float py, int width, int height,
                                   const Vec2& lensSample) const override;
    // A pixel's width in scene units, which no distance widens.
    RayCone pixelCone(int width, int height) const override;
    // Nearer is a smaller view, as a perspective camera's at look_at would be.
    std::unique_ptr<Camera> orbited(const CameraFrame& frame, float distanceScale) const override;

    float height() const { return height_; }

private:
    float height_;
};

}  // namespace lancer
