#pragma once

namespace lancer {

// Where a ray meets a triangle: barycentric coordinates of vertices 0, 1, 2 and the ray's t.
struct TriangleIntersection {
    float b0, b1, b2;
    float t;
};

}  // namespace lancer
