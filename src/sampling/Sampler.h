#pragma once

#include <array>
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
    // Passes over the next request, a point or a value, unseen (a pinhole's lens sample, a
    // bounce's numbers it does not read): the requests after it get what they would get after
    // get2D or get1D, and nothing is drawn.
    void skip();

private:
    enum class RequestKind : std::uint8_t { point, value, skipped };

    // The scramble seeds of one request: for a point, those of the sample index and of its two
    // coordinates; for a value, those of the index and of the value (the third is unused).
    struct RequestSeeds {
        std::array<std::uint32_t, 3> seeds;
        RequestKind kind;
    };

    // Hashing the seeds costs more than scrambling with them, and they depend only on the pixel
    // and the request: the pixel's samples share them, hashed by the first sample that makes the
    // request. The cache covers the requests of a few dozen bounces or area lights; the rest are
    // hashed each time, as is a request whose kind differs from the one cached (one skipped
    // where it was cached takes its place).
    static constexpr int kCachedRequests = 256;

    RequestSeeds nextRequestSeeds(RequestKind kind);
    RequestSeeds hashRequestSeeds(int request, RequestKind kind) const;

    std::uint64_t pixelHash_;  // the hash chain after (seed, pixel), each request extends it
    std::uint32_t reversedIndex_ = 0;  // the sample index, bit-reversed
    int request_ = 0;
    int cachedRequestCount_ = 0;
    std::array<RequestSeeds, kCachedRequests> cachedRequests_;  // filled in request order
};

}  // namespace lancer
