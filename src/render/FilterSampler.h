#pragma once

#include <memory>

#include "math/Distribution1D.h"
#include "math/Vec2.h"
#include "render/Filter.h"
#include "render/FilterSample.h"

namespace lancer {

// Filter importance sampling (as pbrt-v4): sample offsets are drawn with a density proportional
// to |filter|, and weighted by filter / density, so that sum(w L) / sum(w) over a pixel's own
// samples converges to the filtered image. Each pixel keeps its own samples (no splatting into
// the neighbours), so pixels stay independent of tiles and threads. The separable profile is
// tabulated once per axis (Distribution1D); the weights use the exact filter, so the table's
// coarseness costs a little variance, never bias.
class FilterSampler {
public:
    explicit FilterSampler(std::unique_ptr<Filter> filter);

    const Filter& filter() const { return *filter_; }

    // Maps a point of [0,1)^2 to an offset and its weight; monotonic along each axis, so that
    // stratified points give stratified offsets.
    FilterSample sample(const Vec2& u) const;

private:
    // An offset along one axis, in [-radius, radius), and profile / density there.
    float sampleAxis(float u, float& weight) const;

    std::unique_ptr<Filter> filter_;
    Distribution1D profileDistribution_;  // |profile| over [-radius, radius]
    bool flat_;                           // whether the profile is the same everywhere
};

}  // namespace lancer
