// Mirror reflection, Snell refraction, the dielectric Fresnel term and conductors made from
// colours.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "TestSupport.h"
#include "materials/Optics.h"
#include "math/Float.h"

namespace lancer {
namespace {

using test::Random;

// Float evaluation of a few square roots and products of values <= 1.
constexpr float kTolerance = 1e-6f;

constexpr float kGlass = 1.5f;
const Vec3 kUp(0, 1, 0);

// The unit direction at `degrees` from the normal (0, 1, 0), leaning towards +x.
Vec3 atAngle(float degrees) {
    return {std::sin(radians(degrees)), std::cos(radians(degrees)), 0};
}

// sin of the angle between unit direction w and the normal n.
float sine(const Vec3& w, const Vec3& n) {
    return length(cross(w, n));
}

TEST(OpticsTest, ReflectKeepsTheAngleAndFlipsTheTangentialPart) {
    for (float degrees : {0.0f, 10.0f, 45.0f, 80.0f, 89.9f}) {
        const Vec3 wo = atAngle(degrees);
        EXPECT_VEC3_NEAR(reflect(wo, kUp), Vec3(-wo.x, wo.y, 0), kTolerance) << degrees;
    }
}

TEST(OpticsTest, RefractAtNormalIncidenceGoesStraightThrough) {
    for (float eta : {kGlass, 1 / kGlass, 2.4f}) {
        const std::optional<Vec3> t = refract(kUp, kUp, eta);
        ASSERT_TRUE(t.has_value());
        EXPECT_VEC3_NEAR(*t, -kUp, kTolerance);
    }
}

TEST(OpticsTest, RefractIntoGlassAt45DegreesBendsTo28Degrees) {
    // sin(theta_t) = sin(45) / 1.5, theta_t = 28.1255057 degrees.
    const std::optional<Vec3> t = refract(atAngle(45), kUp, kGlass);
    ASSERT_TRUE(t.has_value());
    const float thetaT = radians(28.125505702055705f);
    EXPECT_VEC3_NEAR(*t, Vec3(-std::sin(thetaT), -std::cos(thetaT), 0), kTolerance);
}

// Snell's law for random directions: unit length, the far side of the surface,
// sin(theta_i) = eta sin(theta_t), and wi, n and the refracted direction in one plane with the
// tangential part reversed (the ray keeps going the same way along the surface).
void expectSnellsLaw(float eta, std::uint64_t seed) {
    Random random(seed);
    int refracted = 0;
    for (int i = 0; i < 10000; ++i) {
        const Vec3 n = random.unitVector();
        const Vec3 wi = random.unitVectorOnSide(n, true);
        const std::optional<Vec3> t = refract(wi, n, eta);
        // Refused exactly beyond the critical angle, where sin(theta_t) would exceed 1.
        const float sinThetaT = sine(wi, n) / eta;
        if (!t) {
            EXPECT_GE(sinThetaT, 1 - 4 * kTolerance);
            continue;
        }
        EXPECT_LE(sinThetaT, 1 + 4 * kTolerance);
        ++refracted;
        EXPECT_NEAR(length(*t), 1, 4 * kTolerance);
        EXPECT_LT(dot(*t, n), 0);
        EXPECT_NEAR(sine(wi, n), eta * sine(*t, n), 4 * kTolerance);
        EXPECT_NEAR(dot(cross(wi, n), *t), 0, 4 * kTolerance);  // coplanar
        const Vec3 wiTangent = wi - dot(wi, n) * n, tTangent = *t - dot(*t, n) * n;
        EXPECT_LE(dot(wiTangent, tTangent), 0);
    }
    EXPECT_GT(refracted, 0);
}

TEST(OpticsTest, RefractObeysSnellsLawEnteringGlass) {
    expectSnellsLaw(kGlass, 51);
}

TEST(OpticsTest, RefractObeysSnellsLawLeavingGlass) {
    expectSnellsLaw(1 / kGlass, 52);
}

TEST(OpticsTest, TotalInternalReflectionBeyondTheCriticalAngle) {
    // Leaving glass: the critical angle is asin(1 / 1.5) = 41.8103149 degrees.
    const float critical = 41.810314895778596f;
    for (float degrees : {critical + 0.01f, 45.0f, 60.0f, 89.0f, 90.0f}) {
        const Vec3 wi = atAngle(degrees);
        EXPECT_FALSE(refract(wi, kUp, 1 / kGlass).has_value()) << degrees;
        EXPECT_EQ(fresnelDielectric(wi.y, 1 / kGlass), 1) << degrees;
    }
    const Vec3 justBelow = atAngle(critical - 0.01f);
    EXPECT_TRUE(refract(justBelow, kUp, 1 / kGlass).has_value());
    EXPECT_LT(fresnelDielectric(justBelow.y, 1 / kGlass), 1);
}

TEST(OpticsTest, FresnelAtNormalIncidenceIsTheSquaredIndexRatio) {
    EXPECT_NEAR(fresnelDielectric(1, kGlass), 0.04f, kTolerance);      // ((1.5 - 1) / 2.5)^2
    EXPECT_NEAR(fresnelDielectric(1, 1 / kGlass), 0.04f, kTolerance);  // the same from inside
    for (float eta : {1.33f, 2.4f, 0.5f}) {
        const float expected = ((eta - 1) / (eta + 1)) * ((eta - 1) / (eta + 1));
        EXPECT_NEAR(fresnelDielectric(1, eta), expected, kTolerance) << eta;
    }
}

TEST(OpticsTest, FresnelAtObliqueAnglesMatchesTheFormula) {
    // Unpolarised average of the s and p reflectances, computed in double precision.
    EXPECT_NEAR(fresnelDielectric(std::cos(radians(45)), kGlass), 0.05023991101223595f, kTolerance);
    EXPECT_NEAR(fresnelDielectric(std::cos(radians(60)), kGlass), 0.08918671280221274f, kTolerance);
    EXPECT_NEAR(fresnelDielectric(std::cos(radians(30)), 1 / kGlass), 0.055190167295375916f,
                kTolerance);
}

TEST(OpticsTest, FresnelTendsToOneAtGrazingIncidence) {
    EXPECT_NEAR(fresnelDielectric(0, kGlass), 1, kTolerance);
    EXPECT_NEAR(fresnelDielectric(1e-3f, kGlass), 0.9942055725085015f, 1e-5f);
    // Non-decreasing towards grazing (for glass, the unpolarised average has no dip).
    float previous = fresnelDielectric(1, kGlass);
    for (int degrees = 1; degrees <= 90; ++degrees) {
        const float F = fresnelDielectric(std::cos(radians(static_cast<float>(degrees))), kGlass);
        EXPECT_GE(F, previous - kTolerance) << degrees;
        previous = F;
    }
}

TEST(OpticsTest, FresnelIsTheSameBothWaysThroughTheBoundary) {
    // Reciprocity: light entering at theta_i and light leaving at the refracted theta_t see the
    // same reflectance.
    for (float degrees = 0; degrees < 89; degrees += 4) {
        const Vec3 wi = atAngle(degrees);
        const std::optional<Vec3> t = refract(wi, kUp, kGlass);
        ASSERT_TRUE(t.has_value());
        EXPECT_NEAR(fresnelDielectric(wi.y, kGlass), fresnelDielectric(-t->y, 1 / kGlass),
                    4 * kTolerance)
            << degrees;
    }
}

// An index-matched boundary is no boundary at all: nothing reflected, the ray unchanged, up to
// exactly grazing directions (where 1 - cos^2 rounds to 1 in float).
TEST(OpticsTest, IndexOneChangesNothing) {
    Random random(53);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 n = random.unitVector();
        const Vec3 wi = random.unitVectorOnSide(n, true);
        EXPECT_NEAR(fresnelDielectric(dot(wi, n), 1), 0, kTolerance);
        const std::optional<Vec3> t = refract(wi, n, 1);
        ASSERT_TRUE(t.has_value());
        EXPECT_VEC3_NEAR(*t, -wi, 4 * kTolerance);
    }
    for (float cosine : {1e-2f, 1e-4f, 1e-6f}) {
        const Vec3 wi = normalize(Vec3(1, cosine, 0));
        EXPECT_NEAR(fresnelDielectric(wi.y, 1), 0, kTolerance) << "cos " << wi.y;
        const std::optional<Vec3> t = refract(wi, kUp, 1);
        ASSERT_TRUE(t.has_value()) << "cos " << wi.y;
        EXPECT_VEC3_NEAR(*t, -wi, kTolerance);
    }
}

// A conductor made from a colour reflects that colour head-on, rises to 1 at grazing, and stays
// finite for white (held at F0 = 0.9999). The tolerance is kTolerance's: a few float square roots.
TEST(OpticsTest, ConductorReflectingAColourReflectsItAtNormalIncidence) {
    for (float f0 : {0.0f, 0.04f, 0.2f, 0.5f, 0.8f, 0.95f}) {
        const ConductorIor ior = conductorReflecting(Color(f0));
        EXPECT_EQ(ior.eta, Color(1));
        EXPECT_NEAR(fresnelConductor(1, ior).g, f0, kTolerance) << f0;
        if (f0 > 0) {
            EXPECT_NEAR(fresnelConductor(1e-4f, ior).g, 1, 1e-3f) << f0;  // 1 - O(cos)
        }
    }
    EXPECT_NEAR(conductorReflecting(Color(0.8f, 0.5f, 0.2f)).k.r, 4, kTolerance);
    const ConductorIor white = conductorReflecting(Color(1));
    // 1 - 0.9999f is 1.0002e-4 in float (0.9999 is not exact): k = 199.97.
    EXPECT_NEAR(white.k.r, 200, 0.05f);
    EXPECT_NEAR(fresnelConductor(1, white).r, 0.9999f, kTolerance);
}

}  // namespace
}  // namespace lancer
