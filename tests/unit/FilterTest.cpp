// The reconstruction filters: normalised (they integrate to 1), zero beyond their radius,
// symmetric, with the documented shapes and defaults; and the factory's errors.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "render/Filter.h"
#include "render/GaussianFilter.h"
#include "scene/FilterSettings.h"

namespace lancer {
namespace {

std::unique_ptr<Filter> makeFilter(const std::string& type, std::optional<float> radius = {}) {
    return Filter::create(FilterSettings{type, radius});
}

// The integral of the 2D filter over [-r, r]^2 by the midpoint rule on an n x n grid (in
// double; the profile's kinks at 0 and at Mitchell's |x| = r/2 fall on cell edges for even n).
double integral2D(const Filter& f, int n) {
    const double r = f.radius(), h = 2 * r / n;
    double sum = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            sum += f.evaluate(
                {static_cast<float>(-r + (i + 0.5) * h), static_cast<float>(-r + (j + 0.5) * h)});
    return sum * h * h;
}

struct FilterCase {
    std::string name;
    std::string type;
    std::optional<float> radius;
    float expectedRadius;
};

class FilterShapeTest : public testing::TestWithParam<FilterCase> {};

TEST_P(FilterShapeTest, IntegratesToOne) {
    const auto filter = makeFilter(GetParam().type, GetParam().radius);
    EXPECT_NEAR(integral2D(*filter, 400), 1.0, 1e-4);
}

TEST_P(FilterShapeTest, HasItsRadiusAndVanishesBeyondIt) {
    const auto filter = makeFilter(GetParam().type, GetParam().radius);
    const float r = GetParam().expectedRadius;
    EXPECT_FLOAT_EQ(filter->radius(), r);
    for (float beyond : {1.0001f, 1.5f, 3.0f, 100.0f}) {
        EXPECT_EQ(filter->profile(r * beyond), 0);
        EXPECT_EQ(filter->profile(-r * beyond), 0);
        EXPECT_EQ(filter->evaluate({r * beyond, 0}), 0);
        EXPECT_EQ(filter->evaluate({0, -r * beyond}), 0);
    }
}

TEST_P(FilterShapeTest, IsSymmetricSeparableAndHighestAtTheCentre) {
    const auto filter = makeFilter(GetParam().type, GetParam().radius);
    const float r = GetParam().expectedRadius;
    for (int i = 0; i <= 50; ++i) {
        const float x = r * static_cast<float>(i) / 50;
        EXPECT_EQ(filter->profile(x), filter->profile(-x));
        EXPECT_LE(filter->profile(x), filter->profile(0));
        EXPECT_EQ(filter->evaluate({x, 0.3f * r}), filter->profile(x) * filter->profile(0.3f * r));
    }
}

INSTANTIATE_TEST_SUITE_P(Filters, FilterShapeTest,
                         testing::Values(FilterCase{"BoxDefault", "box", {}, 0.5f},
                                         FilterCase{"BoxWide", "box", 1.5f, 1.5f},
                                         FilterCase{"TentDefault", "tent", {}, 1.0f},
                                         FilterCase{"TentNarrow", "tent", 0.75f, 0.75f},
                                         FilterCase{"GaussianDefault", "gaussian", {}, 1.5f},
                                         FilterCase{"GaussianWide", "gaussian", 3.0f, 3.0f},
                                         FilterCase{"MitchellDefault", "mitchell", {}, 2.0f},
                                         FilterCase{"MitchellNarrow", "mitchell", 1.0f, 1.0f}),
                         [](const testing::TestParamInfo<FilterCase>& c) { return c.param.name; });

TEST(FilterTest, BoxOfHalfAPixelIsTheAverageOverThePixel) {
    const auto box = makeFilter("box");
    EXPECT_EQ(box->evaluate({0.49f, -0.49f}), 1.0f);
    EXPECT_EQ(box->evaluate({0, 0}), 1.0f);
}

TEST(FilterTest, TentFallsLinearly) {
    const auto tent = makeFilter("tent", 2.0f);
    EXPECT_FLOAT_EQ(tent->profile(0), 0.5f);
    EXPECT_FLOAT_EQ(tent->profile(1), 0.25f);
    EXPECT_FLOAT_EQ(tent->profile(-1.5f), 0.125f);
}

TEST(FilterTest, GaussianSigmaIsAThirdOfTheRadiusAndItReachesZeroThere) {
    const auto filter = makeFilter("gaussian", 1.5f);
    const auto& gaussian = dynamic_cast<const GaussianFilter&>(*filter);
    EXPECT_FLOAT_EQ(gaussian.sigma(), 0.5f);
    EXPECT_NEAR(gaussian.profile(1.5f), 0, 1e-7);
    // The ratio of two values is that of the shifted Gaussian exp(-x^2 / 2 sigma^2) - exp(-4.5).
    const double tail = std::exp(-4.5);
    EXPECT_NEAR(gaussian.profile(0.5f) / gaussian.profile(0), (std::exp(-0.5) - tail) / (1 - tail),
                1e-6);
}

TEST(FilterTest, MitchellHasTheOneThirdKernelWithNegativeLobes) {
    const auto mitchell = makeFilter("mitchell");  // radius 2: the paper's kernel as it is
    // k(0) = (6 - 2B) / 6 and k(1) = B / 6: 8/9 and 1/18 at B = C = 1/3.
    EXPECT_NEAR(mitchell->profile(0), 8.0 / 9, 1e-6);
    EXPECT_NEAR(mitchell->profile(1), 1.0 / 18, 1e-6);
    EXPECT_LT(mitchell->profile(1.5f), 0);
    EXPECT_LT(mitchell->profile(-1.5f), 0);
    // Stretched to radius 4, it is twice as wide and half as high.
    const auto wide = makeFilter("mitchell", 4.0f);
    EXPECT_NEAR(wide->profile(3), mitchell->profile(1.5f) / 2, 1e-7);
}

TEST(FilterTest, FactoryRejectsUnknownTypesAndBadRadii) {
    EXPECT_THROW(makeFilter("lanczos"), std::invalid_argument);
    try {
        makeFilter("mitchel");
        ADD_FAILURE() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), R"(unknown filter "mitchel" (did you mean "mitchell"?); expected )"
                               R"("box", "tent", "gaussian" or "mitchell")");
    }
    EXPECT_THROW(makeFilter("box", 0.0f), std::invalid_argument);
    EXPECT_THROW(makeFilter("tent", -1.0f), std::invalid_argument);
    EXPECT_THROW(makeFilter("gaussian", std::nanf("")), std::invalid_argument);
    for (const std::string& name : Filter::types().names())
        EXPECT_NO_THROW(makeFilter(name));
}

}  // namespace
}  // namespace lancer
