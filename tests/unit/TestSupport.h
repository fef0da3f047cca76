#pragma once

// Helpers shared by the unit tests: seeded random geometry and extended-precision references.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "geometry/Csg.h"
#include "geometry/Hit.h"
#include "math/Vec3.h"

namespace lancer::test {

// Extended precision (80-bit on x86-64) for reference values that float results are checked
// against: far more precise than the double arithmetic inside the code under test.
using Vec3L = Vec3T<long double>;

inline Vec3L toLong(const Vec3& v) {
    return Vec3L(v);
}

// The roots t0 <= t1 of |origin + t direction - center| = radius, in extended precision, or
// nothing when the line misses the sphere.
inline std::optional<std::pair<long double, long double>> sphereRoots(const Ray& ray,
                                                                      const Vec3& center,
                                                                      float radius) {
    const Vec3L o = toLong(ray.origin) - toLong(center);
    const Vec3L d = toLong(ray.direction);
    const long double r = radius;
    const long double a = dot(d, d);
    const long double halfB = dot(o, d);
    const Vec3L toLine = o - (halfB / a) * d;  // the closest point of the line to the centre
    const long double discriminant = a * (r * r - dot(toLine, toLine));
    if (discriminant < 0) return std::nullopt;
    const long double q = -(halfB + std::copysign(std::sqrt(discriminant), halfB));
    const long double c = dot(o, o) - r * r;
    const long double t0 = q / a, t1 = q != 0 ? c / q : t0;
    return std::minmax(t0, t1);
}

// Where the ray meets the plane through `point` with normal `normal` (not necessarily unit).
inline long double planeRoot(const Ray& ray, const Vec3L& point, const Vec3L& normal) {
    return dot(normal, point - toLong(ray.origin)) / dot(normal, toLong(ray.direction));
}

inline Vec3L pointOnRay(const Ray& ray, long double t) {
    return toLong(ray.origin) + t * toLong(ray.direction);
}

// A scene moved away from the origin and rescaled: intersection and ray spawning must work
// the same for every placement (a scene scaled by 1e-3 or 1e4 renders the same picture).
struct SceneFrame {
    const char* name;
    float scale;
    Vec3 offset;

    Vec3 place(const Vec3& p) const { return offset + scale * p; }
};

inline void PrintTo(const SceneFrame& frame, std::ostream* out) {
    *out << frame.name;
}

inline const SceneFrame kSceneFrames[] = {
    {"Unit", 1, Vec3(0, 0, 0)},
    {"Offset1e4", 1, Vec3(1e4f, -1e4f, 1e4f)},
    {"Scale1em3", 1e-3f, Vec3(0, 0, 0)},
    {"Scale1e4", 1e4f, Vec3(0, 0, 0)},
    {"Scale1em3Offset1", 1e-3f, Vec3(1, 1, -1)},
};

inline std::string frameName(const testing::TestParamInfo<SceneFrame>& info) {
    return info.param.name;
}

// A seeded random source, so that every run of a test sees the same cases.
class Random {
public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}

    double uniform(double lo = 0, double hi = 1) {
        return std::uniform_real_distribution<double>(lo, hi)(engine_);
    }
    // Uniform on the unit sphere (the normalized vector is rounded to float afterwards).
    Vec3 unitVector() {
        const double z = uniform(-1, 1);
        const double phi = uniform(0, 2 * 3.14159265358979323846);
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        return Vec3(Vec3d(r * std::cos(phi), r * std::sin(phi), z));
    }
    // Uniform over the hemisphere around `n` (dot > 0), or the opposite one.
    Vec3 unitVectorOnSide(const Vec3& n, bool sameSide) {
        for (;;) {
            const Vec3 w = unitVector();
            const float c = dot(w, n);
            if (c == 0) continue;
            return (c > 0) == sameSide ? w : -w;
        }
    }
    Vec3 pointInBox(float halfSize) {
        return Vec3(Vec3d(uniform(-halfSize, halfSize), uniform(-halfSize, halfSize),
                          uniform(-halfSize, halfSize)));
    }

private:
    std::mt19937_64 engine_;
};

// True when every component of `p` is within `bound` of the reference point.
inline ::testing::AssertionResult isWithinErrorBound(const Vec3& p, const Vec3L& reference,
                                                     const Vec3& bound) {
    for (int i = 0; i < 3; ++i) {
        const long double error = std::fabs(static_cast<long double>(p[i]) - reference[i]);
        if (!(error <= static_cast<long double>(bound[i])))
            return ::testing::AssertionFailure()
                   << "component " << i << ": computed " << p[i] << ", reference "
                   << static_cast<double>(reference[i]) << ", error " << static_cast<double>(error)
                   << " exceeds the bound " << bound[i];
    }
    return ::testing::AssertionSuccess();
}

// A hit record holding recognisable values, to check that a miss leaves it untouched.
inline Hit untouchedHit() {
    Hit hit;
    hit.t = 123;
    hit.p = Vec3(4, 5, 6);
    return hit;
}

inline ::testing::AssertionResult isUntouched(const Hit& hit) {
    if (hit.t == 123 && hit.p == Vec3(4, 5, 6) && hit.shape == nullptr)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "a miss changed the hit record (t = " << hit.t << ")";
}

inline ::testing::AssertionResult isFiniteHit(const Hit& hit) {
    if (std::isfinite(hit.t) && isFinite(hit.p) && isFinite(hit.pError) && isFinite(hit.ng) &&
        isFinite(hit.ns) && std::isfinite(hit.uv().x) && std::isfinite(hit.uv().y))
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "the hit record holds a NaN or an infinity (t = " << hit.t << ")";
}

template <typename T>
std::string describe(const Vec3T<T>& v) {
    return "(" + std::to_string(static_cast<double>(v.x)) + ", " +
           std::to_string(static_cast<double>(v.y)) + ", " +
           std::to_string(static_cast<double>(v.z)) + ")";
}

// Vectors compare component by component within an absolute tolerance.
template <typename T>
::testing::AssertionResult isNear(const Vec3T<T>& actual, const Vec3T<T>& expected,
                                  double tolerance) {
    for (int i = 0; i < 3; ++i)
        if (!(std::fabs(static_cast<double>(actual[i]) - static_cast<double>(expected[i])) <=
              tolerance))
            return ::testing::AssertionFailure() << describe(actual) << " is not within "
                                                 << tolerance << " of " << describe(expected);
    return ::testing::AssertionSuccess();
}

// The CSG of two solids, with the given material.
inline std::unique_ptr<Csg> combine(Csg::Operation operation, std::unique_ptr<Shape> a,
                                    std::unique_ptr<Shape> b, const Material* material) {
    std::vector<std::unique_ptr<Shape>> children;
    children.push_back(std::move(a));
    children.push_back(std::move(b));
    return std::make_unique<Csg>(operation, std::move(children), material);
}

#define EXPECT_VEC3_NEAR(actual, expected, tolerance) \
    EXPECT_TRUE(::lancer::test::isNear((actual), (expected), (tolerance)))

}  // namespace lancer::test
