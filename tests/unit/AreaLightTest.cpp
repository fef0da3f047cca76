// Quad and sphere lights: their samples and densities agree with each other and with the shapes
// the lights are seen as, and many samples add up to the closed-form irradiance.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "IntersectInto.h"
#include "TestSupport.h"
#include "geometry/Quad.h"
#include "geometry/Sphere.h"
#include "lights/AreaLight.h"

namespace lancer {
namespace {

using test::Random;

constexpr double kPiD = 3.14159265358979323846;
const Color kRadiance(3, 2, 1);

// The irradiance on a surface at p with normal n, as the average of the one-sample estimates
// E_l max(0, n.L) over a grid x grid midpoint grid of light samples.
Color estimateIrradiance(const Light& light, const Vec3& p, const Vec3& n, int grid) {
    Color sum;
    for (int i = 0; i < grid; ++i)
        for (int j = 0; j < grid; ++j) {
            const Vec2 u((static_cast<float>(i) + 0.5f) / static_cast<float>(grid),
                         (static_cast<float>(j) + 0.5f) / static_cast<float>(grid));
            const LightSample s = light.sample(p, u);
            sum += s.irradiance * std::max(0.0f, dot(n, s.wi));
        }
    return sum / static_cast<float>(grid * grid);
}

void expectColorNear(const Color& actual, const Color& expected, double relative) {
    EXPECT_NEAR(actual.r, expected.r, relative * expected.r);
    EXPECT_NEAR(actual.g, expected.g, relative * expected.g);
    EXPECT_NEAR(actual.b, expected.b, relative * expected.b);
}

// The form factor from a differential area to an a x b rectangle in a parallel plane at height
// c, the area lying below one of the rectangle's corners (Howell's catalogue, case B-3):
// F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))],
// A = a/c, B = b/c. A Lambertian emitter of radiance L gives irradiance pi L F.
double formFactorBelowCorner(double a, double b, double c) {
    const double A = a / c, B = b / c;
    const double sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
    return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * kPiD);
}

// --- quad lights ---

// A 2 x 1 rectangle at height 3 facing down, over x in [-1, 1], z in [-0.5, 0.5].
struct QuadLightFixture {
    Quad surface{Vec3(-1, 3, -0.5f), Vec3(2, 0, 0), Vec3(0, 0, 1), nullptr};
    AreaLight light{surface, 0, kRadiance};
};

TEST(QuadLightTest, IrradianceBelowACornerMatchesTheFormFactor) {
    const QuadLightFixture f;
    const Color estimate = estimateIrradiance(f.light, Vec3(-1, 0, -0.5f), Vec3(0, 1, 0), 256);
    const double expected = kPiD * formFactorBelowCorner(2, 1, 3);
    expectColorNear(estimate, static_cast<float>(expected) * kRadiance, 1e-3);
}

TEST(QuadLightTest, IrradianceBelowAnInnerPointIsTheSumOfFourCornerRectangles) {
    const QuadLightFixture f;
    // Below (0.5, 3, 0.1): rectangles 1.5 x 0.6, 1.5 x 0.4, 0.5 x 0.6 and 0.5 x 0.4.
    const Color estimate = estimateIrradiance(f.light, Vec3(0.5f, 0, 0.1f), Vec3(0, 1, 0), 256);
    const double expected =
        kPiD * (formFactorBelowCorner(1.5, 0.6, 3) + formFactorBelowCorner(1.5, 0.4, 3) +
                formFactorBelowCorner(0.5, 0.6, 3) + formFactorBelowCorner(0.5, 0.4, 3));
    expectColorNear(estimate, static_cast<float>(expected) * kRadiance, 1e-3);
}

TEST(QuadLightTest, PointsBehindItGetNothing) {
    const QuadLightFixture f;
    Random random(3);
    for (int i = 0; i < 200; ++i) {
        const Vec3 p = Vec3(0, 3.5f, 0) + random.pointInBox(0.4f);  // above: behind the light
        const LightSample s = f.light.sample(
            p, Vec2(static_cast<float>(random.uniform()), static_cast<float>(random.uniform())));
        EXPECT_TRUE(s.irradiance.isBlack());
        EXPECT_FALSE(s.atInfinity);
    }
    EXPECT_TRUE(estimateIrradiance(f.light, Vec3(0, 4, 0), Vec3(0, -1, 0), 16).isBlack());
}

TEST(QuadLightTest, SampleDensityIsTheDensityOfTheDirectionItPicked) {
    const QuadLightFixture f;
    Random random(5);
    for (int i = 0; i < 500; ++i) {
        const Vec3 p = random.pointInBox(2);
        const Vec2 u(static_cast<float>(random.uniform()), static_cast<float>(random.uniform()));
        const LightSample s = f.light.sample(p, u);
        ASSERT_GT(s.pdf, 0);
        // The sample lies on the light, and the ray along wi finds it there.
        Hit hit;
        ASSERT_TRUE(test::intersectInto(f.surface, {p, s.wi}, kInfinity, hit));
        EXPECT_VEC3_NEAR(hit.p, s.position, 1e-5);
        EXPECT_NEAR(f.light.pdf(p, s.wi, hit), s.pdf, 1e-4 * s.pdf);
        // In front, the one-sample estimate is radiance / pdf.
        if (dot(f.surface.normal(), s.wi) < 0)
            expectColorNear(s.irradiance, kRadiance / s.pdf, 1e-6);
    }
}

TEST(QuadLightTest, PowerIsPiTimesAreaTimesRadiance) {
    const QuadLightFixture f;
    expectColorNear(f.light.power(100), static_cast<float>(kPiD * 2) * kRadiance, 1e-6);
    EXPECT_FALSE(f.light.isDelta());
}

// --- sphere lights ---

struct SphereLightFixture {
    Sphere surface{Vec3(1, 4, -2), 0.5f, nullptr};
    AreaLight light{surface, 0, kRadiance};
};

// A sphere wholly above a surface's horizon gives E = pi L (r / d)^2 cos(beta), beta the angle
// between the normal and the direction to the centre (Nusselt: it projects as a disc would).
TEST(SphereLightTest, IrradianceFromOutsideMatchesTheClosedForm) {
    const SphereLightFixture f;
    const Vec3 p(1, 0, -2);
    for (const Vec3& n : {Vec3(0, 1, 0), normalize(Vec3(0.5f, 1, 0.2f))}) {
        const Vec3d toCenter = Vec3d(f.surface.center()) - Vec3d(p);
        const double d = length(toCenter);
        const double cosBeta = dot(Vec3d(n), toCenter) / d;
        const double expected = kPiD * 0.25 / (d * d) * cosBeta;
        const Color estimate = estimateIrradiance(f.light, p, n, 256);
        expectColorNear(estimate, static_cast<float>(expected) * kRadiance, 1e-3);
    }
}

TEST(SphereLightTest, IrradianceInsideIsPiTimesRadianceEverywhere) {
    const SphereLightFixture f;
    Random random(11);
    for (int i = 0; i < 5; ++i) {
        const Vec3 p = f.surface.center() + random.pointInBox(0.25f);
        const Color estimate = estimateIrradiance(f.light, p, random.unitVector(), 512);
        expectColorNear(estimate, kPi * kRadiance, 5e-3);
    }
}

// A point on the sphere, as a hit computes it (rounded to float, so on either side), sees the
// whole inside of the sphere: samples must spread over it, not collapse onto the point.
TEST(SphereLightTest, PointsOnTheSurfaceSeeTheWholeInside) {
    const SphereLightFixture f;
    Random random(19);
    for (int i = 0; i < 20; ++i) {
        const Vec3 outward = random.unitVector();
        const Vec3 p = f.surface.center() + f.surface.radius() * outward;
        double distance = 0;
        for (int k = 0; k < 64; ++k) {
            const Vec2 u(static_cast<float>(random.uniform()),
                         static_cast<float>(random.uniform()));
            distance += length(f.light.sample(p, u).position - p) / 64;
        }
        EXPECT_GT(distance, 0.5 * f.surface.radius()) << "at " << test::describe(p);
        expectColorNear(estimateIrradiance(f.light, p, -outward, 256), kPi * kRadiance, 1e-2);
    }
}

TEST(SphereLightTest, SamplesFromOutsideLieOnTheVisibleCap) {
    const SphereLightFixture f;
    const Vec3 p(0, 0, 0);
    const Vec3 toCenter = f.surface.center() - p;
    const float sinThetaMax = f.surface.radius() / length(toCenter);
    const float cosThetaMax = std::sqrt(1 - sinThetaMax * sinThetaMax);
    Random random(13);
    for (int i = 0; i < 500; ++i) {
        const Vec2 u(static_cast<float>(random.uniform()), static_cast<float>(random.uniform()));
        const LightSample s = f.light.sample(p, u);
        EXPECT_NEAR(length(s.position - f.surface.center()), f.surface.radius(), 1e-5);
        EXPECT_GE(dot(s.wi, normalize(toCenter)), cosThetaMax - 1e-6f);
        // The point faces p: it is on the near side.
        EXPECT_LT(dot(s.position - f.surface.center(), s.wi), 1e-5f);
    }
}

TEST(SphereLightTest, SampleDensityIsTheDensityOfTheDirectionItPicked) {
    const SphereLightFixture f;
    Random random(17);
    for (int i = 0; i < 500; ++i) {
        // Half the points outside, half inside.
        const Vec3 p = i % 2 ? random.pointInBox(2) : f.surface.center() + random.pointInBox(0.2f);
        const Vec2 u(static_cast<float>(random.uniform()), static_cast<float>(random.uniform()));
        const LightSample s = f.light.sample(p, u);
        ASSERT_GT(s.pdf, 0);
        Hit hit;
        ASSERT_TRUE(test::intersectInto(f.surface, {p, s.wi}, kInfinity, hit));
        EXPECT_VEC3_NEAR(hit.p, s.position, 1e-4);
        EXPECT_NEAR(f.light.pdf(p, s.wi, hit), s.pdf, 1e-3 * s.pdf);
        expectColorNear(s.irradiance, kRadiance / s.pdf, 1e-6);
    }
}

TEST(SphereLightTest, PowerIsPiTimesAreaTimesRadiance) {
    const SphereLightFixture f;
    const double area = 4 * kPiD * 0.25;
    expectColorNear(f.light.power(100), static_cast<float>(kPiD * area) * kRadiance, 1e-6);
    EXPECT_FALSE(f.light.isDelta());
}

}  // namespace
}  // namespace lancer
