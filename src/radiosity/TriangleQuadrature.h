#pragma once

#include <array>

#include "math/Vec3.h"

namespace lancer {

// The three points of a triangle where the solve evaluates form factors and light: the
// quadrature rule of degree 2 (exact for quadratics) with its points inside the triangle, at
// barycentric (2/3, 1/6, 1/6), halfway from the centroid to each corner: away from the edges
// that neighbours and contact lines share. Each point has weight 1/3.
template <class T>
constexpr std::array<Vec3T<T>, 3> triangleQuadraturePoints(const std::array<Vec3T<T>, 3>& t) {
    constexpr T kNear = T(4) / 6, kFar = T(1) / 6;
    return {kNear * t[0] + kFar * (t[1] + t[2]), kNear * t[1] + kFar * (t[2] + t[0]),
            kNear * t[2] + kFar * (t[0] + t[1])};
}

}  // namespace lancer
