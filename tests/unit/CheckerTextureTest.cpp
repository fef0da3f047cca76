// The checker texture: even where floor(u / scale) + floor(v / scale) is even, in the surface's uv.

#include <gtest/gtest.h>

#include <ostream>

#include "geometry/Hit.h"
#include "materials/CheckerTexture.h"

namespace lancer {
namespace {

const Color kEven(0.9f, 0.8f, 0.7f), kOdd(0.1f, 0.2f, 0.3f);

Color at(const CheckerTexture& checker, float u, float v) {
    Hit hit;
    hit.setUv({u, v});
    return checker.evaluate(hit);
}

struct CheckerCase {
    float scale, u, v;
    bool even;
};

void PrintTo(const CheckerCase& c, std::ostream* out) {
    *out << "scale " << c.scale << " at (" << c.u << ", " << c.v << ")";
}

class CheckerTextureTest : public testing::TestWithParam<CheckerCase> {};

TEST_P(CheckerTextureTest, ColourFollowsTheParityOfTheSquare) {
    const CheckerCase& c = GetParam();
    const CheckerTexture checker(kEven, kOdd, c.scale);
    EXPECT_EQ(at(checker, c.u, c.v), c.even ? kEven : kOdd);
}

// Values exactly representable in float, so that each square is unambiguous.
INSTANTIATE_TEST_SUITE_P(
    Squares, CheckerTextureTest,
    testing::Values(CheckerCase{1, 0.5f, 0.5f, true},   // square (0, 0)
                    CheckerCase{1, 1.5f, 0.5f, false},  // (1, 0)
                    CheckerCase{1, 0.5f, 1.5f, false},  // (0, 1)
                    CheckerCase{1, 1.5f, 1.5f, true},   // (1, 1)
                    CheckerCase{1, 0, 0, true},         // corners belong to the square above
                    CheckerCase{1, 1, 0, false},
                    CheckerCase{1, 0.99999994f, 0, true},  // the last float before the edge
                    // Negative coordinates: floor, not truncation towards zero.
                    CheckerCase{1, -0.5f, 0.5f, false},    // (-1, 0)
                    CheckerCase{1, -0.5f, -0.5f, true},    // (-1, -1)
                    CheckerCase{1, -1.5f, 0.5f, true},     // (-2, 0)
                    CheckerCase{1, -1, 0.25f, false},      // (-1, 0)
                    CheckerCase{1, -3.25f, -7.75f, true},  // (-4, -8)
                    // Other scales.
                    CheckerCase{0.25f, 0.3f, 0.1f, false},  // (1, 0)
                    CheckerCase{0.25f, 0.6f, 0.6f, true},   // (2, 2)
                    CheckerCase{4, 3.5f, -0.5f, false},     // (0, -1)
                    CheckerCase{4, 9, 17, true},            // (2, 4)
                    // Far from the origin, where float spacing is coarse.
                    CheckerCase{1, 1e6f + 0.5f, 0.5f, true},          // (1000000, 0)
                    CheckerCase{1, 1e6f + 1.5f, 0.5f, false},         // (1000001, 0)
                    CheckerCase{1, 16777215, 3, true},                // (2^24 - 1, 3)
                    CheckerCase{1, -16777215, 0.5f, false},           // (-(2^24 - 1), 0)
                    CheckerCase{2, 1e7f, 1e7f, true},                 // (5000000, 5000000)
                    CheckerCase{0.5f, -123456.5f, 654321.25f, false}  // (-246913, 1308642)
                    ));

}  // namespace
}  // namespace lancer
