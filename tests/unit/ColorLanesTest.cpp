// Colour sums in SIMD lanes: each term lands in one lane, in a fixed order, so that the total is
// the same whatever the CPU or the number of terms a loop takes at a time.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "math/ColorArrays.h"
#include "math/ColorLanes.h"

namespace lancer {
namespace {

TEST(ColorLanesTest, ForEachVisitsEveryIndexOnceInItsLaneAndThePaddingOutOfRange) {
    for (std::uint32_t first : {0u, 3u}) {
        for (std::uint32_t count : {0u, 1u, 7u, 8u, 9u, 16u, 21u}) {
            const std::uint32_t last = first + count;
            std::vector<int> visits(last + ColorLanes::kPadding, 0);
            ColorLanes::forEach(
                first, last, [&](std::uint32_t lane, std::uint32_t i, bool inRange) {
                    EXPECT_EQ(lane, (i - first) % ColorLanes::kLanes) << first << " " << count;
                    EXPECT_EQ(inRange, i < last) << i;
                    ++visits[i];
                });
            // Whole groups of lanes: the indices in range, then up to the group's end.
            const std::uint32_t end =
                first + (count + ColorLanes::kPadding) / ColorLanes::kLanes * ColorLanes::kLanes;
            for (std::uint32_t i = 0; i < visits.size(); ++i)
                EXPECT_EQ(visits[i], i >= first && i < end ? 1 : 0) << first << " " << count;
        }
    }
}

TEST(ColorLanesTest, ForEachBlockVisitsTheWholeBlocksOfTheRangeEachItemInItsOwnLane) {
    constexpr std::uint32_t kLanes = ColorLanes::kLanes;
    for (std::uint32_t first : {0u, 3u, 8u, 13u}) {
        for (std::uint32_t count : {0u, 1u, 5u, 7u, 8u, 9u, 16u, 21u}) {
            const std::uint32_t last = first + count;
            std::vector<int> visits(last + 2 * kLanes, 0);
            ColorLanes::forEachBlock(
                first, last, [&](std::uint32_t block, std::uint32_t lane, bool inRange) {
                    ASSERT_LT(lane, kLanes);
                    const std::uint32_t i = block * kLanes + lane;
                    EXPECT_EQ(inRange, i >= first && i < last) << first << " " << count;
                    ++visits[i];
                });
            // Every lane of the blocks from first's to (last - 1)'s, once; none of an empty range.
            const std::uint32_t begin = first / kLanes * kLanes;
            const std::uint32_t end = count == 0 ? begin : (last + kLanes - 1) / kLanes * kLanes;
            for (std::uint32_t i = 0; i < visits.size(); ++i)
                EXPECT_EQ(visits[i], i >= begin && i < end ? 1 : 0)
                    << first << " " << count << " " << i;
        }
    }
}

TEST(ColorLanesTest, TheTotalAddsEachLanesSumInLaneOrderAndNothingPastTheLast) {
    // Terms whose sum depends on the order of the additions: 1e8 and -1e8 cancel only when they
    // meet before the small terms are rounded away.
    std::vector<float> terms(19);
    for (std::size_t i = 0; i < terms.size(); ++i)
        terms[i] = (i % 3 == 0) ? 1e8f : (i % 3 == 1 ? -1e8f : 0.75f + static_cast<float>(i));
    // What forEach reads past the last term is not added, whatever it holds.
    const std::vector<float> padding{std::numeric_limits<float>::infinity(),
                                     std::numeric_limits<float>::quiet_NaN(),
                                     1e30f,
                                     -1,
                                     2,
                                     3,
                                     4};
    ASSERT_EQ(padding.size(), ColorLanes::kPadding);
    std::vector<float> padded = terms;
    padded.insert(padded.end(), padding.begin(), padding.end());
    ColorLanes sum;
    ColorLanes::forEach(0, static_cast<std::uint32_t>(terms.size()),
                        [&](std::uint32_t lane, std::uint32_t i, bool inRange) {
                            sum.addIf(inRange, lane, padded[i], 1, 2, 0.5f);
                        });
    // The same additions by hand: lane by lane, then the lanes in order.
    float lanes[ColorLanes::kLanes] = {};
    for (std::size_t i = 0; i < terms.size(); ++i)
        lanes[i % ColorLanes::kLanes] += terms[i];
    float expected = 0;
    for (float lane : lanes)
        expected += lane;
    // Each channel's sum is the same sum of products (exact here: by 1, 2 and 0.5).
    EXPECT_EQ(sum.total(), Color(expected, 2 * expected, 0.5f * expected));
}

TEST(ColorLanesTest, AddToOneLeavesTheOtherSumUntouchedEvenByAnInfiniteTerm) {
    ColorLanes front, back;
    const float inf = std::numeric_limits<float>::infinity();
    ColorLanes::addToOne(true, true, front, back, 2, 0.5f, 2, inf, 4);
    ColorLanes::addToOne(true, false, front, back, 2, 0.25f, 8, 1, 0);
    // Out of range: to neither.
    ColorLanes::addToOne(false, true, front, back, 2, inf, 1, 1, 1);
    ColorLanes::addToOne(false, false, front, back, 2, inf, 1, 1, 1);
    EXPECT_EQ(front.total().r, 1.0f);
    EXPECT_EQ(front.total().g, inf);
    EXPECT_EQ(front.total().b, 2.0f);
    EXPECT_EQ(back.total(), Color(2, 0.25f, 0));
}

TEST(ColorArraysTest, KeepsEachChannelInItsArray) {
    ColorArrays colors;
    colors.resize(3);
    colors.set(1, Color(1, 2, 3));
    for (const std::vector<float>* channel : {&colors.r, &colors.g, &colors.b}) {
        EXPECT_EQ(channel->size(), 3u);
        EXPECT_EQ((*channel)[0], 0.0f);
        EXPECT_EQ((*channel)[2], 0.0f);
    }
    EXPECT_EQ(Color(colors.r[1], colors.g[1], colors.b[1]), Color(1, 2, 3));
}

}  // namespace
}  // namespace lancer
