#include "math/Distribution1D.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

using lancer::Distribution1D;

TEST(Distribution1D, DiscreteProbabilitiesFollowTheWeights) {
    const Distribution1D d({1, 0, 3});
    EXPECT_FLOAT_EQ(d.pmf(0), 0.25f);
    EXPECT_FLOAT_EQ(d.pmf(1), 0.0f);
    EXPECT_FLOAT_EQ(d.pmf(2), 0.75f);
    EXPECT_FLOAT_EQ(d.integral(), 4.0f / 3.0f);
    float pmf = 0, remapped = 0;
    EXPECT_EQ(d.sampleDiscrete(0.1f, &pmf, &remapped), 0u);
    EXPECT_FLOAT_EQ(pmf, 0.25f);
    EXPECT_NEAR(remapped, 0.4f, 1e-6f);
    // u exactly on the boundary of an empty cell never picks the empty cell.
    EXPECT_EQ(d.sampleDiscrete(0.25f), 2u);
    EXPECT_EQ(d.sampleDiscrete(0.0f), 0u);
    EXPECT_EQ(d.sampleDiscrete(0x1.fffffep-1f), 2u);
}

TEST(Distribution1D, ContinuousSamplesInvertTheCdf) {
    const Distribution1D d({1, 3});
    float pdf = 0;
    // The first cell [0, 0.5) holds a quarter of the probability.
    EXPECT_NEAR(d.sampleContinuous(0.125f, &pdf), 0.25f, 1e-6f);
    EXPECT_FLOAT_EQ(pdf, 0.5f);
    EXPECT_NEAR(d.sampleContinuous(0.625f, &pdf), 0.75f, 1e-6f);
    EXPECT_FLOAT_EQ(pdf, 1.5f);
    EXPECT_FLOAT_EQ(d.pdf(0.2f), 0.5f);
    EXPECT_FLOAT_EQ(d.pdf(0.9f), 1.5f);
    EXPECT_LT(d.sampleContinuous(0x1.fffffep-1f), 1.0f);
}

TEST(Distribution1D, AllZeroWeightsBecomeUniform) {
    const Distribution1D d({0, 0});
    EXPECT_FLOAT_EQ(d.pmf(0), 0.5f);
    EXPECT_FLOAT_EQ(d.pmf(1), 0.5f);
}

TEST(Distribution1D, RejectsNegativeOrNonFiniteWeights) {
    EXPECT_THROW(Distribution1D({1, -1}), std::invalid_argument);
    EXPECT_THROW(Distribution1D({1, std::numeric_limits<float>::quiet_NaN()}),
                 std::invalid_argument);
    EXPECT_THROW(Distribution1D(std::vector<float>{}), std::invalid_argument);
}
