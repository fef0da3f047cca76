// Spot lights: full intensity inside the cone, a smooth fade over cone_falloff degrees, nothing
// beyond cone_angle; the power is the intensity integrated over the sphere of directions.

#include <gtest/gtest.h>

#include <cmath>

#include "TestSupport.h"
#include "lights/SpotLight.h"

namespace lancer {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// At the origin pointing down -y; cone of 30 degrees fading over its outer 10.
const SpotLight kSpot(Vec3(0, 0, 0), Vec3(0, -1, 0), Color(8, 4, 2), 30, 10);

// The point at distance d from the light, `degrees` off its axis.
Vec3 pointOffAxis(float degrees, float d) {
    return d * Vec3(std::sin(radians(degrees)), -std::cos(radians(degrees)), 0);
}

TEST(SpotLightTest, OnTheAxisItIsAPointLight) {
    const LightSample s = kSpot.sample(Vec3(0, -2, 0), Vec2(0.3f, 0.9f));
    EXPECT_EQ(s.irradiance, Color(2, 1, 0.5f));  // I / d^2
    EXPECT_VEC3_NEAR(s.wi, Vec3(0, 1, 0), 1e-7);
    EXPECT_EQ(s.position, Vec3(0, 0, 0));
    EXPECT_EQ(s.pdf, 0);
    EXPECT_TRUE(kSpot.isDelta());
}

TEST(SpotLightTest, FullIntensityInsideTheFalloffStart) {
    EXPECT_FLOAT_EQ(kSpot.coneFactor(normalize(pointOffAxis(0, 1))), 1);
    EXPECT_FLOAT_EQ(kSpot.coneFactor(normalize(pointOffAxis(19.9f, 1))), 1);
    EXPECT_FLOAT_EQ(kSpot.sample(pointOffAxis(15, 2), Vec2(0.5f, 0.5f)).irradiance.r, 2);
}

TEST(SpotLightTest, FadesSmoothlyToNothingAtTheConeAngle) {
    // The smoothstep of the cosine: 1/2 where the cosine is half-way between the edges.
    const double cosStart = std::cos(20 * kPiD / 180), cosEnd = std::cos(30 * kPiD / 180);
    const double halfWay = std::acos((cosStart + cosEnd) / 2) * 180 / kPiD;
    EXPECT_NEAR(kSpot.coneFactor(normalize(pointOffAxis(static_cast<float>(halfWay), 1))), 0.5,
                1e-5);
    float previous = 1;
    for (float degrees = 20; degrees <= 30; degrees += 0.5f) {
        const float factor = kSpot.coneFactor(normalize(pointOffAxis(degrees, 1)));
        EXPECT_LE(factor, previous) << degrees << " degrees";
        previous = factor;
    }
    EXPECT_NEAR(kSpot.coneFactor(normalize(pointOffAxis(29.99f, 1))), 0, 1e-5);
}

TEST(SpotLightTest, NothingBeyondTheConeNorBehind) {
    for (const float degrees : {30.01f, 45.0f, 90.0f, 150.0f, 180.0f})
        EXPECT_TRUE(kSpot.sample(pointOffAxis(degrees, 2), Vec2(0.5f, 0.5f)).irradiance.isBlack())
            << degrees << " degrees";
}

TEST(SpotLightTest, WithoutFalloffAConeOfZeroWidthIsAHardEdge) {
    const SpotLight hard(Vec3(0, 0, 0), Vec3(0, -1, 0), Color(1), 30, 0, false);
    EXPECT_EQ(hard.sample(pointOffAxis(29.9f, 5), Vec2(0.5f, 0.5f)).irradiance, Color(1));
    EXPECT_TRUE(hard.sample(pointOffAxis(30.1f, 5), Vec2(0.5f, 0.5f)).irradiance.isBlack());
}

// The power is the intensity times the cone factor integrated over all directions.
TEST(SpotLightTest, PowerIsTheIntensityIntegratedOverTheCone) {
    constexpr int kSteps = 200000;
    double integral = 0;  // of the cone factor over the sphere, by the midpoint rule in theta
    for (int i = 0; i < kSteps; ++i) {
        const double theta = (i + 0.5) * kPiD / kSteps;
        const Vec3 w(Vec3d(std::sin(theta), -std::cos(theta), 0));
        integral += kSpot.coneFactor(w) * 2 * kPiD * std::sin(theta) * (kPiD / kSteps);
    }
    const Color power = kSpot.power(10);
    EXPECT_NEAR(power.r, 8 * integral, 1e-4 * 8 * integral);
    EXPECT_NEAR(power.b, 2 * integral, 1e-4 * 2 * integral);
}

}  // namespace
}  // namespace lancer
