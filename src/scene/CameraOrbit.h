#pragma once

#include <memory>

#include "scene/Camera.h"

namespace lancer {

// Moves a camera on a sphere around its look_at point, as the window's mouse does: turning
// around the up axis, tilting towards it (stopping short of straight up or down), and moving
// nearer or farther. The moved camera is of the original's type and keeps its up and its other
// keys but those that depend on the distance to look_at, which scale with it (a lens's focus
// distance, so that what was in focus stays in focus; an orthographic view's height).
class CameraOrbit {
public:
    explicit CameraOrbit(const Camera& original);

    // Turns by `yaw` radians around the up axis through look_at (positive: counter-clockwise seen
    // from above) and tilts by `pitch` radians (positive: the camera rises).
    void rotate(float yaw, float pitch);
    // Multiplies the distance to look_at by `factor` (below 1: nearer), within 1/100 to 100
    // times the original distance.
    void zoom(float factor);

    std::unique_ptr<Camera> camera() const;

private:
    std::unique_ptr<Camera> original_;
    Vec3 up_, front_, side_;  // an orthonormal frame: the up axis, and two horizontal directions
    float distance_;          // from look_at, originally
    float yaw_ = 0;           // from front_, around up_
    float pitch_;             // elevation above the horizontal plane
    float distanceScale_ = 1;
};

}  // namespace lancer
