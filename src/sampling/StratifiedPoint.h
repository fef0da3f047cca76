#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "math/Float.h"
#include "math/Vec2.h"
#include "sampling/Sampling.h"

namespace lancer {

// Point k of `count` points over the unit square: rows of cells (the rows' cells widened so that
// every row tiles the square), one jittered point per cell, the jitter a hash of (seed, k). Each
// cell has the same area, so the average over the points is an unbiased estimate of an average
// over the square, and a deterministic one.
inline Vec2 stratifiedPoint(int k, int count, std::uint64_t seed) {
    const int rows = std::max(1, static_cast<int>(std::sqrt(static_cast<float>(count))));
    const int perRow = count / rows, extra = count % rows;
    // The first `extra` rows hold perRow + 1 points.
    const int bigRows = extra * (perRow + 1);
    const int row = k < bigRows ? k / (perRow + 1) : extra + (k - bigRows) / perRow;
    const int column = k < bigRows ? k % (perRow + 1) : (k - bigRows) % perRow;
    const int columns = row < extra ? perRow + 1 : perRow;
    const std::uint64_t bits = hashValues(seed, k);
    const float jitterX = static_cast<float>(bits >> 40) * 0x1p-24f;
    const float jitterY = static_cast<float>(bits & 0xffffff) * 0x1p-24f;
    return {
        std::min((static_cast<float>(column) + jitterX) / static_cast<float>(columns),
                 kOneMinusEpsilon),
        std::min((static_cast<float>(row) + jitterY) / static_cast<float>(rows), kOneMinusEpsilon)};
}

// A point of the unit square moved by `offset` (in [0, 1)^2) with wrap-around: a uniformly random
// offset makes every point of a pattern uniform over the square.
inline Vec2 shifted(const Vec2& point, const Vec2& offset) {
    // Below 2, so one subtraction (exact in [1, 2)) brings it back into [0, 1).
    const auto wrap = [](float x) { return x >= 1 ? x - 1 : x; };
    return {wrap(point.x + offset.x), wrap(point.y + offset.y)};
}

}  // namespace lancer
