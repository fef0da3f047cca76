// The environment light: the contract's mapping (u = 0.5 + atan2(d.x, -d.z) / (2 pi),
// v = acos(d.y) / pi, rotate about +y counter-clockwise seen from above), its bilinear lookup,
// its sampling density against the map's luminance times sin(theta), its power, and the error of
// its importance sampling against uniform sampling of the sphere on a sun-like map.

#include "lights/EnvironmentLight.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "geometry/Hit.h"

namespace lancer {
namespace {

constexpr double kPiD = std::numbers::pi;

// The unit direction of texel (x, y)'s centre, by the contract's formulas inverted in double.
Vec3 texelDirection(int x, int y, int width, int height) {
    const double u = (x + 0.5) / width, v = (y + 0.5) / height;
    const double phi = (u - 0.5) * 2 * kPiD, theta = v * kPiD;
    return Vec3(static_cast<float>(std::sin(theta) * std::sin(phi)),
                static_cast<float>(std::cos(theta)),
                static_cast<float>(-std::sin(theta) * std::cos(phi)));
}

TEST(EnvironmentLight, MapsDirectionsAsTheContractSays) {
    const auto near = [](const Vec2& a, const Vec2& b) {
        EXPECT_NEAR(a.x, b.x, 1e-6f);
        EXPECT_NEAR(a.y, b.y, 1e-6f);
    };
    near(EnvironmentLight::mapPoint(Vec3(0, 0, -1)), Vec2(0.5f, 0.5f));     // ahead: the centre
    near(EnvironmentLight::mapPoint(Vec3(1, 0, 0)), Vec2(0.75f, 0.5f));     // right: 3/4 across
    near(EnvironmentLight::mapPoint(Vec3(-1, 0, 0)), Vec2(0.25f, 0.5f));    // left: 1/4 across
    EXPECT_NEAR(EnvironmentLight::mapPoint(Vec3(0, 1, 0)).y, 0.0f, 1e-6f);  // up: the top row
    EXPECT_NEAR(EnvironmentLight::mapPoint(Vec3(0, -1, 0)).y, 1.0f, 1e-6f);
    const Vec3 d = normalize(Vec3(0.3f, -0.4f, 0.8f));
    const Vec3 back = EnvironmentLight::mapDirection(EnvironmentLight::mapPoint(d));
    EXPECT_NEAR(back.x, d.x, 1e-5f);
    EXPECT_NEAR(back.y, d.y, 1e-5f);
    EXPECT_NEAR(back.z, d.z, 1e-5f);
}

// One bright texel, seen exactly at its centre's direction (bilinear weights 1, 0, 0, 0), and,
// turned by rotate, where the rotation takes it.
TEST(EnvironmentLight, OneBrightTexelIsSeenInItsDirectionAndTurnedByRotate) {
    constexpr int kW = 16, kH = 8;
    Image map(kW, kH, Color(0));
    // Texel (11, 3): u = 0.71875, just left of +x, a little above the horizon.
    map.at(11, 3) = Color(5, 6, 7);
    const Vec3 d = texelDirection(11, 3, kW, kH);
    const EnvironmentLight still(map, 2, 0);
    const Color seen = still.radiance(d);
    EXPECT_NEAR(seen.r, 10, 1e-3f);
    EXPECT_NEAR(seen.g, 12, 1e-3f);
    EXPECT_NEAR(seen.b, 14, 1e-3f);
    EXPECT_EQ(still.radiance(-d), Color(0));
    // Turned 90 degrees counter-clockwise seen from above: +x goes to -z, -z to -x.
    const EnvironmentLight turned(map, 2, 90);
    const Vec3 turnedD(d.z, d.y, -d.x);
    EXPECT_NEAR(turned.radiance(turnedD).g, 12, 1e-3f);
    EXPECT_NEAR(turned.radiance(d).g, 0, 1e-3f);
    // Halfway between two texel centres along a row: the mean of the two.
    map.at(12, 3) = Color(1, 2, 3);
    const EnvironmentLight two(map, 1, 0);
    const Vec3 between = EnvironmentLight::mapDirection(Vec2(12.0f / kW, 3.5f / kH));
    EXPECT_NEAR(two.radiance(between).r, 3, 1e-3f);
}

// The sampling weights the contract states: the luminance of the bilinear map averaged over each
// texel's cell (1/8, 3/4, 1/8 across and down) times sin(theta) at the cell's centre, normalised
// to a density over the sphere. At a texel centre the solid-angle density is then
// W H w / (sum w * 2 pi^2 sin(theta)).
TEST(EnvironmentLight, DensityIsTheLuminanceTimesSinThetaNormalised) {
    constexpr int kW = 12, kH = 6;
    Image map(kW, kH);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            map.at(x, y) =
                Color(uniform(rng), uniform(rng), uniform(rng)) * (x == 4 ? 20.0f : 1.0f);
    const EnvironmentLight light(map, 1, 30);
    const double spread[3] = {0.125, 0.75, 0.125};
    std::vector<double> w(kW * kH);
    double sum = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            double average = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const Color& c = map.at((x + dx + kW) % kW, std::clamp(y + dy, 0, kH - 1));
                    average += spread[dy + 1] * spread[dx + 1] *
                               (0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b);
                }
            w[static_cast<std::size_t>(y * kW + x)] = average * std::sin(kPiD * (y + 0.5) / kH);
            sum += w[static_cast<std::size_t>(y * kW + x)];
        }
    const Hit nowhere;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const double sinTheta = std::sin(kPiD * (y + 0.5) / kH);
            const double expected = kW * kH * w[static_cast<std::size_t>(y * kW + x)] /
                                    (sum * 2 * kPiD * kPiD * sinTheta);
            // The light is turned by 30 degrees: the texel is seen turned.
            const Vec3 m = texelDirection(x, y, kW, kH);
            const float c = std::cos(radians(30)), s = std::sin(radians(30));
            const Vec3 world(c * m.x + s * m.z, m.y, -s * m.x + c * m.z);
            EXPECT_NEAR(light.pdf(Vec3(0), world, nowhere), expected, 1e-4 * expected)
                << "texel " << x << ", " << y;
        }
    // Samples state the density pdf() gives for their direction, and carry radiance / pdf.
    for (int i = 0; i < 1000; ++i) {
        const LightSample s = light.sample(Vec3(0), Vec2(uniform(rng), uniform(rng)));
        ASSERT_GT(s.pdf, 0);
        EXPECT_TRUE(s.atInfinity);
        EXPECT_NEAR(s.pdf, light.pdf(Vec3(0), s.wi, nowhere), 2e-3f * s.pdf);
        const Color expected = light.radiance(s.wi) / s.pdf;
        EXPECT_NEAR(s.irradiance.g, expected.g, 1e-3f * expected.g + 1e-6f);
    }
}

// A constant map: at the centre of every row the density is uniform over the sphere, 1 / 4 pi
// (the sin(theta) of the weights cancelling the Jacobian's; within 1e-3, the midpoint rule's error
// in the rows' sines at 64 rows being 2e-4; between row centres the density follows
// sin(theta_row) / sin(theta)), and the power is pi R^2 * 4 pi L.
TEST(EnvironmentLight, ConstantMapIsUniformAndItsPowerIsPiRSquaredTimesFourPiL) {
    const EnvironmentLight light(Image(128, 64, Color(0.5f)), 2, 0);
    const Hit nowhere;
    for (const auto& [x, y] : {std::pair{64, 31}, std::pair{3, 5}, std::pair{100, 60}})
        EXPECT_NEAR(light.pdf(Vec3(0), texelDirection(x, y, 128, 64), nowhere), 1 / (4 * kPiD),
                    1e-3 / (4 * kPiD));
    const Color power = light.power(3);
    EXPECT_NEAR(power.g, kPiD * 9 * 4 * kPiD * 1.0, 1e-3 * power.g);
}

// The irradiance of an upward surface under a sun-like map (a dim sky and one texel 10^4 times
// brighter), estimated from 16 samples, 2000 times over: importance sampling's RMSE must be far
// below that of directions uniform over the sphere (whose estimate rarely finds the sun). The
// reference is the midpoint rule over a 4096 x 2048 grid of the same bilinear map.
TEST(EnvironmentLight, ImportanceSamplingErrorIsFarBelowUniformSampling) {
    constexpr int kW = 32, kH = 16;
    Image map(kW, kH, Color(0.2f, 0.3f, 0.5f));
    map.at(20, 5) = Color(3000);
    const EnvironmentLight light(map, 1, 0);
    const Vec3 n(0, 1, 0);
    double reference = 0;
    constexpr int kGridW = 4096, kGridH = 2048;
    for (int y = 0; y < kGridH; ++y)
        for (int x = 0; x < kGridW; ++x) {
            const Vec3 d = texelDirection(x, y, kGridW, kGridH);
            const double solidAngle =
                2 * kPiD * kPiD * std::sin(kPiD * (y + 0.5) / kGridH) / (double(kGridW) * kGridH);
            reference += std::max(0.0f, dot(d, n)) * light.radiance(d).g * solidAngle;
        }
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    constexpr int kSamples = 16, kTrials = 2000;
    double importanceSquares = 0, uniformSquares = 0, importanceSum = 0;
    for (int trial = 0; trial < kTrials; ++trial) {
        double importance = 0, uniformSphere = 0;
        for (int i = 0; i < kSamples; ++i) {
            const LightSample s = light.sample(Vec3(0), Vec2(uniform(rng), uniform(rng)));
            importance += std::max(0.0f, dot(s.wi, n)) * s.irradiance.g;
            const float z = 1 - 2 * uniform(rng),
                        phi = 2 * std::numbers::pi_v<float> * uniform(rng);
            const float r = std::sqrt(std::max(0.0f, 1 - z * z));
            const Vec3 d(r * std::cos(phi), z, r * std::sin(phi));
            uniformSphere += std::max(0.0f, dot(d, n)) * light.radiance(d).g * 4 * kPiD;
        }
        importanceSum += importance / kSamples;
        importanceSquares += std::pow(importance / kSamples - reference, 2);
        uniformSquares += std::pow(uniformSphere / kSamples - reference, 2);
    }
    const double importanceRmse = std::sqrt(importanceSquares / kTrials);
    const double uniformRmse = std::sqrt(uniformSquares / kTrials);
    EXPECT_LT(importanceRmse, 0.1 * uniformRmse)
        << "importance " << importanceRmse << ", uniform " << uniformRmse << ", E " << reference;
    // And it is unbiased: the mean of the 2000 estimates is within 4 standard errors of the
    // reference (the RMSE, some 30% of E: within a texel the bilinear map varies while the
    // density is constant, most where the sun's light spills into its neighbours' cells).
    EXPECT_NEAR(importanceSum / kTrials, reference, 4 * importanceRmse / std::sqrt(kTrials));
}

}  // namespace
}  // namespace lancer
