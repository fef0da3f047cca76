#include "render/Sampler.h"

#include <array>

#include "render/Sampling.h"

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

// Owen scrambling of a 0.32 fixed-point value: bit i (from the top) is flipped as a hash of the
// bits above it, which keeps every elementary interval's points inside one elementary interval.
std::uint32_t nestedUniformScramble(std::uint32_t x, std::uint32_t seed) {
    return reverseBits(laineKarrasPermutation(reverseBits(x), seed));
}

// Generator matrix columns of Sobol's second dimension (primitive polynomial x + 1): Pascal's
// triangle mod 2, v_k = v_(k-1) ^ (v_(k-1) >> 1). The first dimension is the bit reversal of the
// index (van der Corput).
constexpr std::array<std::uint32_t, 32> kSobolDimension1 = [] {
    std::array<std::uint32_t, 32> v{};
    v[0] = 0x80000000u;
    for (std::size_t k = 1; k < v.size(); ++k)
        v[k] = v[k - 1] ^ (v[k - 1] >> 1);
    return v;
}();

std::uint32_t sobolDimension1(std::uint32_t index) {
    std::uint32_t x = 0;
    for (std::size_t k = 0; index != 0; index >>= 1, ++k)
        if (index & 1u) x ^= kSobolDimension1[k];
    return x;
}

// The top 24 bits as a float in [0,1): exact, so truncation keeps every point in the elementary
// interval its bits say (rounding all 32 bits could carry it onto the next interval's edge, or 1).
float toUnitFloat(std::uint32_t x) {
    return static_cast<float>(x >> 8) * 0x1p-24f;
}

}  // namespace

Sampler::Sampler(std::uint64_t seed, int pixelX, int pixelY)
    : pixelSeed_(hashValues(seed, pixelX, pixelY)) {}

void Sampler::startSample(int index) {
    sampleIndex_ = static_cast<std::uint32_t>(index);
    dimension_ = 0;
}

std::uint64_t Sampler::requestSeed() {
    return hashValues(pixelSeed_, dimension_++);
}

Vec2 Sampler::get2D() {
    const std::uint64_t seed = requestSeed();
    const auto seedOf = [&](int part) {
        return static_cast<std::uint32_t>(hashValues(seed, part));
    };
    const std::uint32_t index = nestedUniformScramble(sampleIndex_, seedOf(0));
    return {toUnitFloat(nestedUniformScramble(reverseBits(index), seedOf(1))),
            toUnitFloat(nestedUniformScramble(sobolDimension1(index), seedOf(2)))};
}

float Sampler::get1D() {
    const std::uint64_t seed = requestSeed();
    const auto low = static_cast<std::uint32_t>(seed),
               high = static_cast<std::uint32_t>(seed >> 32);
    return toUnitFloat(
        nestedUniformScramble(reverseBits(nestedUniformScramble(sampleIndex_, low)), high));
}

}  // namespace lancer
