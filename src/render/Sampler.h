#pragma once

#include <cstdint>

#include "math/Vec2.h"

namespace lancer {

// Sample points for one pixel: Owen-scrambled Sobol points, "padded" as in Burley 2020
// ("Practical Hash-based Owen Scrambling"). Every request (a 2D point or a 1D value) takes the
// first two (or the first) Sobol dimensions under its own nested uniform scramble, and visits the
// Sobol points in its own shuffled order: the sample index is itself Owen-scrambled, which maps
// the first 2^k indices onto one aligned block of 2^k Sobol points. So the first 2^k samples of a
// pixel are stratified in every request (one point in each elementary interval of area 2^-k) for
// every k, whatever the sample count turns out to be (adaptive sampling stops anywhere), and the
// requests do not correlate with each other. The scrambles are hashes of (seed, pixel, request):
// the same sample gets the same numbers in any thread, and neighbouring pixels are independent.
class Sampler {
public:
    Sampler(std::uint64_t seed, int pixelX, int pixelY);

    // Starts sample `index` (any index >= 0) of the pixel.
    void startSample(int index);

    // The next 2D point of the current sample, in [0,1)^2.
    Vec2 get2D();
    // The next number of the current sample, in [0,1).
    float get1D();

private:
    std::uint64_t requestSeed();

    std::uint64_t pixelSeed_;
    std::uint32_t sampleIndex_ = 0;
    int dimension_ = 0;
};

}  // namespace lancer
