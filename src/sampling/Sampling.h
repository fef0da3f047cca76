#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "math/Float.h"
#include "math/Vec2.h"
#include "math/Vec3.h"

namespace lancer {

// Maps the unit square onto the unit disc, keeping strata compact (Shirley and Chiu 1997).
inline Vec2 sampleUniformDiskConcentric(const Vec2& u) {
    const Vec2 offset = 2.0f * u - Vec2(1, 1);
    if (offset.x == 0 && offset.y == 0) return {0, 0};
    float r, theta;
    if (std::abs(offset.x) > std::abs(offset.y)) {
        r = offset.x;
        theta = (kPi / 4) * (offset.y / offset.x);
    } else {
        r = offset.y;
        theta = kPi / 2 - (kPi / 4) * (offset.x / offset.y);
    }
    return r * Vec2(std::cos(theta), std::sin(theta));
}

// A direction in the hemisphere around +z with density cos(theta) / pi (Malley's method: a point
// of the unit disc lifted onto the hemisphere).
inline Vec3 sampleCosineHemisphere(const Vec2& u) {
    const Vec2 d = sampleUniformDiskConcentric(u);
    return {d.x, d.y, std::sqrt(std::max(0.0f, 1 - d.x * d.x - d.y * d.y))};
}

// The power heuristic with beta = 2 (Veach 1997): the weight of a sample drawn with density a
// when b is the other strategy's density for it (1 for a delta strategy's, of infinite density).
inline float powerHeuristic(float a, float b) {
    if (std::isinf(a)) return 1;
    const float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0 ? a2 / (a2 + b2) : 0;
}

// A 64-bit hash of several integers (the SplitMix64 finaliser, chained): turns (seed, pixel,
// dimension) into independent-looking seeds.
inline std::uint64_t mixBits(std::uint64_t v) {
    v ^= v >> 31;
    v *= 0x7fb5d329728ea185ULL;
    v ^= v >> 27;
    v *= 0x81dadef4bc2dd44dULL;
    v ^= v >> 33;
    return v;
}

// The chain's two steps, for callers that hash many values after a common prefix once:
// hashValues(a, b) == extendHash(beginHash(a), b).
inline std::uint64_t beginHash(std::uint64_t first) {
    return mixBits(first + 0x9e3779b97f4a7c15ULL);
}

inline std::uint64_t extendHash(std::uint64_t hash, std::uint64_t next) {
    return mixBits(hash ^ (next + 0x9e3779b97f4a7c15ULL));
}

template <typename... Ts>
std::uint64_t hashValues(std::uint64_t first, Ts... rest) {
    std::uint64_t h = beginHash(first);
    ((h = extendHash(h, static_cast<std::uint64_t>(rest))), ...);
    return h;
}

}  // namespace lancer
