#include "sampling/Sampler.h"

#include "sampling/Sampling.h"

namespace lancer {

namespace {

std::uint32_t reverseBits(std::uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
    return (v >> 16) | (v << 16);
}

// A bijection of 32-bit words in which each bit changes only as a function of the bits below it
// (additions, odd multiplications and x ^= x * even all carry upwards only): on bit-reversed
// values it is a nested uniform (Owen) scramble. Laine and Karras's hash as improved by Vegdahl
// (2021, "Building a better LK hash").
std::uint32_t laineKarrasPermutation(std::uint32_t x, std::uint32_t seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// Owen scrambling of a 0.32 fixed-point value x is reverseBits(laineKarrasPermutation(
// reverseBits(x), seed)): bit i (from the top) is flipped as a hash of the bits above it, which
// keeps every elementary interval's points inside one elementary interval. The code below works
// on bit-reversed values where it can, to skip reversals that would cancel.

// Sobol's second dimension (primitive polynomial x + 1), bit-reversed. Its generator matrix is
// Pascal's triangle mod 2 (column k is the top bit times (1 + shift right)^k), so bit i from the
// top is the parity of the index bits k with C(k, i) odd: by Lucas's theorem, of the k whose bits
// include all of i's. That parity over supersets takes one step per bit of i. (The first
// dimension is the bit reversal of the index, van der Corput.)
std::uint32_t reversedSobolDimension1(std::uint32_t index) {
    index ^= (index >> 1) & 0x55555555u;
    index ^= (index >> 2) & 0x33333333u;
    index ^= (index >> 4) & 0x0f0f0f0fu;
    index ^= (index >> 8) & 0x00ff00ffu;
    index ^= index >> 16;
    return index;
}

// The top 24 bits as a float in [0,1): exact, so truncation keeps every point in the elementary
// interval its bits say (rounding all 32 bits could carry it onto the next interval's edge, or 1).
float toUnitFloat(std::uint32_t x) {
    return static_cast<float>(x >> 8) * 0x1p-24f;
}

}  // namespace

Sampler::Sampler(std::uint64_t seed, int pixelX, int pixelY)
    : pixelHash_(beginHash(hashValues(seed, pixelX, pixelY))) {}

void Sampler::startSample(int index) {
    reversedIndex_ = reverseBits(static_cast<std::uint32_t>(index));
    request_ = 0;
}

Sampler::RequestSeeds Sampler::hashRequestSeeds(int request, RequestKind kind) const {
    const std::uint64_t seed = extendHash(pixelHash_, static_cast<std::uint64_t>(request));
    if (kind == RequestKind::value)
        return {{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32), 0},
                kind};
    const std::uint64_t partsHash = beginHash(seed);
    const auto seedOf = [&](std::uint64_t part) {
        return static_cast<std::uint32_t>(extendHash(partsHash, part));
    };
    return {{seedOf(0), seedOf(1), seedOf(2)}, kind};
}

Sampler::RequestSeeds Sampler::nextRequestSeeds(RequestKind kind) {
    const int request = request_++;
    if (request < cachedRequestCount_) {
        const RequestSeeds& cached = cachedRequests_[static_cast<std::size_t>(request)];
        if (cached.kind == kind) return cached;
        const RequestSeeds seeds = hashRequestSeeds(request, kind);
        if (cached.kind == RequestKind::skipped)
            cachedRequests_[static_cast<std::size_t>(request)] = seeds;
        return seeds;
    }
    const RequestSeeds seeds = hashRequestSeeds(request, kind);
    if (request < kCachedRequests) {
        cachedRequests_[static_cast<std::size_t>(request)] = seeds;
        ++cachedRequestCount_;
    }
    return seeds;
}

Vec2 Sampler::get2D() {
    const auto [indexSeed, xSeed, ySeed] = nextRequestSeeds(RequestKind::point).seeds;
    // The Owen-scrambled sample index picks the Sobol point. Its x, the index reversed, is
    // scrambled by reversing it back (the index itself), permuting and reversing; its y likewise
    // from the reversed second dimension.
    const std::uint32_t index = reverseBits(laineKarrasPermutation(reversedIndex_, indexSeed));
    return {
        toUnitFloat(reverseBits(laineKarrasPermutation(index, xSeed))),
        toUnitFloat(reverseBits(laineKarrasPermutation(reversedSobolDimension1(index), ySeed)))};
}

void Sampler::skip() {
    // A request's seeds hash only the pixel and the request's number: a skipped one needs none.
    // It still takes its place in the cache, marked so that a point asked there later is hashed.
    const int request = request_++;
    if (request == cachedRequestCount_ && request < kCachedRequests) {
        cachedRequests_[static_cast<std::size_t>(request)] = {{}, RequestKind::skipped};
        ++cachedRequestCount_;
    }
}

float Sampler::get1D() {
    const auto [indexSeed, valueSeed, unused] = nextRequestSeeds(RequestKind::value).seeds;
    // The scrambled index, reversed, is the van der Corput point, which is then scrambled.
    const std::uint32_t point = laineKarrasPermutation(reversedIndex_, indexSeed);
    return toUnitFloat(reverseBits(laineKarrasPermutation(reverseBits(point), valueSeed)));
}

}  // namespace lancer
