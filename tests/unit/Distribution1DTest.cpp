#include "math/Distribution1D.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

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

// Equal weights (a box filter's table, a single light) are found without a search: cell
// floor(u n), probability 1 / n, and u's place in the cell u n - floor(u n).
TEST(Distribution1D, EqualWeightsPickCellUNDirectly) {
    for (const std::size_t n : {std::size_t{1}, std::size_t{3}, std::size_t{256}}) {
        const Distribution1D d(std::vector<float>(n, 2.5f));
        for (const float u : {0.0f, 0.2f, 1.0f / 3, 0.5f, 0.74f, 0x1.fffffep-1f}) {
            float pmf = 0, remapped = -1;
            const std::size_t i = d.sampleDiscrete(u, &pmf, &remapped);
            const double scaled = static_cast<double>(u) * static_cast<double>(n);
            EXPECT_EQ(i, std::min(static_cast<std::size_t>(scaled), n - 1)) << n << " " << u;
            EXPECT_NEAR(pmf, 1.0 / static_cast<double>(n), 1e-7);
            EXPECT_NEAR(remapped, scaled - static_cast<double>(i), 1e-6);
            EXPECT_LT(remapped, 1.0f);
            EXPECT_NEAR(d.sampleContinuous(u), u, 1e-6f);
        }
    }
}

// sampleDiscrete searches only the cells of u's bucket; it must pick what a search of the whole
// cumulative table picks, for every u, on the boundaries and beside them, whatever the weights
// (spikes, long runs of zeros, tiny cells several to a bucket).
TEST(Distribution1D, TheBucketedSearchAgreesWithASearchOfTheWholeTable) {
    std::vector<float> weights(997, 0.0f);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (std::size_t i = 0; i < weights.size(); ++i) {
        const float r = uniform(random);
        weights[i] = r < 0.5f ? 0.0f : r < 0.9f ? 1e-6f * r : r < 0.99f ? r : 300 * r;
    }
    const Distribution1D d(weights);
    // The table as the class builds it.
    std::vector<double> cdf(weights.size() + 1, 0.0);
    for (std::size_t i = 0; i < weights.size(); ++i)
        cdf[i + 1] = cdf[i] + weights[i];
    const double total = cdf.back();
    for (double& c : cdf)
        c /= total;
    cdf.back() = 1;
    const auto wholeTableSearch = [&](float u) {
        const auto upper = std::upper_bound(cdf.begin(), cdf.end(), static_cast<double>(u));
        std::size_t i =
            static_cast<std::size_t>(std::max<std::ptrdiff_t>(upper - cdf.begin() - 1, 0));
        i = std::min(i, weights.size() - 1);
        while (cdf[i + 1] == cdf[i] && i > 0)
            --i;
        return i;
    };
    std::vector<float> us;
    for (int k = 0; k < 100000; ++k)
        us.push_back(static_cast<float>(k) / 100000);
    for (const double c : cdf) {
        const float u = static_cast<float>(c);
        for (float v : {std::nextafter(u, 0.0f), u, std::nextafter(u, 1.0f)})
            if (v >= 0 && v < 1) us.push_back(v);
    }
    us.push_back(0x1.fffffep-1f);
    for (const float u : us) {
        ASSERT_EQ(d.sampleDiscrete(u), wholeTableSearch(u)) << "u = " << u;
        EXPECT_GT(d.pmf(d.sampleDiscrete(u)), 0.0f);
    }
}
