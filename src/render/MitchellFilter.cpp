#include "render/MitchellFilter.h"

#include <cmath>

namespace lancer {

namespace {

constexpr float kB = 1.0f / 3, kC = 1.0f / 3;

// The kernel of Mitchell and Netravali's paper, on [-2, 2].
float mitchell(float t) {
    t = std::abs(t);
    if (t < 1)
        return ((12 - 9 * kB - 6 * kC) * t * t * t + (-18 + 12 * kB + 6 * kC) * t * t +
                (6 - 2 * kB)) /
               6;
    if (t < 2)
        return ((-kB - 6 * kC) * t * t * t + (6 * kB + 30 * kC) * t * t + (-12 * kB - 48 * kC) * t +
                (8 * kB + 24 * kC)) /
               6;
    return 0;
}

}  // namespace

MitchellFilter::MitchellFilter(float radius) : Filter(radius) {}

float MitchellFilter::profile(float x) const {
    if (std::abs(x) > radius()) return 0;
    return mitchell(2 * x / radius()) * 2 / radius();
}

}  // namespace lancer
