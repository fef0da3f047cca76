#pragma once

#include "math/Float.h"
#include "math/Ray.h"
#include "math/Vec3.h"

namespace lancer {

// An axis-aligned box. The default box is empty (min > max), the neutral element of merge.
struct Bounds3 {
    Vec3 min{kInfinity, kInfinity, kInfinity};
    Vec3 max{-kInfinity, -kInfinity, -kInfinity};

    constexpr Bounds3() = default;
    constexpr Bounds3(const Vec3& a, const Vec3& b)
        : min(lancer::min(a, b)), max(lancer::max(a, b)) {}
    constexpr explicit Bounds3(const Vec3& p) : min(p), max(p) {}

    constexpr bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    constexpr Vec3 diagonal() const { return max - min; }
    constexpr Vec3 centroid() const { return 0.5f * (min + max); }
    constexpr float surfaceArea() const {
        if (isEmpty()) return 0;
        const Vec3 d = diagonal();
        return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
    // Position of p in the box, 0 at min and 1 at max, per axis.
    constexpr Vec3 offset(const Vec3& p) const {
        Vec3 o = p - min;
        for (int i = 0; i < 3; ++i)
            if (max[i] > min[i]) o[i] /= max[i] - min[i];
        return o;
    }
    constexpr bool contains(const Vec3& p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
               p.z <= max.z;
    }
    constexpr int maxExtentAxis() const { return maxDimension(diagonal()); }
};

constexpr Bounds3 merge(const Bounds3& a, const Bounds3& b) {
    Bounds3 r;
    r.min = min(a.min, b.min);
    r.max = max(a.max, b.max);
    return r;
}
constexpr Bounds3 merge(const Bounds3& a, const Vec3& p) {
    Bounds3 r;
    r.min = min(a.min, p);
    r.max = max(a.max, p);
    return r;
}

}  // namespace lancer
