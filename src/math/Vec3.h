#pragma once

#include <algorithm>
#include <cmath>

#include "math/Float.h"

namespace lancer {

// A 3-component vector. Points, directions and normals are all Vec3: the distinction is kept by
// names, not types, as in Ray Tracing in One Weekend. Vec3d is used where an intersection routine
// needs double precision internally.
template <typename T>
struct Vec3T {
    T x = 0, y = 0, z = 0;

    constexpr Vec3T() = default;
    constexpr Vec3T(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Vec3T(T v) : x(v), y(v), z(v) {}
    template <typename U>
    constexpr explicit Vec3T(const Vec3T<U>& v)
        : x(static_cast<T>(v.x)), y(static_cast<T>(v.y)), z(static_cast<T>(v.z)) {}

    constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3T operator-() const { return {-x, -y, -z}; }
    constexpr Vec3T& operator+=(const Vec3T& b) {
        x += b.x;
        y += b.y;
        z += b.z;
        return *this;
    }
    constexpr Vec3T& operator-=(const Vec3T& b) {
        x -= b.x;
        y -= b.y;
        z -= b.z;
        return *this;
    }
    constexpr Vec3T& operator*=(T s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr Vec3T& operator/=(T s) { return *this *= T(1) / s; }

    constexpr bool operator==(const Vec3T&) const = default;
};

template <typename T>
constexpr Vec3T<T> operator+(Vec3T<T> a, const Vec3T<T>& b) {
    return a += b;
}
template <typename T>
constexpr Vec3T<T> operator-(Vec3T<T> a, const Vec3T<T>& b) {
    return a -= b;
}
template <typename T>
constexpr Vec3T<T> operator*(Vec3T<T> a, T s) {
    return a *= s;
}
template <typename T>
constexpr Vec3T<T> operator*(T s, Vec3T<T> a) {
    return a *= s;
}
template <typename T>
constexpr Vec3T<T> operator/(Vec3T<T> a, T s) {
    return a /= s;
}

template <typename T>
constexpr T dot(const Vec3T<T>& a, const Vec3T<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
constexpr Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T>
constexpr T lengthSquared(const Vec3T<T>& v) {
    return dot(v, v);
}
template <typename T>
T length(const Vec3T<T>& v) {
    return std::sqrt(dot(v, v));
}
template <typename T>
LANCER_ALWAYS_INLINE Vec3T<T> normalize(const Vec3T<T>& v) {
    return v / length(v);
}
// The angle between two vectors, in radians: accurate near 0 and pi, where acos of the normalized
// dot product is not.
template <typename T>
T angleBetween(const Vec3T<T>& a, const Vec3T<T>& b) {
    return std::atan2(length(cross(a, b)), dot(a, b));
}
template <typename T>
Vec3T<T> abs(const Vec3T<T>& v) {
    return {std::abs(v.x), std::abs(v.y), std::abs(v.z)};
}
template <typename T>
constexpr Vec3T<T> min(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
template <typename T>
constexpr Vec3T<T> max(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
template <typename T>
constexpr T maxComponent(const Vec3T<T>& v) {
    return std::max(v.x, std::max(v.y, v.z));
}
// Index of the component with the largest absolute value.
template <typename T>
constexpr int maxDimension(const Vec3T<T>& v) {
    const T ax = v.x < 0 ? -v.x : v.x, ay = v.y < 0 ? -v.y : v.y, az = v.z < 0 ? -v.z : v.z;
    return ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
}
template <typename T>
constexpr Vec3T<T> permute(const Vec3T<T>& v, int i, int j, int k) {
    return {v[i], v[j], v[k]};
}
template <typename T>
bool isFinite(const Vec3T<T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The mirror image of the direction `wo` (pointing away from the surface) about the normal `n`.
template <typename T>
constexpr Vec3T<T> reflect(const Vec3T<T>& wo, const Vec3T<T>& n) {
    return T(2) * dot(wo, n) * n - wo;
}

// An orthonormal basis (s, t) completing the unit vector n (Duff et al. 2017, branchless).
template <typename T>
LANCER_ALWAYS_INLINE void coordinateSystem(const Vec3T<T>& n, Vec3T<T>& s, Vec3T<T>& t) {
    const T sign = std::copysign(T(1), n.z);
    const T a = T(-1) / (sign + n.z);
    const T b = n.x * n.y * a;
    s = {T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x};
    t = {b, sign + n.y * n.y * a, -n.y};
}

using Vec3 = Vec3T<float>;
using Vec3d = Vec3T<double>;

}  // namespace lancer
