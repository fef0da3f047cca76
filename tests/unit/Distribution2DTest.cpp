// Distribution2D: its density is the grid's values normalised (cell by cell, exactly), sampling
// inverts the marginal and conditional cumulative distributions exactly, and a histogram of many
// samples passes a chi-square test against the density.

#include "math/Distribution2D.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace lancer {
namespace {

TEST(Distribution2D, DensityIsTheValuesNormalised) {
    // Rows {1, 3} and {0, 4}: the integral over [0,1)^2 is (1 + 3 + 0 + 4) / 4 = 2.
    const Distribution2D d({1, 3, 0, 4}, 2, 2);
    EXPECT_FLOAT_EQ(d.pdf(Vec2(0.25f, 0.25f)), 0.5f);
    EXPECT_FLOAT_EQ(d.pdf(Vec2(0.75f, 0.25f)), 1.5f);
    EXPECT_FLOAT_EQ(d.pdf(Vec2(0.25f, 0.75f)), 0.0f);
    EXPECT_FLOAT_EQ(d.pdf(Vec2(0.75f, 0.75f)), 2.0f);
}

TEST(Distribution2D, SamplingInvertsTheMarginalThenTheConditional) {
    const Distribution2D d({1, 3, 0, 4}, 2, 2);
    float pdf = 0;
    // The first row holds half the mass: u.y = 0.25 is its middle, y = 0.25. In it, the first
    // column holds a quarter: u.x = 0.125 is that column's middle, x = 0.25.
    Vec2 p = d.sample(Vec2(0.125f, 0.25f), &pdf);
    EXPECT_NEAR(p.x, 0.25f, 1e-6f);
    EXPECT_NEAR(p.y, 0.25f, 1e-6f);
    EXPECT_FLOAT_EQ(pdf, 0.5f);
    // The second row has all its mass in its second column.
    p = d.sample(Vec2(0.5f, 0.75f), &pdf);
    EXPECT_NEAR(p.x, 0.75f, 1e-6f);
    EXPECT_NEAR(p.y, 0.75f, 1e-6f);
    EXPECT_FLOAT_EQ(pdf, 2.0f);
    EXPECT_FLOAT_EQ(pdf, d.pdf(p));
    p = d.sample(Vec2(0x1.fffffep-1f, 0x1.fffffep-1f), &pdf);
    EXPECT_LT(p.x, 1.0f);
    EXPECT_LT(p.y, 1.0f);
}

// sampleCell gives the cell sample() places its point in, the cell's probability, and where u
// fell within the cell's share: sample() is (cell + offset) / size.
TEST(Distribution2D, SampleCellGivesTheCellItsProbabilityAndTheOffsetWithin) {
    const Distribution2D d({1, 3, 0, 4}, 2, 2);
    // The first row holds half the mass, its first column a quarter of that: u.y = 0.25 is the
    // row's middle, u.x = 0.125 the column's.
    Distribution2D::CellSample cell = d.sampleCell(Vec2(0.125f, 0.25f));
    EXPECT_EQ(cell.x, 0);
    EXPECT_EQ(cell.y, 0);
    EXPECT_FLOAT_EQ(cell.probability, 0.125f);
    EXPECT_FLOAT_EQ(cell.offset.x, 0.5f);
    EXPECT_FLOAT_EQ(cell.offset.y, 0.5f);
    // The second row's mass is all in its second column: u.x = 0.9 is 9/10 across it.
    cell = d.sampleCell(Vec2(0.9f, 0.625f));
    EXPECT_EQ(cell.x, 1);
    EXPECT_EQ(cell.y, 1);
    EXPECT_FLOAT_EQ(cell.probability, 0.5f);
    EXPECT_NEAR(cell.offset.x, 0.9f, 1e-6f);
    EXPECT_NEAR(cell.offset.y, 0.25f, 1e-6f);
    float pdf = 0;
    const Vec2 p = d.sample(Vec2(0.9f, 0.625f), &pdf);
    EXPECT_NEAR(p.x, (1 + 0.9f) / 2, 1e-6f);
    EXPECT_NEAR(p.y, (1 + 0.25f) / 2, 1e-6f);
    EXPECT_FLOAT_EQ(pdf, cell.probability * 4);
}

TEST(Distribution2D, AllZeroIsUniformAndBadSizesAreRefused) {
    const Distribution2D d({0, 0, 0, 0, 0, 0}, 3, 2);
    EXPECT_FLOAT_EQ(d.pdf(Vec2(0.1f, 0.9f)), 1.0f);
    EXPECT_THROW(Distribution2D({1, 2, 3}, 2, 2), std::invalid_argument);
    EXPECT_THROW(Distribution2D({}, 0, 0), std::invalid_argument);
}

// 400 000 samples of a 12 x 6 grid of random values (some cells empty) binned per cell against
// the expected counts. With at most 71 degrees of freedom the chi-square statistic exceeds 130 with
// probability below 1e-5, so a correct sampler fails this test (fixed seed) essentially never,
// while a sampler whose cell probabilities were off by 1% of the largest would exceed it.
TEST(Distribution2D, SampleHistogramPassesAChiSquareTest) {
    constexpr int kWidth = 12, kHeight = 6, kSamples = 400000;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<float> values(kWidth * kHeight);
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = i % 7 == 3 ? 0.0f : uniform(rng) * uniform(rng) * 10;
    const Distribution2D d(values, kWidth, kHeight);
    std::vector<int> counts(values.size(), 0);
    for (int i = 0; i < kSamples; ++i) {
        float pdf = 0;
        const Vec2 p = d.sample(Vec2(uniform(rng), uniform(rng)), &pdf);
        ASSERT_NEAR(pdf, d.pdf(p), 1e-4f * pdf);
        const int x = static_cast<int>(p.x * kWidth), y = static_cast<int>(p.y * kHeight);
        ++counts[static_cast<std::size_t>(y * kWidth + x)];
    }
    double total = 0;
    for (float v : values)
        total += v;
    double chiSquare = 0;
    int cells = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double expected = kSamples * values[i] / total;
        if (expected == 0) {
            EXPECT_EQ(counts[i], 0) << "an empty cell was sampled";
            continue;
        }
        chiSquare += (counts[i] - expected) * (counts[i] - expected) / expected;
        ++cells;
    }
    EXPECT_GT(cells, 60);
    EXPECT_LT(chiSquare, 130.0);
}

}  // namespace
}  // namespace lancer
