#pragma once

#include <memory>
#include <optional>

#include "math/Ray.h"
#include "math/RayCone.h"
#include "math/Vec2.h"
#include "scene/CameraFrame.h"

namespace lancer {

// The scene's camera: from an image point to the ray that sees it. Each type (perspective,
// orthographic, fisheye, lat-long) is a class of its own, made by name from the scene loader's
// table. A camera does not know the image size; each ray is asked for with it, so the same
// camera serves any resolution.
class Camera {
public:
    explicit Camera(const CameraFrame& frame) : frame_(frame) {}
    virtual ~Camera() = default;

    // The ray through image point (px, py) of a width x height image, in pixel units from the
    // top-left corner, y downwards; none where the image shows nothing (outside a fisheye's
    // circle). lensSample in [0,1)^2 picks the point on a lens.
    virtual std::optional<Ray> generateRay(float px, float py, int width, int height,
                                           const Vec2& lensSample) const = 0;
    // Whether generateRay reads lensSample (a thin lens); for the others it is not drawn.
    virtual bool usesLensSample() const { return false; }

    // How a pixel's footprint starts and grows along its rays, for texture filtering.
    virtual RayCone pixelCone(int width, int height) const = 0;

    // This camera's type seen from `frame`, whose distance to look_at is `distanceScale` times
    // this one's: what depends on that distance (a lens's focus, an orthographic view's height)
    // scales with it. The window's orbit moves the camera this way.
    virtual std::unique_ptr<Camera> orbited(const CameraFrame& frame,
                                            float distanceScale) const = 0;

    const CameraFrame& frame() const { return frame_; }
    const Vec3& position() const { return frame_.position; }
    const Vec3& lookAt() const { return frame_.lookAt; }
    const Vec3& up() const { return frame_.up; }

private:
    CameraFrame frame_;
};

}  // namespace lancer
