// The image pyramid: exact texel centres, bilinear blends, repeat addressing, the v axis, the
// levels' filtering (power of two or not) and the choice of level from a footprint.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "TextureTestSupport.h"
#include "materials/MipMap.h"

namespace lancer {
namespace {

// Float rounding of the filter weights and of the uv arithmetic.
constexpr float kTolerance = 1e-5f;

void expectColorNear(const Color& actual, const Color& expected, float tolerance = kTolerance) {
    EXPECT_NEAR(actual.r, expected.r, tolerance);
    EXPECT_NEAR(actual.g, expected.g, tolerance);
    EXPECT_NEAR(actual.b, expected.b, tolerance);
}

// Every texel different: red counts columns, green counts rows.
Color distinctTexel(int x, int y) {
    return {static_cast<float>(x), static_cast<float>(y), 1};
}

// The uv of texel (x, y)'s centre in a level width x height (row 0 at the top, v = 0 at the
// bottom).
Vec2 centreOf(int x, int y, int width, int height) {
    return {(static_cast<float>(x) + 0.5f) / static_cast<float>(width),
            1 - (static_cast<float>(y) + 0.5f) / static_cast<float>(height)};
}

Color imageMean(const Image& image) {
    Color sum;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            sum += image.at(x, y);
    return sum / static_cast<float>(image.width() * image.height());
}

TEST(MipMapTest, TexelCentresReturnTheTexels) {
    const MipMap mipmap(test::makeImage(8, 4, distinctTexel));
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(mipmap.bilinear(0, centreOf(x, y, 8, 4)), distinctTexel(x, y))
                << "at " << x << ", " << y;
}

TEST(MipMapTest, TexelCentresOfAnOddSizedImageReturnTheTexels) {
    const MipMap mipmap(test::makeImage(3, 5, distinctTexel));
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 3; ++x)
            expectColorNear(mipmap.bilinear(0, centreOf(x, y, 3, 5)), distinctTexel(x, y));
}

TEST(MipMapTest, VZeroIsTheBottomOfTheImage) {
    const Image image = test::makeImage(2, 4, distinctTexel);
    const MipMap mipmap(image);
    // Just above v = 0: the bottom row, image row 3.
    EXPECT_EQ(mipmap.bilinear(0, {0.25f, 0.125f}), image.at(0, 3));
    // Just below v = 1: the top row, image row 0.
    EXPECT_EQ(mipmap.bilinear(0, {0.25f, 0.875f}), image.at(0, 0));
}

TEST(MipMapTest, BlendsHalfWayBetweenTexelsToTheirMean) {
    const Image image = test::makeImage(4, 4, distinctTexel);
    const MipMap mipmap(image);
    // Between the centres of texels (1, 2) and (2, 2): u = 2 / 4.
    EXPECT_EQ(mipmap.bilinear(0, {0.5f, 1 - 2.5f / 4}), (image.at(1, 2) + image.at(2, 2)) / 2);
    // Between rows 1 and 2 of column 0.
    EXPECT_EQ(mipmap.bilinear(0, {0.125f, 0.5f}), (image.at(0, 1) + image.at(0, 2)) / 2);
    // Where four texels meet: the mean of the four.
    EXPECT_EQ(mipmap.bilinear(0, {0.5f, 0.5f}),
              (image.at(1, 1) + image.at(2, 1) + image.at(1, 2) + image.at(2, 2)) / 4);
    // A quarter of the way from texel (0, 0) to texel (1, 0): weights 3/4 and 1/4.
    expectColorNear(mipmap.bilinear(0, {0.1875f, 1 - 0.125f}),
                    0.75f * image.at(0, 0) + 0.25f * image.at(1, 0));
}

TEST(MipMapTest, InterpolatesLinearlyAlongARow) {
    const MipMap mipmap(test::makeImage(4, 1, distinctTexel));
    for (int i = 0; i <= 24; ++i) {
        // From texel 0's centre to texel 3's, where red runs from 0 to 3.
        const float u = 0.125f + 0.75f * static_cast<float>(i) / 24;
        EXPECT_NEAR(mipmap.bilinear(0, {u, 0.5f}).r, 4 * u - 0.5f, kTolerance) << "u = " << u;
    }
}

TEST(MipMapTest, RepeatsOutsideTheUnitSquare) {
    const MipMap mipmap(test::makeImage(4, 4, distinctTexel));
    // Dyadic coordinates, so that adding whole numbers is exact and so must be the lookups.
    for (const Vec2 uv :
         {Vec2{0.25f, 0.3125f}, Vec2{0.59375f, 0.90625f}, Vec2{0.15625f, 0.046875f}}) {
        const Color inside = mipmap.bilinear(0, uv);
        EXPECT_EQ(mipmap.bilinear(0, {uv.x + 1, uv.y}), inside);
        EXPECT_EQ(mipmap.bilinear(0, {uv.x - 1, uv.y - 1}), inside);
        EXPECT_EQ(mipmap.bilinear(0, {uv.x + 5, uv.y - 3}), inside);
        EXPECT_EQ(mipmap.bilinear(0, {uv.x - 100, uv.y + 100}), inside);
    }
    EXPECT_EQ(mipmap.bilinear(0, {1.25f, 0.5f}), mipmap.bilinear(0, {0.25f, 0.5f}));
    EXPECT_EQ(mipmap.bilinear(0, {-0.75f, -0.5f}), mipmap.bilinear(0, {0.25f, 0.5f}));
}

TEST(MipMapTest, BlendsAcrossTheEdgesWithTheOppositeSide) {
    const Image image = test::makeImage(4, 4, distinctTexel);
    const MipMap mipmap(image);
    // u = 0 lies half-way between the last column's centre and the first's.
    EXPECT_EQ(mipmap.bilinear(0, {0, 1 - 0.125f}), (image.at(3, 0) + image.at(0, 0)) / 2);
    // v = 0 (the bottom edge) blends the bottom row with the top row.
    EXPECT_EQ(mipmap.bilinear(0, {0.125f, 0}), (image.at(0, 3) + image.at(0, 0)) / 2);
}

TEST(MipMapTest, TexelAddressesWrap) {
    const Image image = test::makeImage(4, 3, distinctTexel);
    const MipMap mipmap(image);
    EXPECT_EQ(mipmap.texel(0, -1, 0), image.at(3, 0));
    EXPECT_EQ(mipmap.texel(0, 4, 3), image.at(0, 0));
    EXPECT_EQ(mipmap.texel(0, -9, -4), image.at(3, 2));
    EXPECT_EQ(mipmap.texel(0, 13, 7), image.at(1, 1));
}

TEST(MipMapTest, NonFiniteCoordinatesDoNotFail) {
    const MipMap mipmap(test::makeImage(4, 4, distinctTexel));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();
    EXPECT_TRUE(mipmap.bilinear(0, {nan, 0.5f}).isFinite());
    EXPECT_TRUE(mipmap.bilinear(0, {infinity, -infinity}).isFinite());
    EXPECT_TRUE(mipmap.trilinear({nan, nan}, nan).isFinite());
}

// ---- The levels.

TEST(MipMapTest, HalvesDownToOneTexel) {
    const MipMap square(test::makeImage(16, 16, distinctTexel));
    ASSERT_EQ(square.levelCount(), 5);
    for (int level = 0; level < 5; ++level) {
        EXPECT_EQ(square.image(level).width(), 16 >> level);
        EXPECT_EQ(square.image(level).height(), 16 >> level);
    }
    const MipMap wide(test::makeImage(8, 2, distinctTexel));
    ASSERT_EQ(wide.levelCount(), 4);
    EXPECT_EQ(wide.image(1).width(), 4);
    EXPECT_EQ(wide.image(1).height(), 1);
    EXPECT_EQ(wide.image(3).width(), 1);
    EXPECT_EQ(wide.image(3).height(), 1);
}

TEST(MipMapTest, OddSizesRoundDown) {
    const MipMap mipmap(test::makeImage(3, 5, distinctTexel));
    ASSERT_EQ(mipmap.levelCount(), 3);
    EXPECT_EQ(mipmap.image(1).width(), 1);
    EXPECT_EQ(mipmap.image(1).height(), 2);
    EXPECT_EQ(mipmap.image(2).width(), 1);
    EXPECT_EQ(mipmap.image(2).height(), 1);
    const MipMap single(test::makeImage(1, 1, distinctTexel));
    EXPECT_EQ(single.levelCount(), 1);
}

TEST(MipMapTest, EvenSizesAverageTwoByTwoTexels) {
    const Image image = test::makeImage(4, 4, distinctTexel);
    const MipMap mipmap(image);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            EXPECT_EQ(mipmap.image(1).at(x, y),
                      (image.at(2 * x, 2 * y) + image.at(2 * x + 1, 2 * y) +
                       image.at(2 * x, 2 * y + 1) + image.at(2 * x + 1, 2 * y + 1)) /
                          4);
}

TEST(MipMapTest, OddSizesAverageTheAreaEachTexelCovers) {
    // 5 texels halve to 2, each 2.5 wide: (a + b + c/2) / 2.5 and (c/2 + d + e) / 2.5.
    const Image row = test::makeImage(5, 1, [](int x, int) { return Color(float(1 << x)); });
    const MipMap mipmap(row);
    expectColorNear(mipmap.image(1).at(0, 0), Color((1 + 2 + 4 * 0.5f) / 2.5f));
    expectColorNear(mipmap.image(1).at(1, 0), Color((4 * 0.5f + 8 + 16) / 2.5f));
    // 3 texels halve to 1: their mean.
    const MipMap column(test::makeImage(1, 3, [](int, int y) { return Color(float(1 << y)); }));
    expectColorNear(column.image(1).at(0, 0), Color(7.0f / 3));
}

TEST(MipMapTest, ConstantImageStaysConstantAtEveryLevel) {
    const Color constant(0.3f, 0.6f, 0.9f);
    for (const auto& [width, height] :
         {std::pair{16, 16}, std::pair{3, 5}, std::pair{7, 12}, std::pair{249, 250}}) {
        const MipMap mipmap(test::makeImage(width, height, [&](int, int) { return constant; }));
        for (int level = 0; level < mipmap.levelCount(); ++level) {
            const Image& image = mipmap.image(level);
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    expectColorNear(image.at(x, y), constant);
        }
    }
}

TEST(MipMapTest, CheckerboardLevelsAverageToGrey) {
    const auto checker = [](int x, int y) { return Color((x + y) % 2 == 0 ? 1.0f : 0.0f); };
    const MipMap mipmap(test::makeImage(16, 16, checker));
    for (int level = 1; level < mipmap.levelCount(); ++level) {
        const Image& image = mipmap.image(level);
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                EXPECT_EQ(image.at(x, y), Color(0.5f));
    }
    // Odd sizes too, within the checkerboard's own imbalance: 3 of 5 texels lit.
    const MipMap odd(test::makeImage(5, 7, checker));
    for (int level = 1; level < odd.levelCount(); ++level) {
        const Image& image = odd.image(level);
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                EXPECT_NEAR(image.at(x, y).r, 0.5f, 0.12f) << "level " << level;
    }
}

TEST(MipMapTest, EveryLevelKeepsTheImageMean) {
    for (const auto& [width, height] :
         {std::pair{16, 8}, std::pair{3, 5}, std::pair{13, 6}, std::pair{31, 17}}) {
        const MipMap mipmap(test::makeImage(width, height, [](int x, int y) {
            return Color(static_cast<float>((x * 7 + y * 13) % 11), static_cast<float>(x * y), 1);
        }));
        const Color mean = imageMean(mipmap.image(0));
        for (int level = 1; level < mipmap.levelCount(); ++level)
            expectColorNear(imageMean(mipmap.image(level)), mean,
                            1e-4f * (1 + mean.maxComponent()));
    }
}

// ---- Trilinear lookups.

class TrilinearTest : public testing::Test {
protected:
    // 16 x 16, so levels 16, 8, 4, 2 and 1 texels wide.
    const MipMap mipmap{test::makeImage(16, 16, [](int x, int y) {
        return Color(static_cast<float>(x * x), static_cast<float>((x + 3 * y) % 5), 1);
    })};
    const Vec2 uv{0.3f, 0.7f};
    static constexpr float kTexel = 1.0f / 16;
};

TEST_F(TrilinearTest, FootprintOfOneTexelReadsLevelZero) {
    EXPECT_EQ(mipmap.trilinear(uv, kTexel), mipmap.bilinear(0, uv));
}

TEST_F(TrilinearTest, SmallerFootprintsReadLevelZero) {
    EXPECT_EQ(mipmap.trilinear(uv, kTexel / 10), mipmap.bilinear(0, uv));
    EXPECT_EQ(mipmap.trilinear(uv, 0), mipmap.bilinear(0, uv));
    EXPECT_EQ(mipmap.trilinear(uv, -kTexel), mipmap.bilinear(0, uv));
}

TEST_F(TrilinearTest, FootprintOfFourTexelsReadsLevelTwo) {
    EXPECT_EQ(mipmap.trilinear(uv, 4 * kTexel), mipmap.bilinear(2, uv));
    EXPECT_EQ(mipmap.trilinear(uv, 2 * kTexel), mipmap.bilinear(1, uv));
    EXPECT_EQ(mipmap.trilinear(uv, 8 * kTexel), mipmap.bilinear(3, uv));
}

TEST_F(TrilinearTest, FractionalFootprintsBlendTheTwoLevels) {
    // 2^1.5 texels: half-way between levels 1 and 2.
    expectColorNear(mipmap.trilinear(uv, std::sqrt(8.0f) * kTexel),
                    (mipmap.bilinear(1, uv) + mipmap.bilinear(2, uv)) / 2, 1e-4f);
    // 2^2.25 texels: a quarter of the way from level 2 to level 3.
    expectColorNear(mipmap.trilinear(uv, std::exp2(2.25f) * kTexel),
                    0.75f * mipmap.bilinear(2, uv) + 0.25f * mipmap.bilinear(3, uv), 1e-4f);
}

TEST_F(TrilinearTest, FootprintsAsLargeAsTheImageReadTheMean) {
    const Color mean = imageMean(mipmap.image(0));
    expectColorNear(mipmap.trilinear(uv, 1), mean, 1e-4f);
    expectColorNear(mipmap.trilinear(uv, 1000), mean, 1e-4f);
    expectColorNear(mipmap.trilinear(uv, std::numeric_limits<float>::infinity()), mean, 1e-4f);
}

TEST(MipMapTrilinearTest, NonSquareImagesMeasureFootprintsInTheLargerSide) {
    // 8 x 2: a footprint of 2 texels along the 8-texel side reads level 1 (4 x 1).
    const MipMap mipmap(test::makeImage(8, 2, distinctTexel));
    const Vec2 uv{0.4f, 0.2f};
    EXPECT_EQ(mipmap.trilinear(uv, 2.0f / 8), mipmap.bilinear(1, uv));
}

}  // namespace
}  // namespace lancer
