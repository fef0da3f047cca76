#pragma once

#include <cstdint>

#include "math/Vec3.h"

namespace lancer {

// Four triangles side by side, for testing them together: vertex[i][axis][lane] is coordinate
// `axis` of vertex i of the lane's triangle, so that one row holds a coordinate of all four and
// the row of an axis known only at run time is one aligned load.
struct alignas(16) TrianglePack {
    static constexpr int kLanes = 4;

    float vertex[3][3][kLanes];
    std::uint32_t triangle[kLanes];  // which triangle each lane holds, in the owner's numbering

    void set(int lane, const Vec3& v0, const Vec3& v1, const Vec3& v2) {
        const Vec3* corners[3] = {&v0, &v1, &v2};
        for (int i = 0; i < 3; ++i)
            for (int axis = 0; axis < 3; ++axis)
                vertex[i][axis][lane] = (*corners[i])[axis];
    }
};

}  // namespace lancer
