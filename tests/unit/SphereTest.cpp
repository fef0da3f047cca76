// Ray/sphere intersection: which root, which side, and how precise.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "IntersectInto.h"
#include "TestSupport.h"
#include "geometry/LineCrossing.h"
#include "geometry/Sphere.h"
#include "math/Float.h"

namespace lancer {
namespace {

using test::isFiniteHit;
using test::isUntouched;
using test::isWithinErrorBound;
using test::Random;
using test::SceneFrame;
using test::untouchedHit;

// Results of float arithmetic on values of order 1: a few units in the last place.
constexpr float kTolerance = 1e-6f;

TEST(SphereTest, HitsTheNearestOfTwoRoots) {
    const Sphere sphere(Vec3(0, 0, 0), 1, nullptr);
    Hit hit;
    ASSERT_TRUE(test::intersectInto(sphere, {Vec3(0, 0, 5), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_EQ(hit.t, 4);  // not 6, the far side
    EXPECT_EQ(hit.p, Vec3(0, 0, 1));
    EXPECT_EQ(hit.ng, Vec3(0, 0, 1));
    EXPECT_EQ(hit.ns, Vec3(0, 0, 1));
    EXPECT_EQ(hit.shape, &sphere);
}

TEST(SphereTest, HitsAnOffCentreSphereWhereTheQuadraticSays) {
    // Centre (1, 2, 3), radius 2; the ray runs along -z at y = 3, one unit off the centre, so it
    // enters at z = 3 + sqrt(4 - 1).
    const Sphere sphere(Vec3(1, 2, 3), 2, nullptr);
    Hit hit;
    ASSERT_TRUE(test::intersectInto(sphere, {Vec3(1, 3, 10), Vec3(0, 0, -1)}, kInfinity, hit));
    const float root3 = std::sqrt(3.0f);
    EXPECT_NEAR(hit.t, 7 - root3, kTolerance);
    EXPECT_VEC3_NEAR(hit.p, Vec3(1, 3, 3 + root3), kTolerance);
    EXPECT_VEC3_NEAR(hit.ng, Vec3(0, 0.5f, root3 / 2), kTolerance);
}

TEST(SphereTest, MissesARayPassingBeside) {
    const Sphere sphere(Vec3(0, 0, 0), 1, nullptr);
    Hit hit = untouchedHit();
    EXPECT_FALSE(test::intersectInto(sphere, {Vec3(1.5f, 0, 5), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_FALSE(test::intersectInto(sphere, {Vec3(0, 0, 5), Vec3(0, 1, 0)}, kInfinity, hit));
    EXPECT_TRUE(isUntouched(hit));
}

TEST(SphereTest, DoesNotReportAHitBehindTheOrigin) {
    const Sphere sphere(Vec3(0, 0, -5), 1, nullptr);
    Hit hit = untouchedHit();
    EXPECT_FALSE(test::intersectInto(sphere, {Vec3(0, 0, 0), Vec3(0, 0, 1)}, kInfinity, hit));
    EXPECT_TRUE(isUntouched(hit));
}

// cross skips solving for rays from outside that point away (both roots behind the origin);
// crossLine always solves. On rays from everywhere around the sphere, its surface included, cross
// must give crossLine's first root ahead of the origin, to the bit.
TEST(SphereTest, CrossGivesTheFirstRootAheadOfEveryLine) {
    const Sphere sphere(Vec3(0.3f, -1.2f, 2.5f), 1.7f, nullptr);
    Random random(2026);
    int ahead = 0, behind = 0;
    for (int i = 0; i < 20000; ++i) {
        // Origins inside, on (to float rounding) and outside the surface.
        const float distance = 1.7f * static_cast<float>(i % 4 == 0 ? 1 : random.uniform(0, 3));
        const Ray ray{Vec3(0.3f, -1.2f, 2.5f) + distance * random.unitVector(),
                      static_cast<float>(random.uniform(0.1, 4)) * random.unitVector()};
        LineCrossings line;
        sphere.crossLine(ray, line);
        std::optional<double> firstAhead;
        for (const LineCrossing& root : line)
            if (!firstAhead && root.crossing.t > 0) firstAhead = root.crossing.t;
        const std::optional<SurfaceCrossing> crossing = sphere.cross(ray, kInfinity);
        ASSERT_EQ(crossing.has_value(), firstAhead.has_value()) << "ray " << i;
        if (crossing) {
            EXPECT_EQ(crossing->t, *firstAhead) << "ray " << i;
        }
        ++(crossing ? ahead : behind);
    }
    EXPECT_GT(ahead, 5000);
    EXPECT_GT(behind, 5000);
}

TEST(SphereTest, FromInsideHitsTheFarSide) {
    const Sphere sphere(Vec3(0, 0, 0), 1, nullptr);
    Hit hit;
    ASSERT_TRUE(test::intersectInto(sphere, {Vec3(0, 0, 0.5f), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_EQ(hit.t, 1.5f);
    EXPECT_EQ(hit.p, Vec3(0, 0, -1));
    EXPECT_EQ(hit.ng, Vec3(0, 0, -1));  // still the outward normal
    EXPECT_FALSE(hit.frontFace({Vec3(0, 0, 0.5f), Vec3(0, 0, -1)}));
}

TEST(SphereTest, RespectsTMax) {
    const Sphere sphere(Vec3(0, 0, 0), 1, nullptr);
    const Ray fromOutside{Vec3(0, 0, 5), Vec3(0, 0, -1)};  // roots 4 and 6
    Hit hit = untouchedHit();
    EXPECT_FALSE(test::intersectInto(sphere, fromOutside, 4, hit));  // the range is open: t < tMax
    EXPECT_FALSE(test::intersectInto(sphere, fromOutside, 3, hit));
    const Ray fromCentre{Vec3(0, 0, 0), Vec3(1, 0, 0)};  // roots -1 and 1
    EXPECT_FALSE(test::intersectInto(sphere, fromCentre, 0.999f, hit));
    EXPECT_TRUE(isUntouched(hit));
    ASSERT_TRUE(
        test::intersectInto(sphere, fromOutside, 5, hit));  // between the roots: the near one
    EXPECT_EQ(hit.t, 4);
    ASSERT_TRUE(test::intersectInto(sphere, fromOutside, nextFloatUp(4), hit));
    EXPECT_EQ(hit.t, 4);
}

// A ray along +x at height y past the sphere of radius 0.5 centred at (3, -2, 5): tangent to it
// at y = -1.5 and y = -2.5, through it in between. The sphere outlives the record, whose uv
// it works out on demand.
bool intersectAtHeight(float y, Hit& hit) {
    static const Sphere sphere(Vec3(3, -2, 5), 0.5f, nullptr);
    return test::intersectInto(sphere, {Vec3(-7, y, 5), Vec3(1, 0, 0)}, kInfinity, hit);
}

TEST(SphereTest, TangentRayIsHandledWithoutNaN) {
    // Exactly at the radius either answer is acceptable; a NaN or a point off the tangent is not.
    for (float y : {-1.5f, -2.5f}) {
        Hit hit;
        if (intersectAtHeight(y, hit)) {
            EXPECT_TRUE(isFiniteHit(hit));
            EXPECT_VEC3_NEAR(hit.p, Vec3(3, y, 5), 1e-3f);
        }
    }
}

TEST(SphereTest, RayOneUlpInsideTheTangentHitsAndOneUlpOutsideMisses) {
    for (float y : {nextFloatDown(-1.5f), nextFloatUp(-2.5f)}) {
        Hit hit;
        ASSERT_TRUE(intersectAtHeight(y, hit)) << "y = " << y;
        EXPECT_TRUE(isFiniteHit(hit));
        // Half the chord is sqrt(0.5^2 - (0.5 - 1.2e-7)^2) = 3.5e-4.
        EXPECT_VEC3_NEAR(hit.p, Vec3(3, y, 5), 1e-3f);
    }
    for (float y : {nextFloatUp(-1.5f), nextFloatDown(-2.5f)}) {
        Hit hit = untouchedHit();
        EXPECT_FALSE(intersectAtHeight(y, hit)) << "y = " << y;
        EXPECT_TRUE(isUntouched(hit));
    }
}

TEST(SphereTest, DirectionLengthDoesNotChangeTheHitPoint) {
    const Vec3 center(0.3f, -0.2f, 0.5f);
    const Sphere sphere(center, 1.3f, nullptr);
    Random random(11);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 origin = random.pointInBox(5);
        const Vec3 toTarget = center + 1.3f * random.unitVector() - origin;
        const Ray ray{origin, toTarget};  // of any length
        Hit hit;
        ASSERT_TRUE(test::intersectInto(sphere, ray, kInfinity, hit));
        const auto roots = test::sphereRoots(ray, center, 1.3f);
        const long double t = roots->first > 0 ? roots->first : roots->second;
        EXPECT_TRUE(isWithinErrorBound(hit.p, test::pointOnRay(ray, t), hit.pError));
        // Power-of-two scales change the direction exactly, so the ray is the same.
        for (float scale : {0x1p-10f, 0.125f, 8.0f, 1024.0f}) {
            Hit scaled;
            ASSERT_TRUE(test::intersectInto(sphere, {origin, scale * toTarget}, kInfinity, scaled));
            EXPECT_TRUE(isWithinErrorBound(scaled.p, test::toLong(hit.p), hit.pError));
            EXPECT_NEAR(scaled.t * scale, hit.t, kTolerance * hit.t);
        }
    }
}

TEST(SphereTest, NormalPointsOutwardFromTheCentre) {
    const Vec3 center(0.3f, -0.2f, 0.5f);
    const Sphere sphere(center, 1.3f, nullptr);
    Random random(12);
    for (int i = 0; i < 1000; ++i) {
        const Ray ray{random.pointInBox(4), random.unitVector()};
        Hit hit;
        if (!test::intersectInto(sphere, ray, kInfinity, hit)) continue;
        EXPECT_VEC3_NEAR(hit.ng, (hit.p - center) / 1.3f, kTolerance);
        EXPECT_NEAR(length(hit.ng), 1, kTolerance);
        EXPECT_EQ(hit.ns, hit.ng);
    }
}

// The sphere point at longitude u and latitude v (both in [0, 1]), per Sphere's convention:
// u runs from +x towards -z, v from the south pole (-y) to the north pole (+y).
Vec3 pointAtUv(double u, double v) {
    const double phi = 2 * 3.14159265358979323846 * u;
    const double latitude = 3.14159265358979323846 * (v - 0.5);
    return Vec3(Vec3d(std::cos(phi) * std::cos(latitude), std::sin(latitude),
                      -std::sin(phi) * std::cos(latitude)));
}

// Intersects the unit sphere at the origin from outside, along the normal at `n`.
Hit hitUnitSphereAt(const Vec3& n) {
    static const Sphere sphere(Vec3(0, 0, 0), 1, nullptr);
    Hit hit;
    EXPECT_TRUE(test::intersectInto(sphere, {3.0f * n, -n}, kInfinity, hit));
    return hit;
}

TEST(SphereTest, UvIsLongitudeAndLatitude) {
    struct Case {
        Vec3 n;
        Vec2 uv;
    };
    for (const Case& c :
         {Case{Vec3(1, 0, 0), Vec2(0, 0.5f)}, Case{Vec3(0, 0, -1), Vec2(0.25f, 0.5f)},
          Case{Vec3(-1, 0, 0), Vec2(0.5f, 0.5f)}, Case{Vec3(0, 0, 1), Vec2(0.75f, 0.5f)},
          Case{Vec3(0, 1, 0), Vec2(0, 1)}, Case{Vec3(0, -1, 0), Vec2(0, 0)}}) {
        const Hit hit = hitUnitSphereAt(c.n);
        EXPECT_NEAR(hit.uv().y, c.uv.y, kTolerance) << "latitude at " << c.n.x << c.n.y << c.n.z;
        if (std::abs(c.n.y) < 1) {  // the longitude of a pole is arbitrary
            EXPECT_NEAR(hit.uv().x, c.uv.x, kTolerance)
                << "longitude at " << c.n.x << c.n.y << c.n.z;
        }
    }
}

TEST(SphereTest, UvRecoversTheHitPoint) {
    Random random(13);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 n = random.unitVector();
        const Hit hit = hitUnitSphereAt(n);
        ASSERT_GE(hit.uv().x, 0);
        ASSERT_LE(hit.uv().x, 1);
        ASSERT_GE(hit.uv().y, 0);
        ASSERT_LE(hit.uv().y, 1);
        // asin near the poles amplifies rounding: 1e-6 in n.y becomes ~1e-3 in latitude there.
        EXPECT_VEC3_NEAR(pointAtUv(hit.uv().x, hit.uv().y), hit.p, 2e-3f);
        if (std::abs(n.y) < 0.9f) {
            EXPECT_VEC3_NEAR(pointAtUv(hit.uv().x, hit.uv().y), hit.p, 1e-5f);
        }
    }
}

class SphereErrorBoundTest : public testing::TestWithParam<SceneFrame> {};

// pError must bound the distance between the computed point and the exact intersection.
TEST_P(SphereErrorBoundTest, ErrorBoundHoldsAgainstAnExtendedPrecisionReference) {
    const SceneFrame& frame = GetParam();
    const Vec3 center = frame.place(Vec3(0.3f, -0.2f, 0.5f));
    const float radius = 1.3f * frame.scale;
    const Sphere sphere(center, radius, nullptr);
    Random random(14);
    int hits = 0;
    for (int i = 0; i < 10000; ++i) {
        // From anywhere in a box around the sphere (inside too) towards a point of its surface.
        const Vec3 origin = center + frame.scale * random.pointInBox(5);
        const Vec3 target = center + radius * random.unitVector();
        const Ray ray{origin, target - origin};
        Hit hit;
        if (!test::intersectInto(sphere, ray, kInfinity, hit)) continue;
        ++hits;
        const auto roots = test::sphereRoots(ray, center, radius);
        ASSERT_TRUE(roots.has_value());
        const long double t = roots->first > 0 ? roots->first : roots->second;
        ASSERT_TRUE(isWithinErrorBound(hit.p, test::pointOnRay(ray, t), hit.pError)) << "ray " << i;
        EXPECT_NEAR(hit.t, static_cast<double>(t), 1e-6 * static_cast<double>(t));
    }
    EXPECT_GT(hits, 9000);
}

INSTANTIATE_TEST_SUITE_P(Frames, SphereErrorBoundTest, testing::ValuesIn(test::kSceneFrames),
                         test::frameName);

}  // namespace
}  // namespace lancer
