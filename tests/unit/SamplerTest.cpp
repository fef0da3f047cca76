// The per-pixel sampler (padded Owen-scrambled Sobol): deterministic, in range, stratified for
// every power-of-two prefix of a pixel's samples, and decorrelated between pixels and between the
// requests of one sample.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "math/Vec2.h"
#include "sampling/Sampler.h"

namespace lancer {
namespace {

// The 2D requests that the tests look at: the pixel position, the lens, a light... The
// renderer interleaves 1D requests with them; pointsOf() does too, to show that they do not
// disturb each other.
constexpr int kRequestsChecked = 4;

// Which of `count` equal strata of [0, 1) the value falls in (exact: a float times a power of
// two is exact).
int stratumOf(float value, int count) {
    return static_cast<int>(std::floor(static_cast<double>(value) * count));
}

// The points of samples 0 .. count-1 of one pixel for one 2D request: sample i's point is the
// `request`-th 2D point drawn after startSample(i), with a 1D value drawn before each.
std::vector<Vec2> pointsOf(std::uint64_t seed, int x, int y, int count, int request) {
    Sampler sampler(seed, x, y);
    std::vector<Vec2> points;
    for (int i = 0; i < count; ++i) {
        sampler.startSample(i);
        Vec2 p;
        for (int r = 0; r <= request; ++r) {
            sampler.get1D();
            p = sampler.get2D();
        }
        points.push_back(p);
    }
    return points;
}

// The values of samples 0 .. count-1 for the `request`-th 1D request, 2D points drawn between.
std::vector<float> valuesOf(std::uint64_t seed, int x, int y, int count, int request) {
    Sampler sampler(seed, x, y);
    std::vector<float> values;
    for (int i = 0; i < count; ++i) {
        sampler.startSample(i);
        float v = 0;
        for (int r = 0; r <= request; ++r) {
            sampler.get2D();
            v = sampler.get1D();
        }
        values.push_back(v);
    }
    return values;
}

// True when each of `count` strata holds exactly one of the values.
testing::AssertionResult oneInEachStratum(const std::vector<int>& strata, int count) {
    if (strata.size() != static_cast<std::size_t>(count))
        return testing::AssertionFailure() << strata.size() << " values for " << count << " strata";
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

// True when the points hold one point in each 2^k x 2^(m-k) elementary interval of the unit
// square for every k = 0..m, where 2^m is their count: a (0, m, 2)-net.
testing::AssertionResult isZeroNet(const std::vector<Vec2>& points) {
    int m = 0;
    while ((std::size_t{1} << m) < points.size())
        ++m;
    const int count = 1 << m;
    for (int k = 0; k <= m; ++k) {
        const int columns = 1 << k, rows = count / columns;
        std::vector<int> cells;
        for (const Vec2& p : points)
            cells.push_back(stratumOf(p.y, rows) * columns + stratumOf(p.x, columns));
        if (testing::AssertionResult r = oneInEachStratum(cells, count); !r)
            return r << " (" << columns << " x " << rows << " intervals)";
    }
    return testing::AssertionSuccess();
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    const double n = static_cast<double>(a.size());
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ma += a[i] / n;
        mb += b[i] / n;
    }
    double ab = 0, aa = 0, bb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ab += (a[i] - ma) * (b[i] - mb);
        aa += (a[i] - ma) * (a[i] - ma);
        bb += (b[i] - mb) * (b[i] - mb);
    }
    return ab / std::sqrt(aa * bb);
}

TEST(SamplerTest, SameSeedPixelAndSampleGiveTheSameNumbers) {
    Sampler a(7, 12, 34), b(7, 12, 34);
    for (int i = 0; i < 16; ++i) {
        a.startSample(i);
        b.startSample(i);
        for (int d = 0; d < 4; ++d) {
            EXPECT_EQ(a.get2D(), b.get2D());
            EXPECT_EQ(a.get1D(), b.get1D());
        }
    }
}

TEST(SamplerTest, APointPassedOverLeavesTheRequestsAfterItTheirPoints) {
    // (A pinhole camera's lens sample is passed over.)
    Sampler drawn(7, 12, 34), skipped(7, 12, 34);
    for (int i = 0; i < 16; ++i) {
        drawn.startSample(i);
        skipped.startSample(i);
        EXPECT_EQ(drawn.get2D(), skipped.get2D());
        drawn.get2D();
        skipped.skip();
        EXPECT_EQ(drawn.get2D(), skipped.get2D());
        EXPECT_EQ(drawn.get1D(), skipped.get1D());
    }
}

TEST(SamplerTest, AValuePassedOverLeavesTheRequestsAfterItTheirNumbers) {
    // (The path tracer passes over the numbers a bounce does not read: the light choice with one
    // light, the lobe choice of a single lobe, Russian roulette before it starts.)
    Sampler drawn(7, 12, 34), skipped(7, 12, 34);
    for (int i = 0; i < 16; ++i) {
        drawn.startSample(i);
        skipped.startSample(i);
        drawn.get1D();
        skipped.skip();
        EXPECT_EQ(drawn.get2D(), skipped.get2D());
        drawn.get1D();
        skipped.skip();
        EXPECT_EQ(drawn.get1D(), skipped.get1D());
    }
}

TEST(SamplerTest, ARequestPassedOverByOneSampleIsDrawnByTheNext) {
    // (Requests are remembered by the first sample that makes them; a skipped one has no seeds.)
    // The first sample passes over every point and every other value; the next ones draw them.
    Sampler mixed(7, 12, 34), drawn(7, 12, 34);
    mixed.startSample(0);
    drawn.startSample(0);
    for (int request = 0; request < 300; ++request) {  // past the requests remembered too
        mixed.skip();
        drawn.get2D();
        if (request % 2 == 0) {
            EXPECT_EQ(mixed.get1D(), drawn.get1D());
        } else {
            mixed.skip();
            drawn.get1D();
        }
    }
    for (int i = 1; i < 4; ++i) {
        mixed.startSample(i);
        Sampler fresh(7, 12, 34);
        fresh.startSample(i);
        for (int request = 0; request < 300; ++request) {
            EXPECT_EQ(mixed.get2D(), fresh.get2D());
            EXPECT_EQ(mixed.get1D(), fresh.get1D());
        }
    }
}

TEST(SamplerTest, ASampleDoesNotDependOnTheSamplesBeforeIt) {
    // Threads may render a pixel's samples in any order, or only some of them.
    Sampler inOrder(3, 5, 9), direct(3, 5, 9);
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

TEST(SamplerTest, DifferentPixelsSeedsAndRequestsGiveDifferentNumbers) {
    const std::vector<Vec2> reference = pointsOf(0, 10, 10, 16, 0);
    for (const std::vector<Vec2>& other :
         {pointsOf(0, 11, 10, 16, 0), pointsOf(0, 10, 11, 16, 0), pointsOf(1, 10, 10, 16, 0),
          pointsOf(0, 10, 10, 16, 1)}) {
        int same = 0;
        for (std::size_t i = 0; i < reference.size(); ++i)
            same += reference[i] == other[i] ? 1 : 0;
        EXPECT_EQ(same, 0);
    }
}

TEST(SamplerTest, ValuesAreInTheHalfOpenUnitInterval) {
    for (int pixel = 0; pixel < 200; ++pixel) {
        Sampler sampler(42, pixel, 2 * pixel);
        // Small indices, and large ones whose scrambled bits are all near 1.
        for (int i : {0, 1, 2, 3, 100, 4095, 65535, 1 << 20, (1 << 30) - 1}) {
            sampler.startSample(i);
            for (int d = 0; d < kRequestsChecked; ++d) {
                const Vec2 p = sampler.get2D();
                const float v = sampler.get1D();
                ASSERT_TRUE(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)
                    << p.x << ", " << p.y << " (sample " << i << ")";
                ASSERT_TRUE(v >= 0 && v < 1) << v << " (sample " << i << ")";
            }
        }
    }
}

// n x n samples for n = 1, 2, 4, 8, 16, over many pixels: each of the n x n cells of the pixel
// holds one, in the pixel-position request and in every later 2D request.
class SamplerGridTest : public testing::TestWithParam<int> {
protected:
    static constexpr int kPixelsPerSide = 24;
};

TEST_P(SamplerGridTest, EachCellOfTheGridHoldsOnePoint) {
    const int n = GetParam(), count = n * n;
    for (int y = 0; y < kPixelsPerSide; ++y)
        for (int x = 0; x < kPixelsPerSide; ++x)
            for (int request = 0; request < kRequestsChecked; ++request) {
                std::vector<int> cells;
                for (const Vec2& p : pointsOf(9, x, y, count, request))
                    cells.push_back(stratumOf(p.y, n) * n + stratumOf(p.x, n));
                ASSERT_TRUE(oneInEachStratum(cells, count))
                    << n << " x " << n << " cells, pixel " << x << "," << y << ", request "
                    << request;
            }
}

INSTANTIATE_TEST_SUITE_P(PowersOfTwo, SamplerGridTest, testing::Values(1, 2, 4, 8, 16),
                         [](const testing::TestParamInfo<int>& n) {
                             return "Spp" + std::to_string(n.param * n.param);
                         });

// Adaptive sampling stops anywhere: every power-of-two prefix of a pixel's samples must be
// stratified, in every elementary interval, not only the whole set.
TEST(SamplerTest, EveryPowerOfTwoPrefixIsAZeroNet) {
    constexpr int kCount = 1024;
    for (int pixel = 0; pixel < 64; ++pixel)
        for (int request = 0; request < kRequestsChecked; ++request) {
            const std::vector<Vec2> points = pointsOf(11, pixel % 8, pixel / 8, kCount, request);
            for (int prefix = 1; prefix <= kCount; prefix *= 2)
                ASSERT_TRUE(isZeroNet({points.begin(), points.begin() + prefix}))
                    << "the first " << prefix << " samples of pixel " << pixel << ", request "
                    << request;
        }
}

TEST(SamplerTest, EveryPowerOfTwoPrefixOfA1DRequestIsStratified) {
    constexpr int kCount = 256;
    for (int pixel = 0; pixel < 500; ++pixel)
        for (int request = 0; request < kRequestsChecked; ++request) {
            const std::vector<float> values = valuesOf(5, pixel % 25, pixel / 25, kCount, request);
            for (int prefix = 1; prefix <= kCount; prefix *= 2) {
                std::vector<int> strata;
                for (int i = 0; i < prefix; ++i)
                    strata.push_back(stratumOf(values[static_cast<std::size_t>(i)], prefix));
                ASSERT_TRUE(oneInEachStratum(strata, prefix))
                    << "the first " << prefix << " samples of pixel " << pixel << ", request "
                    << request;
            }
        }
}

// Neighbouring pixels' samples must not move together (the old failure of a pattern shared by
// every pixel: structured aliasing instead of noise), nor two requests of one sample (the light
// sample following the pixel position).
TEST(SamplerTest, NeighbouringPixelsAndRequestsAreUncorrelated) {
    constexpr int kSide = 64;  // 64 x 64 pixel pairs
    // A correlation of N independent pairs has a standard deviation of 1/sqrt(N); 4 of them.
    const double bound = 4 / std::sqrt(static_cast<double>(kSide * kSide));
    for (int sample : {0, 1, 5}) {
        std::vector<double> here, right, below, lens;
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x) {
                const auto firstX = [&](int px, int py, int request) {
                    Sampler sampler(3, px, py);
                    sampler.startSample(sample);
                    Vec2 p;
                    for (int r = 0; r <= request; ++r)
                        p = sampler.get2D();
                    return static_cast<double>(p.x);
                };
                here.push_back(firstX(x, y, 0));
                right.push_back(firstX(x + 1, y, 0));
                below.push_back(firstX(x, y + 1, 0));
                lens.push_back(firstX(x, y, 1));
            }
        EXPECT_LT(std::abs(correlation(here, right)), bound) << "sample " << sample;
        EXPECT_LT(std::abs(correlation(here, below)), bound) << "sample " << sample;
        EXPECT_LT(std::abs(correlation(here, lens)), bound) << "sample " << sample;
    }
}

// Within one pixel, the x of one request and the x of the next are independent across the
// samples (each request has its own shuffle of the sample index).
TEST(SamplerTest, RequestsOfOnePixelAreUncorrelatedAcrossSamples) {
    constexpr int kCount = 4096;
    const double bound = 4 / std::sqrt(static_cast<double>(kCount));
    const std::vector<Vec2> first = pointsOf(17, 3, 4, kCount, 0);
    const std::vector<Vec2> second = pointsOf(17, 3, 4, kCount, 1);
    std::vector<double> a, b, c;
    for (int i = 0; i < kCount; ++i) {
        a.push_back(first[static_cast<std::size_t>(i)].x);
        b.push_back(second[static_cast<std::size_t>(i)].x);
        c.push_back(second[static_cast<std::size_t>(i)].y);
    }
    EXPECT_LT(std::abs(correlation(a, b)), bound);
    EXPECT_LT(std::abs(correlation(a, c)), bound);
}

// The numbers of one sample: `count` requests, a 1D one wherever (request + index) % 3 == 0 and
// 2D ones elsewhere, so that consecutive samples make different kinds of request at a position.
std::vector<float> requestsOfSample(Sampler& sampler, int index, int count) {
    sampler.startSample(index);
    std::vector<float> numbers;
    for (int request = 0; request < count; ++request) {
        if ((request + index) % 3 == 0) {
            numbers.push_back(sampler.get1D());
        } else {
            const Vec2 p = sampler.get2D();
            numbers.insert(numbers.end(), {p.x, p.y});
        }
    }
    return numbers;
}

// The sampler keeps the scramble seeds of a pixel's requests from one sample to the next; a
// sample's numbers must still be those of a fresh sampler, whatever the samples before it asked
// for (more requests than are kept, requests of another kind at the same position).
TEST(SamplerTest, ManyRequestsOfEitherKindDoNotDependOnEarlierSamples) {
    constexpr int kRequests = 400;
    Sampler reused(9, 7, 2);
    for (int index = 0; index < 8; ++index) {
        const std::vector<float> numbers = requestsOfSample(reused, index, kRequests + index * 40);
        Sampler fresh(9, 7, 2);
        EXPECT_EQ(numbers, requestsOfSample(fresh, index, kRequests + index * 40))
            << "sample " << index;
    }
}

// Every image depends on these numbers: a change to the hashing or the scrambling, even one that
// keeps the sampler's properties, changes every render (and the references compared against).
// The values are those of the first implementation; exact, as a float's bits are.
TEST(SamplerTest, KeepsItsNumbers) {
    struct Expected {
        int index;
        Vec2 first;
        float value;
        Vec2 second;
    };
    const Expected expected[] = {
        {0, {0x1.ce8ebp-2f, 0x1.8a8094p-2f}, 0x1.992b22p-1f, {0x1.8d6d54p-2f, 0x1.b41e5p-4f}},
        {1, {0x1.3e361p-1f, 0x1.8cab58p-1f}, 0x1.e0e6p-4f, {0x1.ec91eap-1f, 0x1.d759f2p-1f}},
        {5, {0x1.c96bd8p-1f, 0x1.3424e8p-1f}, 0x1.c48618p-3f, {0x1.5ca382p-1f, 0x1.072cb8p-1f}},
        {1000, {0x1.62f9b8p-1f, 0x1.ab259p-1f}, 0x1.323712p-1f, {0x1.aac81p-3f, 0x1.1f87b2p-1f}},
        {123456789,
         {0x1.c43194p-1f, 0x1.1513a2p-1f},
         0x1.7f7572p-1f,
         {0x1.fb32cep-1f, 0x1.6818eap-1f}},
    };
    for (const Expected& e : expected) {
        Sampler sampler(42, 3, 5);
        sampler.startSample(e.index);
        const Vec2 first = sampler.get2D();
        const float value = sampler.get1D();
        const Vec2 second = sampler.get2D();
        EXPECT_EQ(first.x, e.first.x) << "sample " << e.index;
        EXPECT_EQ(first.y, e.first.y) << "sample " << e.index;
        EXPECT_EQ(value, e.value) << "sample " << e.index;
        EXPECT_EQ(second.x, e.second.x) << "sample " << e.index;
        EXPECT_EQ(second.y, e.second.y) << "sample " << e.index;
    }
}

}  // namespace
}  // namespace lancer
