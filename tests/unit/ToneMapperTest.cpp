#include "render/ToneMapper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace lancer {
namespace {

// The contract's curves in double precision; the operators compute in float, so they agree to
// a few float roundings of values in [0, 1] (1e-6).
constexpr double kFloatTolerance = 1e-6;

double aces(double c) {
    return c * (2.51 * c + 0.03) / (c * (2.43 * c + 0.59) + 0.14);
}

TEST(ToneMapper, ClampKeepsRadianceUpToOneAndClampsAbove) {
    const ToneMapper clamp(0, "clamp");
    EXPECT_EQ(clamp.display(Color(0.25f, 0.5f, 1.0f)), Color(0.25f, 0.5f, 1.0f));
    EXPECT_EQ(clamp.display(Color(1.5f, 3, 1e30f)), Color(1));
}

TEST(ToneMapper, ReinhardIsCOverOnePlusC) {
    const Color mapped = ToneMapper(0, "reinhard").display(Color(0.25f, 1, 3));
    EXPECT_NEAR(mapped.r, 0.2, kFloatTolerance);
    EXPECT_NEAR(mapped.g, 0.5, kFloatTolerance);
    EXPECT_NEAR(mapped.b, 0.75, kFloatTolerance);
    // Never reaches 1 but at the top of the float range.
    EXPECT_LT(ToneMapper(0, "reinhard").display(Color(1000)).r, 1.0f);
}

TEST(ToneMapper, AcesIsNarkowiczsFitClampedToOne) {
    const ToneMapper mapper(0, "aces");
    for (const double c : {0.01, 0.18, 0.5, 1.0, 2.0})
        EXPECT_NEAR(mapper.display(Color(static_cast<float>(c))).g, aces(c), kFloatTolerance) << c;
    // The fit exceeds 1 from about c = 10 on: clamped.
    ASSERT_GT(aces(20), 1);
    EXPECT_EQ(mapper.display(Color(20)).r, 1.0f);
}

TEST(ToneMapper, ExposureScalesBeforeTheOperator) {
    // 0.25 * 2^2 = 1: Reinhard gives 1/2; 2^-1 of 2 is 1 as well.
    EXPECT_NEAR(ToneMapper(2, "reinhard").display(Color(0.25f)).r, 0.5, kFloatTolerance);
    EXPECT_NEAR(ToneMapper(-1, "aces").display(Color(2)).r, aces(1), kFloatTolerance);
    EXPECT_EQ(ToneMapper(3, "clamp").exposed(Color(0.5f, 2, 10)), Color(4, 16, 80));
}

TEST(ToneMapper, EveryOperatorMapsZeroNegativeAndNanToBlackAndHugeToWhite) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float huge = std::numeric_limits<float>::max();
    for (const std::string& name : ToneMapper::operators().names()) {
        const ToneMapper mapper(0, name);
        EXPECT_EQ(mapper.display(Color(0, -1, nan)), Color(0)) << name;
        // ACES overflows to infinity over infinity there: its limit is taken.
        EXPECT_EQ(mapper.display(Color(huge)), Color(1)) << name;
        EXPECT_EQ(ToneMapper(64, name).display(Color(1e30f)), Color(1)) << name;
    }
}

TEST(ToneMapper, MapForOutputExposesLinearOutputsAndMapsEightBitOnes) {
    Image film(2, 1);
    film.at(0, 0) = Color(0.5f);
    film.at(1, 0) = Color(3);
    const ToneMapper mapper(1, "reinhard");
    Image linear = film;
    mapper.mapForOutput(linear, true);
    EXPECT_EQ(linear.at(0, 0), Color(1));
    EXPECT_EQ(linear.at(1, 0), Color(6));  // above 1: linear outputs keep their range
    Image display = film;
    mapper.mapForOutput(display, false);
    EXPECT_NEAR(display.at(0, 0).b, 0.5, kFloatTolerance);
    EXPECT_NEAR(display.at(1, 0).b, 6.0 / 7.0, kFloatTolerance);
}

TEST(ToneMapper, UnknownOperatorSuggestsAndListsTheValidOnes) {
    try {
        ToneMapper(0, "reinhardt");
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(),
                     "unknown tonemap \"reinhardt\" (did you mean \"reinhard\"?); expected "
                     "\"clamp\", \"reinhard\" or \"aces\"");
    }
}

TEST(ToneMapper, DefaultShowsTheFilmAsItIs) {
    const ToneMapper plain;
    EXPECT_EQ(plain.exposed(Color(7)), Color(7));
    EXPECT_EQ(plain.display(Color(0.3f, 7, 0)), Color(0.3f, 1, 0));
}

}  // namespace
}  // namespace lancer
