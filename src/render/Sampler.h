#pragma once

#include <cstdint>

#include "math/Vec2.h"

namespace lancer {

// Sample points for the spp samples of one pixel: correlated multi-jittered sampling (Kensler
// 2013). For every dimension pair the spp points are stratified over an m x n grid of the unit
// square, with one point in each row and column as well, and their order is shuffled
// independently per dimension, so that dimensions do not correlate. Everything derives from
// (seed, pixel, sample index, dimension): the same sample gets the same numbers in any thread.
class Sampler {
public:
    Sampler(std::uint64_t seed, int pixelX, int pixelY, int samplesPerPixel);

    // Starts sample `index` (0 <= index < samplesPerPixel) of the pixel.
    void startSample(int index);

    // The next 2D point of the current sample, in [0,1)^2.
    Vec2 get2D();
    // The next number of the current sample, in [0,1).
    float get1D();

    int samplesPerPixel() const { return samplesPerPixel_; }

private:
    std::uint32_t patternFor(int dimension) const;

    std::uint64_t pixelSeed_;
    int samplesPerPixel_;
    int sampleIndex_ = 0;
    int dimension_ = 0;
};

}  // namespace lancer
