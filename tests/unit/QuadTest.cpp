// Ray/parallelogram intersection: where, which side, uv, and how precise.

#include <gtest/gtest.h>

#include "IntersectInto.h"
#include "TestSupport.h"
#include "geometry/Quad.h"

namespace lancer {
namespace {

using test::isUntouched;
using test::isWithinErrorBound;
using test::Random;
using test::SceneFrame;
using test::untouchedHit;

constexpr float kTolerance = 1e-6f;

// A 2 x 1 rectangle in the plane y = 3, facing down (edge1 x edge2 = (2,0,0) x (0,0,1) = -2 y).
const Vec3 kCorner(-1, 3, -0.5f), kEdge1(2, 0, 0), kEdge2(0, 0, 1);

TEST(QuadTest, HitsInsideWithUvAlongTheEdges) {
    const Quad quad(kCorner, kEdge1, kEdge2, nullptr);
    Hit hit;
    // Straight up through the point at u = 0.75, v = 0.25.
    ASSERT_TRUE(test::intersectInto(quad, {Vec3(0.5f, 0, -0.25f), Vec3(0, 1, 0)}, kInfinity, hit));
    EXPECT_NEAR(hit.t, 3, kTolerance);
    EXPECT_VEC3_NEAR(hit.p, Vec3(0.5f, 3, -0.25f), kTolerance);
    EXPECT_NEAR(hit.uv().x, 0.75f, kTolerance);
    EXPECT_NEAR(hit.uv().y, 0.25f, kTolerance);
    EXPECT_EQ(hit.ng, Vec3(0, -1, 0));
    EXPECT_EQ(hit.ns, Vec3(0, -1, 0));
    EXPECT_EQ(hit.dpdu, kEdge1);
    EXPECT_EQ(hit.dpdv, kEdge2);
    EXPECT_EQ(hit.shape, &quad);
    EXPECT_TRUE(hit.frontFace({Vec3(0.5f, 0, -0.25f), Vec3(0, 1, 0)}));
}

TEST(QuadTest, IsHitFromBehindWithTheSameFrontNormal) {
    const Quad quad(kCorner, kEdge1, kEdge2, nullptr);
    Hit hit;
    const Ray fromAbove{Vec3(0, 5, 0), Vec3(0, -1, 0)};
    ASSERT_TRUE(test::intersectInto(quad, fromAbove, kInfinity, hit));
    EXPECT_NEAR(hit.t, 2, kTolerance);
    EXPECT_EQ(hit.ng, Vec3(0, -1, 0));
    EXPECT_FALSE(hit.frontFace(fromAbove));
    EXPECT_FALSE(quad.emitsOnBothSides());
}

TEST(QuadTest, MissesOutsideTheEdgesParallelRaysAndHitsBeyondTMax) {
    const Quad quad(kCorner, kEdge1, kEdge2, nullptr);
    Hit hit = untouchedHit();
    EXPECT_FALSE(test::intersectInto(quad, {Vec3(1.01f, 0, 0), Vec3(0, 1, 0)}, kInfinity, hit));
    EXPECT_FALSE(test::intersectInto(quad, {Vec3(0, 0, 0.51f), Vec3(0, 1, 0)}, kInfinity, hit));
    EXPECT_FALSE(test::intersectInto(quad, {Vec3(0, 0, -0.51f), Vec3(0, 1, 0)}, kInfinity, hit));
    EXPECT_FALSE(
        test::intersectInto(quad, {Vec3(0, 3, 0), Vec3(1, 0, 0)}, kInfinity, hit));  // in its plane
    EXPECT_FALSE(test::intersectInto(quad, {Vec3(0, 0, 0), Vec3(0, 1, 0)}, 2.9f, hit));
    EXPECT_FALSE(
        test::intersectInto(quad, {Vec3(0, 4, 0), Vec3(0, 1, 0)}, kInfinity, hit));  // behind
    EXPECT_TRUE(isUntouched(hit));
}

TEST(QuadTest, ParallelogramEdgesNeedNotBeOrthogonal) {
    // A sheared quad: edge2 leans along x. The point corner + 0.5 edge1 + 0.5 edge2 is inside,
    // the corner's mirror image beyond edge2's start is not.
    const Vec3 corner(0, 0, 0), edge1(1, 0, 0), edge2(1, 1, 0);
    const Quad quad(corner, edge1, edge2, nullptr);
    Hit hit;
    ASSERT_TRUE(test::intersectInto(quad, {Vec3(1, 0.5f, 5), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_NEAR(hit.uv().x, 0.5f, kTolerance);
    EXPECT_NEAR(hit.uv().y, 0.5f, kTolerance);
    EXPECT_FALSE(test::intersectInto(quad, {Vec3(0.1f, 0.5f, 5), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_NEAR(quad.area(0), 1, kTolerance);
    EXPECT_VEC3_NEAR(quad.normal(), Vec3(0, 0, 1), kTolerance);
}

TEST(QuadTest, BoundsHoldAllFourCorners) {
    const Quad quad(Vec3(1, 2, 3), Vec3(-2, 1, 0), Vec3(0, 3, -4), nullptr);
    const Bounds3 box = quad.bounds();
    for (const Vec2 uv : {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(1, 1)})
        EXPECT_TRUE(box.contains(quad.pointAt(uv)));
}

class QuadFrameTest : public testing::TestWithParam<SceneFrame> {};

// Random rays at a tilted quad, wherever it is placed: the hit point lies within its error bound
// of the exact intersection, so that rays spawned from it start on the right side.
TEST_P(QuadFrameTest, HitPointsAreWithinTheirErrorBound) {
    const SceneFrame& frame = GetParam();
    const Vec3 corner = frame.place(Vec3(-0.7f, 0.2f, -0.4f));
    const Vec3 edge1 = frame.scale * Vec3(1.3f, 0.4f, -0.2f);
    const Vec3 edge2 = frame.scale * Vec3(-0.1f, 0.5f, 1.1f);
    const Quad quad(corner, edge1, edge2, nullptr);
    Random random(7);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 target = quad.pointAt(
            Vec2(static_cast<float>(random.uniform()), static_cast<float>(random.uniform())));
        const Vec3 origin = target + frame.scale * 3 * random.unitVector();
        const Ray ray{origin, normalize(target - origin)};
        Hit hit;
        if (!test::intersectInto(quad, ray, kInfinity, hit)) continue;
        ++hits;
        const long double t = test::planeRoot(ray, test::toLong(corner),
                                              test::Vec3L(cross(Vec3d(edge1), Vec3d(edge2))));
        ASSERT_TRUE(isWithinErrorBound(hit.p, test::pointOnRay(ray, t), hit.pError));
    }
    EXPECT_GT(hits, 1900) << "rays aimed at points of the quad hit it";
}

INSTANTIATE_TEST_SUITE_P(Frames, QuadFrameTest, testing::ValuesIn(test::kSceneFrames),
                         test::frameName);

}  // namespace
}  // namespace lancer
