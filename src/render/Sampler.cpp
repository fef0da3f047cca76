#include "render/Sampler.h"

#include <algorithm>
#include <cmath>

#include "math/Float.h"
#include "render/Sampling.h"

namespace lancer {

namespace {

// A pseudo-random permutation of [0, size) selected by `pattern`: a hash that is a bijection on
// the enclosing power of two, applied until the value falls inside the range ("cycle walking").
std::uint32_t permute(std::uint32_t i, std::uint32_t size, std::uint32_t pattern) {
    std::uint32_t mask = size - 1;
    mask |= mask >> 1;
    mask |= mask >> 2;
    mask |= mask >> 4;
    mask |= mask >> 8;
    mask |= mask >> 16;
    do {
        i ^= pattern;
        i *= 0xe170893d;
        i ^= pattern >> 16;
        i ^= (i & mask) >> 4;
        i ^= pattern >> 8;
        i *= 0x0929eb3f;
        i ^= pattern >> 23;
        i ^= (i & mask) >> 1;
        i *= 1 | pattern >> 27;
        i *= 0x6935fa69;
        i ^= (i & mask) >> 11;
        i *= 0x74dcb303;
        i ^= (i & mask) >> 2;
        i *= 0x9e501cc3;
        i ^= (i & mask) >> 2;
        i *= 0xc860a3df;
        i &= mask;
        i ^= i >> 5;
    } while (i >= size);
    return (i + pattern) % size;
}

// A hashed float in [0, 1) for index i under `pattern`.
float hashedFloat(std::uint32_t i, std::uint32_t pattern) {
    i ^= pattern;
    i ^= i >> 17;
    i ^= i >> 10;
    i *= 0xb36534e5;
    i ^= i >> 12;
    i ^= i >> 21;
    i *= 0x93fc4795;
    i ^= 0xdf6e307f;
    i ^= i >> 17;
    i *= 1 | pattern >> 18;
    // The top 24 bits, so that the result is exactly representable and strictly below 1.
    return static_cast<float>(i >> 8) * 0x1p-24f;
}

// Moves u, computed as (stratum + jitter) / strata in float, back into its stratum
// [stratum / strata, (stratum + 1) / strata): with a jitter close to 1 the rounding of the sum or
// of the quotient can land on the next stratum's edge (which also reaches 1 at the top), and
// with a jitter of 0 below an edge that is not a float. Exact tests: u * strata fits a double.
float keepInStratum(float u, std::uint32_t stratum, std::uint32_t strata) {
    while (static_cast<double>(u) * strata >= stratum + 1.0)
        u = nextFloatDown(u);
    while (static_cast<double>(u) * strata < stratum)
        u = nextFloatUp(u);
    return u;
}

}  // namespace

Sampler::Sampler(std::uint64_t seed, int pixelX, int pixelY, int samplesPerPixel)
    : pixelSeed_(hashValues(seed, pixelX, pixelY)), samplesPerPixel_(samplesPerPixel) {}

void Sampler::startSample(int index) {
    sampleIndex_ = index;
    dimension_ = 0;
}

std::uint32_t Sampler::patternFor(int dimension) const {
    return static_cast<std::uint32_t>(hashValues(pixelSeed_, dimension));
}

Vec2 Sampler::get2D() {
    const std::uint32_t pattern = patternFor(dimension_++);
    const auto count = static_cast<std::uint32_t>(samplesPerPixel_);
    // An m x n grid with m * n >= count, as square as possible.
    const auto m = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(count))));
    const std::uint32_t n = (count + m - 1) / m;
    const std::uint32_t s =
        permute(static_cast<std::uint32_t>(sampleIndex_), count, pattern * 0x51633e2d);
    const std::uint32_t sx = permute(s % m, m, pattern * 0xa511e9b3);
    const std::uint32_t sy = permute(s / m, n, pattern * 0x63d83595);
    const float jx = hashedFloat(s, pattern * 0xa399d265);
    const float jy = hashedFloat(s, pattern * 0x711ad6a5);
    const float x =
        (static_cast<float>(s % m) + (static_cast<float>(sy) + jx) / static_cast<float>(n)) /
        static_cast<float>(m);
    const float y =
        (static_cast<float>(s / m) + (static_cast<float>(sx) + jy) / static_cast<float>(m)) /
        static_cast<float>(n);
    // x lies in stratum (s % m) n + sy of the m n columns, y in (s / m) m + sx of the rows.
    return {keepInStratum(x, (s % m) * n + sy, m * n), keepInStratum(y, (s / m) * m + sx, m * n)};
}

float Sampler::get1D() {
    const std::uint32_t pattern = patternFor(dimension_++);
    const auto count = static_cast<std::uint32_t>(samplesPerPixel_);
    const std::uint32_t stratum = permute(static_cast<std::uint32_t>(sampleIndex_), count, pattern);
    const float u = (static_cast<float>(stratum) + hashedFloat(stratum, pattern * 0x68bc21eb)) /
                    static_cast<float>(count);
    return keepInStratum(u, stratum, count);
}

}  // namespace lancer
