// Filter importance sampling: the offsets are distributed as |filter| (chi-square), and the
// weighted samples reproduce the filter itself (a weighted histogram), for every filter.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "math/Distribution1D.h"
#include "render/Filter.h"
#include "render/FilterSampler.h"
#include "scene/FilterSettings.h"

namespace lancer {
namespace {

constexpr int kBins = 16;  // per axis, across [-radius, radius]
constexpr int kSamples = 1 << 20;

FilterSampler makeSampler(const std::string& type) {
    return FilterSampler(Filter::create(FilterSettings{type, {}}));
}

// The integral of g over the bin [a, b] by the midpoint rule, in double.
template <typename G>
double integrate(const G& g, double a, double b, int steps = 2000) {
    const double h = (b - a) / steps;
    double sum = 0;
    for (int i = 0; i < steps; ++i)
        sum += g(a + (i + 0.5) * h);
    return sum * h;
}

struct Histograms {
    std::vector<double> counts = std::vector<double>(kBins * kBins, 0);
    std::vector<double> weights = std::vector<double>(kBins * kBins, 0);
};

// kSamples offsets from uniform random points (seeded): how many land in each bin, and the sum
// of their weights there.
Histograms sampleHistograms(const FilterSampler& sampler) {
    const float r = sampler.filter().radius();
    std::mt19937 random(1234);
    std::uniform_real_distribution<float> uniform(0, 1);
    Histograms h;
    for (int i = 0; i < kSamples; ++i) {
        const Vec2 u(uniform(random), uniform(random));
        const FilterSample s = sampler.sample(u);
        EXPECT_TRUE(std::abs(s.offset.x) <= r && std::abs(s.offset.y) <= r);
        const auto bin = [&](float x) {
            return std::min(kBins - 1, static_cast<int>((x + r) / (2 * r) * kBins));
        };
        const auto index = static_cast<std::size_t>(bin(s.offset.y) * kBins + bin(s.offset.x));
        h.counts[index] += 1;
        h.weights[index] += s.weight;
    }
    return h;
}

class FilterSamplerTest : public testing::TestWithParam<std::string> {};

TEST_P(FilterSamplerTest, OffsetsAreDistributedAsTheFiltersMagnitude) {
    const FilterSampler sampler = makeSampler(GetParam());
    const Filter& f = sampler.filter();
    const double r = f.radius(), width = 2 * r / kBins;
    const auto magnitude = [&](double x) { return std::abs(f.profile(static_cast<float>(x))); };
    const double total = integrate(magnitude, -r, r, 20000);
    std::vector<double> p1(kBins);
    for (int i = 0; i < kBins; ++i)
        p1[static_cast<std::size_t>(i)] =
            integrate(magnitude, -r + i * width, -r + (i + 1) * width) / total;

    const Histograms h = sampleHistograms(sampler);
    double chiSquare = 0;
    int cells = 0;
    for (int j = 0; j < kBins; ++j)
        for (int i = 0; i < kBins; ++i) {
            const double expected =
                kSamples * p1[static_cast<std::size_t>(i)] * p1[static_cast<std::size_t>(j)];
            const double observed = h.counts[static_cast<std::size_t>(j * kBins + i)];
            if (expected < 5) {
                // Too few for the chi-square: at least nothing where the filter is zero.
                if (expected == 0) {
                    EXPECT_EQ(observed, 0);
                }
                continue;
            }
            chiSquare += (observed - expected) * (observed - expected) / expected;
            ++cells;
        }
    // 255 degrees of freedom at most: the 99.9th percentile of chi-square(255) is about 330.
    // A seeded generator: the result is the same every run.
    EXPECT_LT(chiSquare, 330.0) << cells << " cells";
}

TEST_P(FilterSamplerTest, WeightedSamplesReproduceTheFilter) {
    const FilterSampler sampler = makeSampler(GetParam());
    const Filter& f = sampler.filter();
    const double r = f.radius(), width = 2 * r / kBins;
    const auto profile = [&](double x) {
        return static_cast<double>(f.profile(static_cast<float>(x)));
    };
    const auto magnitude = [&](double x) { return std::abs(profile(x)); };
    std::vector<double> f1(kBins), magnitude1(kBins);
    for (int i = 0; i < kBins; ++i) {
        const double a = -r + i * width, b = a + width;
        f1[static_cast<std::size_t>(i)] = integrate(profile, a, b);
        magnitude1[static_cast<std::size_t>(i)] = integrate(magnitude, a, b);
    }
    const double totalMagnitude = integrate(magnitude, -r, r, 20000);

    // The sum of the weights in a bin over N estimates the filter's integral over the bin
    // (E[w 1_bin] = integral of f over the bin). Each weight is about +-A^2 (A: the integral of
    // |profile|) and lands in the bin with probability B / A^2 (B: the integral of |f| over the
    // bin), so the estimate's standard error is about sqrt(A^2 B / N).
    const Histograms h = sampleHistograms(sampler);
    double weightSum = 0;
    for (int j = 0; j < kBins; ++j)
        for (int i = 0; i < kBins; ++i) {
            const double expected =
                f1[static_cast<std::size_t>(i)] * f1[static_cast<std::size_t>(j)];
            const double estimated = h.weights[static_cast<std::size_t>(j * kBins + i)] / kSamples;
            weightSum += h.weights[static_cast<std::size_t>(j * kBins + i)];
            const double binMagnitude =
                magnitude1[static_cast<std::size_t>(i)] * magnitude1[static_cast<std::size_t>(j)];
            const double sigma =
                std::sqrt(totalMagnitude * totalMagnitude * binMagnitude / kSamples) + 1e-9;
            EXPECT_NEAR(estimated, expected, 5 * sigma) << "bin " << i << ", " << j;
        }
    // The weights average to the filter's integral, 1.
    EXPECT_NEAR(weightSum / kSamples, 1.0, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Filters, FilterSamplerTest,
                         testing::Values("box", "tent", "gaussian", "mitchell"),
                         [](const testing::TestParamInfo<std::string>& c) { return c.param; });

TEST(FilterSamplerBoxTest, TheDefaultBoxMapsThePointOntoThePixelWithWeightOne) {
    const FilterSampler box = makeSampler("box");
    for (float u : {0.0f, 0.1f, 0.25f, 0.5f, 0.75f, 0.999f, 0x1.fffffep-1f}) {
        const FilterSample s = box.sample({u, 1 - u / 2});
        EXPECT_EQ(s.weight, 1.0f);
        EXPECT_NEAR(s.offset.x, u - 0.5f, 1e-6f);
        EXPECT_NEAR(s.offset.y, 0.5f - u / 2, 1e-6f);
        EXPECT_LT(s.offset.x, 0.5f);
    }
}

TEST(FilterSamplerBoxTest, BoxesOfAnyRadiusSampleAsTheirTableToTheBit) {
    // (The sampler skips the table's search for a flat profile.)
    for (const float radius : {0.5f, 1.0f, 1.5f, 0.7f}) {
        const FilterSampler box(Filter::create(FilterSettings{"box", radius}));
        const Distribution1D table(std::vector<float>(256, box.filter().profile(0)));
        std::mt19937 random(5);
        for (int i = 0; i < 100000; ++i) {
            const float u = std::uniform_real_distribution<float>(0, 1)(random);
            const FilterSample s = box.sample({u, u});
            float density = 0;
            const float x = -radius + 2 * radius * table.sampleContinuous(u, &density);
            ASSERT_EQ(s.offset.x, x) << "radius " << radius << ", u " << u;
            const float w = box.filter().profile(x) * (2 * radius) / density;
            ASSERT_EQ(s.weight, w * w);
        }
    }
}

TEST(FilterSamplerBoxTest, MappingIsMonotonicSoStrataStayStrata) {
    const FilterSampler mitchell = makeSampler("mitchell");
    float previous = -1e9f;
    for (int i = 0; i < 4096; ++i) {
        const float x = mitchell.sample({static_cast<float>(i) / 4096, 0.5f}).offset.x;
        EXPECT_GE(x, previous);
        previous = x;
    }
}

}  // namespace
}  // namespace lancer
