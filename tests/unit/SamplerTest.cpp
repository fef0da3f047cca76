// The per-pixel sampler: deterministic, in range, and stratified (correlated multi-jitter).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "math/Vec2.h"
#include "render/Sampler.h"

namespace lancer {
namespace {

// The dimensions of one sample that the tests look at: 2D points and 1D values, interleaved as
// a renderer asks for them (pixel position, lens, light...).
constexpr int kDimensionsChecked = 3;

// Which of `count` equal strata of [0, 1) the value falls in (exact: a float times a small
// integer is exact in double).
int stratumOf(float value, int count) {
    return static_cast<int>(std::floor(static_cast<double>(value) * count));
}

// All the points of one pixel for one 2D dimension: sample i's point is the `dimension`-th 2D
// point drawn after startSample(i) (drawing 2D points only).
std::vector<Vec2> pixelPoints(std::uint64_t seed, int x, int y, int spp, int dimension) {
    Sampler sampler(seed, x, y, spp);
    std::vector<Vec2> points;
    for (int i = 0; i < spp; ++i) {
        sampler.startSample(i);
        Vec2 p;
        for (int d = 0; d <= dimension; ++d)
            p = sampler.get2D();
        points.push_back(p);
    }
    return points;
}

std::vector<float> pixelValues(std::uint64_t seed, int x, int y, int spp, int dimension) {
    Sampler sampler(seed, x, y, spp);
    std::vector<float> values;
    for (int i = 0; i < spp; ++i) {
        sampler.startSample(i);
        float v = 0;
        for (int d = 0; d <= dimension; ++d)
            v = sampler.get1D();
        values.push_back(v);
    }
    return values;
}

// True when each of `count` strata holds exactly one of the values.
testing::AssertionResult oneInEachStratum(const std::vector<int>& strata, int count) {
    std::vector<int> hits(static_cast<std::size_t>(count), 0);
    for (int s : strata) {
        if (s < 0 || s >= count)
            return testing::AssertionFailure()
                   << "stratum " << s << " outside [0, " << count << ")";
        if (++hits[static_cast<std::size_t>(s)] > 1)
            return testing::AssertionFailure()
                   << "stratum " << s << " of " << count << " holds two points";
    }
    return testing::AssertionSuccess();
}

TEST(SamplerTest, SameSeedPixelAndSampleGiveTheSameNumbers) {
    Sampler a(7, 12, 34, 16), b(7, 12, 34, 16);
    for (int i = 0; i < 16; ++i) {
        a.startSample(i);
        b.startSample(i);
        for (int d = 0; d < 4; ++d) {
            EXPECT_EQ(a.get2D(), b.get2D());
            EXPECT_EQ(a.get1D(), b.get1D());
        }
    }
}

TEST(SamplerTest, ASampleDoesNotDependOnTheSamplesBeforeIt) {
    // Threads may render a pixel's samples in any order, or only some of them.
    Sampler inOrder(3, 5, 9, 64), direct(3, 5, 9, 64);
    for (int i = 0; i < 64; ++i) {
        inOrder.startSample(i);
        const Vec2 p = inOrder.get2D();
        const float v = inOrder.get1D();
        direct.startSample(63 - i);  // leave the sampler in another state
        direct.get2D();
        direct.startSample(i);
        EXPECT_EQ(direct.get2D(), p);
        EXPECT_EQ(direct.get1D(), v);
    }
}

TEST(SamplerTest, DifferentPixelsAndSeedsGiveDifferentNumbers) {
    const std::vector<Vec2> reference = pixelPoints(0, 10, 10, 16, 0);
    for (const std::vector<Vec2>& other :
         {pixelPoints(0, 11, 10, 16, 0), pixelPoints(0, 10, 11, 16, 0),
          pixelPoints(1, 10, 10, 16, 0), pixelPoints(0, 10, 10, 16, 1)}) {
        int same = 0;
        for (std::size_t i = 0; i < reference.size(); ++i)
            same += reference[i] == other[i] ? 1 : 0;
        EXPECT_EQ(same, 0);
    }
}

TEST(SamplerTest, ValuesAreInTheHalfOpenUnitInterval) {
    for (int spp : {1, 3, 16, 100}) {
        for (int pixel = 0; pixel < 200; ++pixel) {
            Sampler sampler(42, pixel, 2 * pixel, spp);
            for (int i = 0; i < spp; ++i) {
                sampler.startSample(i);
                for (int d = 0; d < kDimensionsChecked; ++d) {
                    const Vec2 p = sampler.get2D();
                    const float v = sampler.get1D();
                    ASSERT_TRUE(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)
                        << p.x << ", " << p.y << " (spp " << spp << ")";
                    ASSERT_TRUE(v >= 0 && v < 1) << v << " (spp " << spp << ")";
                }
            }
        }
    }
}

// Square sample counts n x n over many pixels: the multi-jitter properties.
class SamplerStratificationTest : public testing::TestWithParam<int> {
protected:
    static constexpr int kPixelsPerSide = 48;
};

TEST_P(SamplerStratificationTest, EachCellOfTheGridHoldsOnePoint) {
    const int n = GetParam(), spp = n * n;
    for (int y = 0; y < kPixelsPerSide; ++y) {
        for (int x = 0; x < kPixelsPerSide; ++x) {
            for (int dimension = 0; dimension < kDimensionsChecked; ++dimension) {
                std::vector<int> cells, columns, rows;
                for (const Vec2& p : pixelPoints(9, x, y, spp, dimension)) {
                    cells.push_back(stratumOf(p.y, n) * n + stratumOf(p.x, n));
                    columns.push_back(stratumOf(p.x, spp));
                    rows.push_back(stratumOf(p.y, spp));
                }
                ASSERT_TRUE(oneInEachStratum(cells, spp))
                    << "n x n cells, pixel " << x << "," << y << " dimension " << dimension;
                ASSERT_TRUE(oneInEachStratum(columns, spp))
                    << "x strata, pixel " << x << "," << y << " dimension " << dimension;
                ASSERT_TRUE(oneInEachStratum(rows, spp))
                    << "y strata, pixel " << x << "," << y << " dimension " << dimension;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SquareCounts, SamplerStratificationTest,
                         testing::Values(1, 2, 3, 4, 5, 8, 16),
                         [](const testing::TestParamInfo<int>& count) {
                             return "Spp" + std::to_string(count.param * count.param);
                         });

class Sampler1DStratificationTest : public testing::TestWithParam<int> {};

TEST_P(Sampler1DStratificationTest, EachStratumHoldsOneValue) {
    const int spp = GetParam();
    for (int pixel = 0; pixel < 2000; ++pixel) {
        for (int dimension = 0; dimension < kDimensionsChecked; ++dimension) {
            std::vector<int> strata;
            for (float v : pixelValues(5, pixel % 61, pixel / 61, spp, dimension))
                strata.push_back(stratumOf(v, spp));
            ASSERT_TRUE(oneInEachStratum(strata, spp))
                << "pixel " << pixel << " dimension " << dimension;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Counts, Sampler1DStratificationTest,
                         testing::Values(1, 2, 3, 7, 16, 64, 100, 256),
                         [](const testing::TestParamInfo<int>& count) {
                             return "Spp" + std::to_string(count.param);
                         });

}  // namespace
}  // namespace lancer
