// The sRGB transfer function used for 8-bit output (IEC 61966-2-1).

#include <gtest/gtest.h>

#include <limits>
#include <ostream>

#include "math/Srgb.h"

namespace lancer {
namespace {

// Float evaluation of pow and the affine terms: a few units in the last place of values <= 1.
constexpr float kTolerance = 1e-6f;

struct SrgbPair {
    float linear;
    float encoded;  // computed in double precision from the IEC formula
};

void PrintTo(const SrgbPair& pair, std::ostream* out) {
    *out << "linear " << pair.linear << " encoded " << pair.encoded;
}

class SrgbKnownValueTest : public testing::TestWithParam<SrgbPair> {};

TEST_P(SrgbKnownValueTest, EncodesToTheStandardValue) {
    EXPECT_NEAR(linearToSrgb(GetParam().linear), GetParam().encoded, kTolerance);
}

TEST_P(SrgbKnownValueTest, DecodesToTheStandardValue) {
    EXPECT_NEAR(srgbToLinear(GetParam().encoded), GetParam().linear, kTolerance);
}

INSTANTIATE_TEST_SUITE_P(
    Standard, SrgbKnownValueTest,
    testing::Values(SrgbPair{0, 0}, SrgbPair{1, 1},
                    SrgbPair{0.001f, 0.01292f},              // linear segment: 12.92 v
                    SrgbPair{0.0031308f, 0.040449936f},      // the breakpoint
                    SrgbPair{0.18f, 0.46135612950044164f},   // middle grey
                    SrgbPair{0.5f, 0.7353569830524495f},     // 1.055 * 0.5^(1/2.4) - 0.055
                    SrgbPair{0.21404114048223255f, 0.5f}));  // the linear value of code 0.5

TEST(SrgbTest, RoundTripsEveryEightBitCode) {
    for (int code = 0; code <= 255; ++code) {
        const float encoded = static_cast<float>(code) / 255;
        EXPECT_NEAR(linearToSrgb(srgbToLinear(encoded)), encoded, kTolerance) << "code " << code;
    }
}

TEST(SrgbTest, RoundTripsLinearValues) {
    for (int i = 0; i <= 1000; ++i) {
        const float linear = static_cast<float>(i) / 1000;
        // Relative: the encoding is steep near 0, so compare in proportion to the value.
        EXPECT_NEAR(srgbToLinear(linearToSrgb(linear)), linear, kTolerance * (linear + 1e-3f))
            << "linear " << linear;
    }
}

TEST(SrgbTest, EncodingIsIncreasing) {
    float previous = linearToSrgb(0);
    for (int i = 1; i <= 10000; ++i) {
        const float encoded = linearToSrgb(static_cast<float>(i) / 10000);
        EXPECT_GT(encoded, previous) << "at " << i;
        previous = encoded;
    }
}

// The 8-bit encoding shared by the 8-bit image files and the window.
TEST(SrgbTest, EightBitEncodingClampsRoundsAndMapsNanToBlack) {
    EXPECT_EQ(linearToSrgb8(0), 0);
    EXPECT_EQ(linearToSrgb8(1), 255);
    EXPECT_EQ(linearToSrgb8(-1), 0);
    EXPECT_EQ(linearToSrgb8(1e30f), 255);
    EXPECT_EQ(linearToSrgb8(std::numeric_limits<float>::quiet_NaN()), 0);
    // sRGB(0.5) = 0.7354: 187.5 rounds to 188. sRGB(0.2) = 0.4845: 123.5 rounds to 124.
    EXPECT_EQ(linearToSrgb8(0.5f), 188);
    EXPECT_EQ(linearToSrgb8(0.2f), 124);
}

}  // namespace
}  // namespace lancer
