// Ray/triangle intersection (watertight), normals, shading normals and uvs.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

#include "IntersectInto.h"
#include "TestSupport.h"
#include "accel/Mesh.h"
#include "geometry/Triangle.h"
#include "math/Float.h"

namespace lancer {
namespace {

using test::isFiniteHit;
using test::isUntouched;
using test::isWithinErrorBound;
using test::Random;
using test::SceneFrame;
using test::untouchedHit;
using test::Vec3L;

constexpr float kTolerance = 1e-6f;

using Vertices = std::array<Vec3, 3>;

// The right triangle (0,0,0), (1,0,0), (0,1,0) in the z = 0 plane; its front faces +z.
const Vertices kUnitRightTriangle{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};

// The point of the triangle with barycentric coordinates (1 - b1 - b2, b1, b2).
Vec3 pointAt(const Vertices& v, float b1, float b2) {
    return (1 - b1 - b2) * v[0] + b1 * v[1] + b2 * v[2];
}

// The exact meeting of a ray's line with the plane of the triangle v, in extended precision.
struct ExactCrossing {
    long double t;
    Vec3L p;
    long double edgeDistance;  // from p to the nearest edge line, negative outside the triangle
};

ExactCrossing exactCrossing(const Ray& ray, const Vertices& v) {
    const Vec3L v0 = test::toLong(v[0]), v1 = test::toLong(v[1]), v2 = test::toLong(v[2]);
    const Vec3L n = cross(v1 - v0, v2 - v0);
    ExactCrossing c;
    c.t = test::planeRoot(ray, v0, n);
    c.p = test::pointOnRay(ray, c.t);
    // Signed distance to the line of each edge: (twice) the sub-triangle's area over its length.
    const Vec3L unitN = normalize(n);
    const Vec3L corners[3] = {v0, v1, v2};
    c.edgeDistance = std::numeric_limits<long double>::infinity();
    for (int i = 0; i < 3; ++i) {
        const Vec3L& a = corners[(i + 1) % 3];
        const Vec3L& b = corners[(i + 2) % 3];
        const long double distance = dot(cross(b - a, c.p - a), unitN) / length(b - a);
        c.edgeDistance = std::min(c.edgeDistance, distance);
    }
    return c;
}

// Checks triangle.intersect(ray, tMax) against the exact answer. Within the plane, the computed
// barycentrics carry rounding errors that grow as the ray grazes the triangle, measured at up
// to 5.4 eps |coordinates| / cos; 16 is allowed. Across the plane, the direction spawned rays
// are offset along, pError bounds the error (as in pbrt: it covers the rounding of
// b0 v0 + b1 v1 + b2 v2 for the computed barycentrics). Rays that pass within the in-plane
// tolerance of an edge may go either way.
testing::AssertionResult agreesWithExactIntersection(const Triangle& triangle, const Vertices& v,
                                                     const Ray& ray, float tMax = kInfinity) {
    const ExactCrossing exact = exactCrossing(ray, v);
    const Vec3L unitN = normalize(
        cross(test::toLong(v[1]) - test::toLong(v[0]), test::toLong(v[2]) - test::toLong(v[0])));
    const float cosine = std::abs(dot(normalize(ray.direction), Vec3(unitN)));
    const float coordinates = std::max({maxComponent(abs(v[0])), maxComponent(abs(v[1])),
                                        maxComponent(abs(v[2])), maxComponent(abs(ray.origin))});
    const long double inPlaneTolerance = 16 * kMachineEpsilon * coordinates / cosine;
    const long double tMargin = 1e-3L * std::fabs(exact.t);
    const bool inside =
        exact.edgeDistance > inPlaneTolerance && exact.t > tMargin && exact.t < tMax - tMargin;
    const bool outside =
        exact.edgeDistance < -inPlaneTolerance || exact.t < -tMargin || exact.t > tMax + tMargin;
    Hit hit;
    if (!test::intersectInto(triangle, ray, tMax, hit)) {
        if (inside)
            return testing::AssertionFailure()
                   << "missed a triangle that the ray crosses "
                   << static_cast<double>(exact.edgeDistance)
                   << " inside its edges at t = " << static_cast<double>(exact.t);
        return testing::AssertionSuccess();
    }
    if (outside)
        return testing::AssertionFailure()
               << "hit a triangle that the ray passes " << static_cast<double>(-exact.edgeDistance)
               << " outside of, at t = " << static_cast<double>(exact.t);
    if (!isFiniteHit(hit)) return isFiniteHit(hit);
    const Vec3L error = test::toLong(hit.p) - exact.p;
    const long double acrossError = std::fabs(dot(error, unitN));
    const long double acrossBound = dot(abs(unitN), test::toLong(hit.pError));
    if (!(acrossError <= acrossBound))
        return testing::AssertionFailure()
               << "the hit point is " << static_cast<double>(acrossError)
               << " off the plane, beyond its error bound " << static_cast<double>(acrossBound);
    if (!(length(error) <= inPlaneTolerance))
        return testing::AssertionFailure()
               << "the hit point is " << static_cast<double>(length(error))
               << " from the exact one (tolerance " << static_cast<double>(inPlaneTolerance)
               << ", cosine " << cosine << ")";
    return testing::AssertionSuccess();
}

TEST(TriangleTest, HitsFromTheFront) {
    const Triangle triangle(kUnitRightTriangle, nullptr);
    Hit hit;
    ASSERT_TRUE(
        test::intersectInto(triangle, {Vec3(0.25f, 0.25f, 1), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_EQ(hit.t, 1);
    EXPECT_VEC3_NEAR(hit.p, Vec3(0.25f, 0.25f, 0), kTolerance);
    EXPECT_EQ(hit.ng, Vec3(0, 0, 1));  // (v1 - v0) x (v2 - v0)
    EXPECT_EQ(hit.ns, Vec3(0, 0, 1));
    EXPECT_EQ(hit.shape, &triangle);
}

TEST(TriangleTest, HitsFromTheBackWithTheSameNormal) {
    const Triangle triangle(kUnitRightTriangle, nullptr);
    const Ray fromBehind{Vec3(0.25f, 0.5f, -2), Vec3(0, 0, 1)};
    Hit hit;
    ASSERT_TRUE(test::intersectInto(triangle, fromBehind, kInfinity, hit));
    EXPECT_EQ(hit.t, 2);
    EXPECT_EQ(hit.ng, Vec3(0, 0, 1));
    EXPECT_FALSE(hit.frontFace(fromBehind));
}

TEST(TriangleTest, MissesOutsideTheEdges) {
    const Triangle triangle(kUnitRightTriangle, nullptr);
    Hit hit = untouchedHit();
    for (const Vec3& beside :
         {Vec3(0.75f, 0.75f, 1), Vec3(-0.1f, 0.5f, 1), Vec3(0.5f, -0.1f, 1), Vec3(2, 2, 1)})
        EXPECT_FALSE(test::intersectInto(triangle, {beside, Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_TRUE(isUntouched(hit));
}

TEST(TriangleTest, DoesNotReportAHitBehindTheOrigin) {
    const Triangle triangle(kUnitRightTriangle, nullptr);
    Hit hit = untouchedHit();
    EXPECT_FALSE(
        test::intersectInto(triangle, {Vec3(0.25f, 0.25f, -1), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_FALSE(
        test::intersectInto(triangle, {Vec3(0.25f, 0.25f, 1), Vec3(0, 0, 1)}, kInfinity, hit));
    EXPECT_TRUE(isUntouched(hit));
}

TEST(TriangleTest, RespectsTMax) {
    const Triangle triangle(kUnitRightTriangle, nullptr);
    const Ray ray{Vec3(0.25f, 0.25f, 3), Vec3(0, 0, -1)};
    Hit hit = untouchedHit();
    EXPECT_FALSE(test::intersectInto(triangle, ray, 3, hit));
    EXPECT_FALSE(test::intersectInto(triangle, ray, 2, hit));
    EXPECT_TRUE(isUntouched(hit));
    ASSERT_TRUE(test::intersectInto(triangle, ray, nextFloatUp(3), hit));
    EXPECT_EQ(hit.t, 3);
}

TEST(TriangleTest, ParallelRaysMissWithoutNaN) {
    const Triangle triangle(kUnitRightTriangle, nullptr);
    Hit hit = untouchedHit();
    // Above the plane, and in the plane itself, straight across the triangle.
    EXPECT_FALSE(
        test::intersectInto(triangle, {Vec3(-1, 0.25f, 0.5f), Vec3(1, 0, 0)}, kInfinity, hit));
    EXPECT_FALSE(
        test::intersectInto(triangle, {Vec3(-1, 0.25f, 0), Vec3(1, 0, 0)}, kInfinity, hit));
    EXPECT_FALSE(test::intersectInto(triangle, {Vec3(-1, -1, 0), Vec3(1, 1, 0)}, kInfinity, hit));
    EXPECT_FALSE(
        test::intersectInto(triangle, {Vec3(0.2f, 0.2f, 0), Vec3(0, 1, 0)}, kInfinity, hit));
    EXPECT_TRUE(isUntouched(hit));
}

TEST(TriangleTest, DirectionLengthDoesNotChangeTheHitPoint) {
    const Vertices v{Vec3(-1, -0.5f, 0.2f), Vec3(1.2f, -0.3f, -0.4f), Vec3(0.1f, 1.1f, 0.3f)};
    const Triangle triangle(v, nullptr);
    Random random(31);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 target = pointAt(v, static_cast<float>(random.uniform(0.05, 0.45)),
                                    static_cast<float>(random.uniform(0.05, 0.45)));
        const Vec3 origin = target + 3.0f * random.unitVector();
        const Vec3 toTarget = target - origin;  // of any length
        ASSERT_TRUE(agreesWithExactIntersection(triangle, v, {origin, toTarget})) << "ray " << i;
        Hit hit;
        ASSERT_TRUE(test::intersectInto(triangle, {origin, toTarget}, kInfinity, hit));
        // Power-of-two scales change the direction exactly, so the ray is the same.
        for (float scale : {0x1p-10f, 0.125f, 8.0f, 1024.0f}) {
            Hit scaled;
            ASSERT_TRUE(
                test::intersectInto(triangle, {origin, scale * toTarget}, kInfinity, scaled))
                << "ray " << i << " scaled by " << scale;
            EXPECT_TRUE(isWithinErrorBound(scaled.p, test::toLong(hit.p), hit.pError));
            EXPECT_NEAR(scaled.t * scale, hit.t, kTolerance * hit.t);
        }
    }
}

TEST(TriangleTest, GeometricNormalFollowsTheVertexOrder) {
    Random random(32);
    for (int i = 0; i < 1000; ++i) {
        const Vertices v{random.pointInBox(2), random.pointInBox(2), random.pointInBox(2)};
        const Triangle triangle(v, nullptr);
        const Vec3L expected = normalize(cross(test::toLong(v[1]) - test::toLong(v[0]),
                                               test::toLong(v[2]) - test::toLong(v[0])));
        const Vec3 centroid = (v[0] + v[1] + v[2]) / 3.0f;
        for (float side : {1.0f, -1.0f}) {
            const Vec3 origin = centroid + side * Vec3(expected);
            Hit hit;
            if (!test::intersectInto(triangle, {origin, centroid - origin}, kInfinity, hit)) {
                ADD_FAILURE() << "no hit at the centroid of triangle " << i;
                continue;
            }
            EXPECT_VEC3_NEAR(hit.ng, Vec3(expected), 1e-5f);
        }
    }
}

TEST(TriangleTest, ZeroAreaTrianglesNeverHit) {
    const Vertices degenerate[] = {
        {Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 1, 0)},            // two equal vertices
        {Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3)},            // a point
        {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)},            // collinear
        {Vec3(-1, 0.5f, 2), Vec3(3, 0.5f, 2), Vec3(1, 0.5f, 2)},  // collinear, middle last
    };
    Random random(33);
    for (const Vertices& v : degenerate) {
        const Triangle triangle(v, nullptr);
        EXPECT_EQ(triangle.area(0), 0);
        for (int i = 0; i < 10000; ++i) {
            // Aim at points of the segment (or point) the triangle collapses to.
            const Vec3 target = pointAt(v, static_cast<float>(random.uniform()),
                                        static_cast<float>(random.uniform()));
            const Vec3 origin = target + 5.0f * random.unitVector();
            Hit hit = untouchedHit();
            EXPECT_FALSE(test::intersectInto(triangle, {origin, target - origin}, kInfinity, hit));
            EXPECT_TRUE(isUntouched(hit));
        }
    }
}

// Rays through a random point of an edge shared by two triangles hit at least one of them: the
// watertight test leaves no crack between neighbours.
TEST(TriangleTest, SharedEdgeHasNoCracks) {
    // Two triangles folded slightly (6 degrees) along the edge a b, consistently oriented.
    const Vec3 a(-1.3f, 0.2f, 0.7f), b(1.1f, -0.4f, 0.3f);
    const Vec3 c(0.3f, 1.7f, -0.2f), d(-0.2f, -1.9f, 0.9f);
    const Triangle left({a, b, c}, nullptr);
    const Triangle right({b, a, d}, nullptr);
    const Vec3 leftNormal = cross(b - a, c - a), rightNormal = cross(a - b, d - b);
    Random random(34);
    int misses = 0;
    for (int i = 0; i < 100000; ++i) {
        // The point on the edge is rounded, so the ray passes just beside it; that is covered
        // only where the two triangles lie on either side of the edge as the ray sees them,
        // that is, where it meets both from the same side. (Seen edge-on, in the 6 degree
        // wedge, the ridge is a silhouette that a ray may rightly pass.)
        const Vec3 onEdge = a + static_cast<float>(random.uniform()) * (b - a);
        const Vec3 origin = onEdge + 4.0f * random.unitVector();
        const Ray ray{origin, onEdge - origin};
        if ((dot(ray.direction, leftNormal) > 0) != (dot(ray.direction, rightNormal) > 0)) continue;
        Hit hit;
        if (!test::intersectInto(left, ray, kInfinity, hit) &&
            !test::intersectInto(right, ray, kInfinity, hit))
            ++misses;
    }
    EXPECT_EQ(misses, 0);
}

TEST(TriangleTest, UvInterpolatesTheVertexUvs) {
    const std::array<Vec2, 3> uvs{Vec2(0, 0), Vec2(1, 0), Vec2(0.5f, 1)};
    const Triangle triangle(kUnitRightTriangle, nullptr, std::nullopt, uvs);
    Random random(35);
    for (int i = 0; i < 1000; ++i) {
        const float b1 = static_cast<float>(random.uniform(0, 0.5));
        const float b2 = static_cast<float>(random.uniform(0, 0.5));
        Hit hit;
        ASSERT_TRUE(
            test::intersectInto(triangle, {Vec3(b1, b2, 1), Vec3(0, 0, -1)}, kInfinity, hit));
        // The hit point (b1, b2) on this triangle has barycentrics (1 - b1 - b2, b1, b2).
        EXPECT_NEAR(hit.uv().x, b1 + 0.5f * b2, kTolerance);
        EXPECT_NEAR(hit.uv().y, b2, kTolerance);
    }
}

TEST(TriangleTest, DefaultUvsAreTheUnitRightTriangle) {
    const Vertices v{Vec3(2, 0, -1), Vec3(4, 0, -1), Vec3(2, 0, -5)};  // in the y = 0 plane
    const Triangle triangle(v, nullptr);
    for (const Vec2& b : {Vec2(0.2f, 0.3f), Vec2(0.6f, 0.1f), Vec2(0.05f, 0.9f)}) {
        Hit hit;
        ASSERT_TRUE(test::intersectInto(
            triangle, {pointAt(v, b.x, b.y) + Vec3(0, 2, 0), Vec3(0, -1, 0)}, kInfinity, hit));
        // Default uvs (0,0), (1,0), (0,1): uv = (b1, b2).
        EXPECT_NEAR(hit.uv().x, b.x, kTolerance);
        EXPECT_NEAR(hit.uv().y, b.y, kTolerance);
    }
}

// A triangle keeps its front normal and density for its samples (a light samples it often): they
// must be, to the bit, what its vertices give, the normalized edge product and one over the area,
// for triangles of every size and orientation.
TEST(TriangleTest, SamplesCarryTheNormalizedEdgeProductAndOneOverTheArea) {
    Random random(71);
    for (int i = 0; i < 2000; ++i) {
        const float scale = static_cast<float>(std::pow(10.0, random.uniform(-15, 15)));
        const Vec3 origin = random.unitVector() * static_cast<float>(random.uniform(0, 100));
        const Vertices v{origin, origin + scale * random.unitVector(),
                         origin + scale * random.unitVector()};
        const Triangle triangle(v, nullptr);
        const Vec2 u(static_cast<float>(random.uniform()), static_cast<float>(random.uniform()));
        const std::optional<ShapeSample> kept = triangle.sample(0, u);
        const ShapeSample fromVertices = Triangle::sampleUniformly(v, u);
        ASSERT_TRUE(kept);
        const Vec3 normal = normalize(cross(v[1] - v[0], v[2] - v[0]));
        const float density = 1 / Triangle::areaOf(v);
        for (const ShapeSample& s : {*kept, fromVertices}) {
            EXPECT_EQ(s.p, fromVertices.p);
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_EQ(std::bit_cast<std::uint32_t>(s.n[axis]),
                          std::bit_cast<std::uint32_t>(normal[axis]))
                    << "triangle " << i << ", axis " << axis;
            EXPECT_EQ(std::bit_cast<std::uint32_t>(s.pdf), std::bit_cast<std::uint32_t>(density))
                << "triangle " << i << " of scale " << scale;
        }
    }
}

// A triangle keeps the frame its hits share (normal, dp/du, dp/dv): its records must be, to the
// bit, those of the same triangle in a mesh, which works them out at every hit.
TEST(TriangleTest, RecordsEqualThoseOfTheSameTriangleInAMesh) {
    Random random(72);
    for (int i = 0; i < 500; ++i) {
        const Vertices v{random.unitVector(), random.unitVector(), random.unitVector()};
        std::optional<std::array<Vec2, 3>> uvs;
        if (i % 2 == 0) {
            uvs.emplace();
            for (Vec2& uv : *uvs)
                uv = Vec2(static_cast<float>(random.uniform(-2, 2)),
                          static_cast<float>(random.uniform(-2, 2)));
        }
        if (i % 10 == 4) (*uvs)[2] = (*uvs)[1];  // uvs that do not span the triangle
        const Triangle triangle(v, nullptr, std::nullopt, uvs);
        TriangleMesh triangles;
        triangles.positions.assign(v.begin(), v.end());
        if (uvs) triangles.uvs.assign(uvs->begin(), uvs->end());
        triangles.indices = {0, 1, 2};
        triangles.faceMaterials = {0};
        const Mesh mesh(std::move(triangles));

        const Vec3 target = pointAt(v, 0.3f, 0.3f);
        const Vec3 origin = target + 2.0f * random.unitVector();
        const Ray towards{origin, target - origin};
        Hit fromTriangle, fromMesh;
        if (!test::intersectInto(triangle, towards, kInfinity, fromTriangle)) continue;
        ASSERT_TRUE(test::intersectInto(mesh, towards, kInfinity, fromMesh)) << "triangle " << i;
        EXPECT_EQ(fromTriangle.t, fromMesh.t);
        EXPECT_EQ(fromTriangle.p, fromMesh.p);
        EXPECT_EQ(fromTriangle.ng, fromMesh.ng) << "triangle " << i;
        EXPECT_EQ(fromTriangle.ns, fromMesh.ns);
        EXPECT_EQ(fromTriangle.dpdu, fromMesh.dpdu) << "triangle " << i;
        EXPECT_EQ(fromTriangle.dpdv, fromMesh.dpdv) << "triangle " << i;
        EXPECT_EQ(fromTriangle.uv().x, fromMesh.uv().x);
        EXPECT_EQ(fromTriangle.uv().y, fromMesh.uv().y);
    }
}

TEST(TriangleTest, ShadingNormalInterpolatesVertexNormals) {
    const std::array<Vec3, 3> normals{normalize(Vec3(-1, -1, 1)), normalize(Vec3(1, 0, 1)),
                                      normalize(Vec3(0, 1, 1))};
    const Triangle triangle(kUnitRightTriangle, nullptr, normals);
    Random random(36);
    for (int i = 0; i < 1000; ++i) {
        const float b1 = static_cast<float>(random.uniform(0, 0.5));
        const float b2 = static_cast<float>(random.uniform(0, 0.5));
        Hit hit;
        ASSERT_TRUE(
            test::intersectInto(triangle, {Vec3(b1, b2, 1), Vec3(0, 0, -1)}, kInfinity, hit));
        const Vec3 expected =
            normalize((1 - b1 - b2) * normals[0] + b1 * normals[1] + b2 * normals[2]);
        EXPECT_VEC3_NEAR(hit.ns, expected, kTolerance);
        EXPECT_EQ(hit.ng, Vec3(0, 0, 1));  // the geometric normal is unaffected
    }
}

TEST(TriangleTest, ShadingNormalIsTurnedToTheGeometricSide) {
    // Vertex normals that all face the back: the shading normal stays in ng's hemisphere.
    const std::array<Vec3, 3> backwards{normalize(Vec3(0.1f, 0, -1)), normalize(Vec3(0, 0.2f, -1)),
                                        Vec3(0, 0, -1)};
    const Triangle triangle(kUnitRightTriangle, nullptr, backwards);
    Hit hit;
    ASSERT_TRUE(
        test::intersectInto(triangle, {Vec3(0.25f, 0.25f, 1), Vec3(0, 0, -1)}, kInfinity, hit));
    const Vec3 interpolated =
        normalize(0.5f * backwards[0] + 0.25f * backwards[1] + 0.25f * backwards[2]);
    EXPECT_VEC3_NEAR(hit.ns, -interpolated, kTolerance);
    EXPECT_GT(dot(hit.ns, hit.ng), 0);
}

TEST(TriangleTest, OppositeVertexNormalsCancellingFallBackToTheGeometricNormal) {
    // At the midpoint of edge v1 v2 the two normals sum to zero: no NaN, the flat normal instead.
    const std::array<Vec3, 3> normals{Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(-1, 0, 0)};
    const Triangle triangle(kUnitRightTriangle, nullptr, normals);
    Hit hit;
    ASSERT_TRUE(
        test::intersectInto(triangle, {Vec3(0.5f, 0.5f, 1), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_TRUE(isFiniteHit(hit));
    EXPECT_NEAR(length(hit.ns), 1, kTolerance);
}

class TriangleInFrameTest : public testing::TestWithParam<SceneFrame> {
protected:
    TriangleInFrameTest()
        : v_{GetParam().place(Vec3(-1, -0.5f, 0.2f)), GetParam().place(Vec3(1.2f, -0.3f, -0.4f)),
             GetParam().place(Vec3(0.1f, 1.1f, 0.3f))},
          triangle_(v_, nullptr),
          random_(37) {}

    // A random point well inside the triangle.
    Vec3 randomInteriorPoint() {
        return pointAt(v_, static_cast<float>(random_.uniform(0.02, 0.48)),
                       static_cast<float>(random_.uniform(0.02, 0.48)));
    }

    Vertices v_;
    Triangle triangle_;
    Random random_;
};

TEST_P(TriangleInFrameTest, AgreesWithAnExtendedPrecisionReference) {
    const float scale = GetParam().scale;
    for (int i = 0; i < 10000; ++i) {
        const Vec3 target = randomInteriorPoint();
        const Vec3 origin = target + scale * 5.0f * random_.unitVector();
        ASSERT_TRUE(agreesWithExactIntersection(triangle_, v_, {origin, target - origin}))
            << "ray " << i;
    }
}

// A shadow ray's direction is the whole segment to the light, of any length: a segment through
// the triangle must be blocked by it, at any scale.
TEST_P(TriangleInFrameTest, SegmentsThroughTheTriangleAreBlocked) {
    const float scale = GetParam().scale;
    for (int i = 0; i < 10000; ++i) {
        const Vec3 target = randomInteriorPoint();
        const Vec3 towards = random_.unitVector();
        const float before = scale * static_cast<float>(std::pow(10.0, random_.uniform(-2, 1)));
        const float after = scale * static_cast<float>(std::pow(10.0, random_.uniform(-2, 1)));
        const Vec3 from = target + before * towards, to = target - after * towards;
        ASSERT_TRUE(
            agreesWithExactIntersection(triangle_, v_, {from, to - from}, 1 - kShadowEpsilon))
            << "segment " << i << " of length " << before + after;
    }
}

INSTANTIATE_TEST_SUITE_P(Frames, TriangleInFrameTest, testing::ValuesIn(test::kSceneFrames),
                         test::frameName);

}  // namespace
}  // namespace lancer
