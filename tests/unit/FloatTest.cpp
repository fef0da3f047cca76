// nextFloatUp and nextFloatDown step the bit pattern: they must give exactly what std::nextafter
// gives towards the infinities, signed zeros, denormals and the largest floats included.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "math/Float.h"

namespace lancer {
namespace {

void expectSameAsNextafter(float v) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(nextFloatUp(v)),
              std::bit_cast<std::uint32_t>(std::nextafter(v, kInfinity)))
        << v;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(nextFloatDown(v)),
              std::bit_cast<std::uint32_t>(std::nextafter(v, -kInfinity)))
        << v;
}

TEST(NextFloat, MatchesNextafterOnTheSpecialValues) {
    using limits = std::numeric_limits<float>;
    for (const float v :
         {0.0f, -0.0f, limits::denorm_min(), -limits::denorm_min(), limits::min(), -limits::min(),
          1.0f, -1.0f, limits::max(), -limits::max(), kInfinity, -kInfinity})
        expectSameAsNextafter(v);
}

TEST(NextFloat, MatchesNextafterOnRandomBitPatterns) {
    std::mt19937 random(1);
    for (int i = 0; i < 100000; ++i) {
        const float v = std::bit_cast<float>(static_cast<std::uint32_t>(random()));
        if (!std::isnan(v)) expectSameAsNextafter(v);
    }
}

}  // namespace
}  // namespace lancer
