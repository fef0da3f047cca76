// Ray/plane intersection: an infinite, two-sided plane.

#include <gtest/gtest.h>

#include <cmath>

#include "IntersectInto.h"
#include "TestSupport.h"
#include "geometry/Plane.h"
#include "math/Float.h"

namespace lancer {
namespace {

using test::isFiniteHit;
using test::isUntouched;
using test::isWithinErrorBound;
using test::Random;
using test::SceneFrame;
using test::untouchedHit;

constexpr float kTolerance = 1e-6f;

TEST(PlaneTest, HitsFromAbove) {
    const Plane floor(Vec3(0, 0, 0), Vec3(0, 1, 0), nullptr);
    Hit hit;
    ASSERT_TRUE(test::intersectInto(floor, {Vec3(1, 2, 3), Vec3(0, -1, 0)}, kInfinity, hit));
    EXPECT_EQ(hit.t, 2);
    EXPECT_EQ(hit.p, Vec3(1, 0, 3));
    EXPECT_EQ(hit.ng, Vec3(0, 1, 0));
    EXPECT_EQ(hit.ns, Vec3(0, 1, 0));
    EXPECT_EQ(hit.shape, &floor);
}

TEST(PlaneTest, IsTwoSidedAndKeepsItsNormal) {
    const Plane floor(Vec3(0, 0, 0), Vec3(0, 1, 0), nullptr);
    const Ray fromBelow{Vec3(1, -2, 3), Vec3(0, 1, 0)};
    Hit hit;
    ASSERT_TRUE(test::intersectInto(floor, fromBelow, kInfinity, hit));
    EXPECT_EQ(hit.t, 2);
    EXPECT_EQ(hit.p, Vec3(1, 0, 3));
    EXPECT_EQ(hit.ng, Vec3(0, 1, 0));  // as given, not flipped towards the ray
    EXPECT_FALSE(hit.frontFace(fromBelow));
}

TEST(PlaneTest, NormalIsTheGivenOneNormalized) {
    const Plane wall(Vec3(0, 0, -3), Vec3(0, 0, -2), nullptr);
    Hit hit;
    ASSERT_TRUE(test::intersectInto(wall, {Vec3(0.5f, 0.25f, 0), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_EQ(hit.t, 3);
    EXPECT_EQ(hit.ng, Vec3(0, 0, -1));
    EXPECT_EQ(wall.normal(), Vec3(0, 0, -1));
}

TEST(PlaneTest, HitsAnObliquePlane) {
    // The plane x + y + z = 3 and a ray along -(1, 1, 1) from (3, 3, 3): it meets it at (1, 1, 1).
    const Plane plane(Vec3(3, 0, 0), Vec3(1, 1, 1), nullptr);
    Hit hit;
    ASSERT_TRUE(test::intersectInto(plane, {Vec3(3, 3, 3), Vec3(-1, -1, -1)}, kInfinity, hit));
    EXPECT_NEAR(hit.t, 2, kTolerance);
    EXPECT_VEC3_NEAR(hit.p, Vec3(1, 1, 1), kTolerance);
    EXPECT_VEC3_NEAR(hit.ng, Vec3(1, 1, 1) / std::sqrt(3.0f), kTolerance);
}

TEST(PlaneTest, MissesRaysGoingAway) {
    const Plane floor(Vec3(0, 0, 0), Vec3(0, 1, 0), nullptr);
    Hit hit = untouchedHit();
    EXPECT_FALSE(test::intersectInto(floor, {Vec3(1, 2, 3), Vec3(0.3f, 1, 0)}, kInfinity, hit));
    EXPECT_FALSE(test::intersectInto(floor, {Vec3(1, -2, 3), Vec3(0, -1, 0.2f)}, kInfinity, hit));
    EXPECT_TRUE(isUntouched(hit));
}

TEST(PlaneTest, ParallelRaysMissWithoutNaN) {
    const Plane floor(Vec3(0, 0, 0), Vec3(0, 1, 0), nullptr);
    Hit hit = untouchedHit();
    EXPECT_FALSE(
        test::intersectInto(floor, {Vec3(0, 1, 0), Vec3(1, 0, 0)}, kInfinity, hit));  // above
    EXPECT_FALSE(
        test::intersectInto(floor, {Vec3(0, 0, 0), Vec3(1, 0, 1)}, kInfinity, hit));  // within
    EXPECT_FALSE(
        test::intersectInto(floor, {Vec3(0, -1, 0), Vec3(-1, 0, 3)}, kInfinity, hit));  // below
    const Plane tilted(Vec3(1, 2, 3), Vec3(1, 2, -1), nullptr);
    const Vec3 alongTilted = cross(Vec3(1, 2, -1), Vec3(0, 0, 1));
    EXPECT_FALSE(test::intersectInto(tilted, {Vec3(1, 2, 3), alongTilted}, kInfinity, hit));
    EXPECT_TRUE(isUntouched(hit));
}

TEST(PlaneTest, RespectsTMax) {
    const Plane floor(Vec3(0, 0, 0), Vec3(0, 1, 0), nullptr);
    const Ray ray{Vec3(1, 2, 3), Vec3(0, -1, 0)};
    Hit hit = untouchedHit();
    EXPECT_FALSE(test::intersectInto(floor, ray, 2, hit));
    EXPECT_FALSE(test::intersectInto(floor, ray, 1, hit));
    EXPECT_TRUE(isUntouched(hit));
    EXPECT_TRUE(test::intersectInto(floor, ray, nextFloatUp(2), hit));
}

TEST(PlaneTest, DirectionLengthDoesNotChangeTheHitPoint) {
    const Vec3 point(0.2f, -0.5f, 0.1f);
    const Plane plane(point, Vec3(0.3f, 1, -0.4f), nullptr);
    Random random(21);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 origin = random.pointInBox(5);
        const Vec3 toTarget = point + 10.0f * cross(plane.normal(), random.unitVector()) - origin;
        const Ray ray{origin, toTarget};  // of any length
        Hit hit;
        ASSERT_TRUE(test::intersectInto(plane, ray, kInfinity, hit));
        // The plane of the float unit normal, the one the code intersects.
        const long double t =
            test::planeRoot(ray, test::toLong(point), test::toLong(plane.normal()));
        EXPECT_TRUE(isWithinErrorBound(hit.p, test::pointOnRay(ray, t), hit.pError));
        // Power-of-two scales change the direction exactly, so the ray is the same.
        for (float scale : {0x1p-10f, 0.125f, 8.0f, 1024.0f}) {
            Hit scaled;
            ASSERT_TRUE(test::intersectInto(plane, {origin, scale * toTarget}, kInfinity, scaled));
            EXPECT_TRUE(isWithinErrorBound(scaled.p, test::toLong(hit.p), hit.pError));
            EXPECT_NEAR(scaled.t * scale, hit.t, kTolerance * hit.t);
        }
    }
}

// The world axes a plane uses as uv, per the contract: (x, z) when its normal is nearest the y
// axis, (x, y) when nearest z, (y, z) when nearest x.
struct UvAxesCase {
    Vec3 normal;
    int uAxis, vAxis;
};

void PrintTo(const UvAxesCase& c, std::ostream* out) {
    *out << "normal (" << c.normal.x << ", " << c.normal.y << ", " << c.normal.z << ")";
}

class PlaneUvTest : public testing::TestWithParam<UvAxesCase> {};

TEST_P(PlaneUvTest, UvAreWorldCoordinatesOnTheAxesNearestThePlane) {
    const UvAxesCase& c = GetParam();
    const Vec3 point(0.5f, -1.5f, 2.5f);
    const Plane plane(point, c.normal, nullptr);
    Random random(22);
    for (int i = 0; i < 100; ++i) {
        // Rays from either side towards a point of the plane.
        const Vec3 target = point + cross(c.normal, random.unitVector()) * 10.0f;
        const Vec3 origin = target + 3.0f * random.unitVector();
        Hit hit;
        if (!test::intersectInto(plane, {origin, target - origin}, kInfinity, hit)) continue;
        EXPECT_EQ(hit.uv().x, hit.p[c.uAxis]);
        EXPECT_EQ(hit.uv().y, hit.p[c.vAxis]);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Normals, PlaneUvTest,
    testing::Values(UvAxesCase{Vec3(0, 1, 0), 0, 2}, UvAxesCase{Vec3(0, -1, 0), 0, 2},
                    UvAxesCase{Vec3(0.3f, 1, -0.4f), 0, 2}, UvAxesCase{Vec3(0, 0, 1), 0, 1},
                    UvAxesCase{Vec3(0.1f, -0.3f, -0.8f), 0, 1}, UvAxesCase{Vec3(1, 0, 0), 1, 2},
                    UvAxesCase{Vec3(-0.9f, 0.2f, 0.3f), 1, 2}));

class PlaneErrorBoundTest : public testing::TestWithParam<SceneFrame> {};

TEST_P(PlaneErrorBoundTest, ErrorBoundHoldsAgainstAnExtendedPrecisionReference) {
    const SceneFrame& frame = GetParam();
    const Vec3 point = frame.place(Vec3(0.2f, -0.5f, 0.1f));
    const Vec3 normal(0.3f, 1, -0.4f);
    const Plane plane(point, normal, nullptr);
    // The plane the code intersects is the one of its float unit normal.
    const test::Vec3L planeNormal = test::toLong(plane.normal());
    Random random(23);
    for (int i = 0; i < 10000; ++i) {
        const Ray ray{point + frame.scale * random.pointInBox(10), random.unitVector()};
        Hit hit;
        if (!test::intersectInto(plane, ray, kInfinity, hit)) continue;
        ASSERT_TRUE(isFiniteHit(hit));
        const long double t = test::planeRoot(ray, test::toLong(point), planeNormal);
        ASSERT_TRUE(isWithinErrorBound(hit.p, test::pointOnRay(ray, t), hit.pError)) << "ray " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(Frames, PlaneErrorBoundTest, testing::ValuesIn(test::kSceneFrames),
                         test::frameName);

}  // namespace
}  // namespace lancer
