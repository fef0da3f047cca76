// Linear RGB colours: arithmetic is channel by channel.

#include <gtest/gtest.h>

#include <cmath>

#include "math/Color.h"
#include "math/Float.h"

namespace lancer {
namespace {

TEST(ColorTest, DefaultIsBlackAndOneNumberIsGrey) {
    EXPECT_TRUE(Color().isBlack());
    EXPECT_EQ(Color(0.25f), Color(0.25f, 0.25f, 0.25f));
    EXPECT_FALSE(Color(0, 0, 1e-30f).isBlack());
}

TEST(ColorTest, ArithmeticIsPerChannel) {
    const Color a(0.5f, 1, 2), b(2, 0.25f, 4);
    EXPECT_EQ(a + b, Color(2.5f, 1.25f, 6));
    EXPECT_EQ(b - a, Color(1.5f, -0.75f, 2));
    EXPECT_EQ(a * b, Color(1, 0.25f, 8));
    EXPECT_EQ(a * 4.0f, Color(2, 4, 8));
    EXPECT_EQ(4.0f * a, Color(2, 4, 8));
    EXPECT_EQ(a / 2.0f, Color(0.25f, 0.5f, 1));
    Color c = a;
    c += b;
    c *= Color(2, 4, 0.5f);
    c *= 0.5f;
    c /= 0.25f;
    EXPECT_EQ(c, Color(10, 10, 6));
}

TEST(ColorTest, Summaries) {
    const Color c(0.5f, 3, 1);
    EXPECT_EQ(c.maxComponent(), 3);
    EXPECT_EQ(c.average(), 1.5f);
    EXPECT_TRUE(c.isFinite());
    EXPECT_FALSE(Color(0, kInfinity, 0).isFinite());
    EXPECT_FALSE(Color(std::nanf(""), 0, 0).isFinite());
}

}  // namespace
}  // namespace lancer
