#pragma once

#include <cmath>

#include "math/Float.h"
#include "math/Vec2.h"
#include "math/Vec3.h"

namespace lancer {

// The uv of a surface of revolution about its own z axis (disk, cone) from the point its hit
// deferred: u is the angle of (x, y) around the axis in turns, from the x axis counter-clockwise;
// v is the point's z, which the shape has already made its v (a disk's radius, a cone's height).
inline Vec2 revolutionUv(const Vec3& local) {
    double phi = std::atan2(static_cast<double>(local.y), static_cast<double>(local.x));
    if (phi < 0) phi += 2 * kPi;
    return {static_cast<float>(phi / (2 * kPi)), local.z};
}

}  // namespace lancer
