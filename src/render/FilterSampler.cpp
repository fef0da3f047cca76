#include "render/FilterSampler.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lancer {

namespace {

// Cells of the table across [-radius, radius]; and sub-points per cell averaged into its
// weight, so that a cell is never given zero density where the filter is not zero within it
// (at a zero crossing of Mitchell's lobes, or at the box's edge).
constexpr int kCells = 256;
constexpr int kPointsPerCell = 8;

std::vector<float> tabulateProfile(const Filter& filter) {
    const float r = filter.radius();
    std::vector<float> weights(kCells);
    for (int i = 0; i < kCells; ++i) {
        float sum = 0;
        for (int j = 0; j < kPointsPerCell; ++j) {
            const float t =
                (static_cast<float>(i) + (static_cast<float>(j) + 0.5f) / kPointsPerCell) / kCells;
            sum += std::abs(filter.profile(-r + 2 * r * t));
        }
        weights[static_cast<std::size_t>(i)] = sum / kPointsPerCell;
    }
    return weights;
}

bool isFlat(const std::vector<float>& weights) {
    return std::all_of(weights.begin(), weights.end(),
                       [&](float w) { return w == weights.front(); });
}

}  // namespace

FilterSampler::FilterSampler(std::unique_ptr<Filter> filter)
    : filter_(std::move(filter)),
      profileDistribution_(tabulateProfile(*filter_)),
      flat_(isFlat(tabulateProfile(*filter_))) {}

float FilterSampler::sampleAxis(float u, float& weight) const {
    const float r = filter_->radius();
    // A flat table (the box's) maps u onto itself with density 1, to the bit: the bounds of its
    // kCells cells are multiples of 1 / kCells, exact in floating point. No search needed.
    float density = 1;
    const float x = -r + 2 * r * (flat_ ? u : profileDistribution_.sampleContinuous(u, &density));
    // density is per unit of [0, 1); per pixel it is density / (2 r).
    weight = filter_->profile(x) * (2 * r) / density;
    return x;
}

FilterSample FilterSampler::sample(const Vec2& u) const {
    float wx = 0, wy = 0;
    const float x = sampleAxis(u.x, wx);
    const float y = sampleAxis(u.y, wy);
    return {{x, y}, wx * wy};
}

}  // namespace lancer
