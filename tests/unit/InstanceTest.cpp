// Instances: a shape carried into the world by a transform.

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "IntersectInto.h"
#include "TestSupport.h"
#include "geometry/Instance.h"
#include "geometry/Sphere.h"
#include "geometry/Triangle.h"
#include "materials/BlinnPhongMaterial.h"

namespace lancer {
namespace {

constexpr float kPi2 = 6.2831853f;

// A unit sphere stretched into an ellipsoid with semi-axes (3, 1, 0.5) centred at (2, 0, 0).
class EllipsoidTest : public ::testing::Test {
protected:
    BlinnPhongMaterial material;
    Vec3 semiAxes{3, 1, 0.5f};
    Vec3 center{2, 0, 0};
    Instance ellipsoid{std::make_shared<Sphere>(Vec3(0), 1.0f, &material),
                       Transform::translate(center) * Transform::scale(semiAxes)};
};

TEST_F(EllipsoidTest, RaysHitTheEllipsoidWhereTheImplicitEquationSaysSo) {
    // Along the x axis from far away: the near end is at x = center.x - 3.
    Hit hit;
    ASSERT_TRUE(test::intersectInto(ellipsoid, {{-10, 0, 0}, {1, 0, 0}}, kInfinity, hit));
    EXPECT_NEAR(hit.t, 9 - 0.0f, 1e-5f);  // from -10 to -1
    EXPECT_NEAR(hit.p.x, -1, 1e-5f);
    // Along z: the near end is at z = 0.5.
    ASSERT_TRUE(test::intersectInto(ellipsoid, {{2, 0, 10}, {0, 0, -2}}, kInfinity, hit));
    EXPECT_NEAR(hit.p.z, 0.5f, 1e-5f);
    EXPECT_NEAR(hit.t, 4.75f, 1e-5f);  // direction of length 2: t is in ray units
}

TEST_F(EllipsoidTest, NormalsAreTheGradientOfTheImplicitEquation) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> angle(0, kPi2);
    for (int i = 0; i < 1000; ++i) {
        // Aim at a random point of the surface from outside along its gradient.
        const float a = angle(rng), b = angle(rng) / 2;
        const Vec3 local(std::cos(a) * std::sin(b), std::cos(b), std::sin(a) * std::sin(b));
        const Vec3 surface =
            center + Vec3(semiAxes.x * local.x, semiAxes.y * local.y, semiAxes.z * local.z);
        const Vec3 gradient =
            normalize(Vec3(local.x / semiAxes.x, local.y / semiAxes.y, local.z / semiAxes.z));
        Hit hit;
        ASSERT_TRUE(
            test::intersectInto(ellipsoid, {surface + 5.0f * gradient, -gradient}, kInfinity, hit));
        EXPECT_NEAR(dot(hit.ng, gradient), 1, 1e-4f);
        EXPECT_NEAR(length(hit.p - surface), 0, 1e-4f);
        EXPECT_NEAR(length(hit.p - (surface + 5.0f * gradient - hit.t * gradient)), 0, 1e-4f);
    }
}

TEST_F(EllipsoidTest, BoundsEncloseTheEllipsoid) {
    const Bounds3 b = ellipsoid.bounds();
    EXPECT_LE(b.min.x, -1.0f);
    EXPECT_GE(b.max.x, 5.0f);
    EXPECT_LE(b.min.z, -0.5f);
    EXPECT_GE(b.max.z, 0.5f);
}

TEST(InstanceTest, SpawnedRaysNeverFindTheSurfaceTheyLeave) {
    BlinnPhongMaterial material;
    // Far from the origin and non-uniformly scaled: the transforms add rounding error of their own.
    const Instance instance(std::make_shared<Sphere>(Vec3(0), 1.0f, &material),
                            Transform::translate({1e4f, -2e3f, 5e3f}) *
                                Transform::rotate(30, {1, 2, 3}) * Transform::scale({300, 20, 7}));
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(-1, 1);
    int outward = 0;
    for (int i = 0; i < 10000; ++i) {
        const Vec3 target(1e4f + 200 * unit(rng), -2e3f + 10 * unit(rng), 5e3f + 3 * unit(rng));
        const Vec3 origin = target + 2000.0f * normalize(Vec3(unit(rng), unit(rng), unit(rng)));
        Hit hit;
        if (!test::intersectInto(instance, {origin, target - origin}, kInfinity, hit)) continue;
        Vec3 direction = normalize(Vec3(unit(rng), unit(rng), unit(rng)));
        if (dot(direction, hit.ng) < 0) direction = -direction;  // leaving the ellipsoid
        Hit again;
        EXPECT_FALSE(test::intersectInto(instance, hit.spawnRay(direction), kInfinity, again));
        ++outward;
    }
    EXPECT_GT(outward, 1000);
}

TEST(InstanceTest, MaterialOverrideReplacesTheShapesMaterial) {
    BlinnPhongMaterial own, replacement;
    const Instance plain(std::make_shared<Sphere>(Vec3(0), 1.0f, &own), Transform());
    const Instance overridden(std::make_shared<Sphere>(Vec3(0), 1.0f, &own), Transform(),
                              &replacement);
    Hit hit;
    ASSERT_TRUE(test::intersectInto(plain, {{0, 0, 5}, {0, 0, -1}}, kInfinity, hit));
    EXPECT_EQ(hit.material, &own);
    ASSERT_TRUE(test::intersectInto(overridden, {{0, 0, 5}, {0, 0, -1}}, kInfinity, hit));
    EXPECT_EQ(hit.material, &replacement);
}

TEST(InstanceTest, WithoutATransformTheShapesOwnHitsPassThrough) {
    // The identity is applied exactly: no shift of t, no widened error bound, no renormalised
    // normal; only the instance's material and itself are put in the record.
    BlinnPhongMaterial own, replacement;
    const auto sphere = std::make_shared<Sphere>(Vec3(0.3f, -0.2f, 0.1f), 1.3f, &own);
    const Instance placed(sphere, Transform(), &replacement);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(-1, 1);
    int hits = 0;
    for (int i = 0; i < 200; ++i) {
        const Ray ray{{uniform(rng) * 1.5f, uniform(rng) * 1.5f, 5},
                      normalize(Vec3(uniform(rng) * 0.3f, uniform(rng) * 0.3f, -1))};
        Hit ownHit, placedHit;
        const bool hitsShape = test::intersectInto(*sphere, ray, kInfinity, ownHit);
        ASSERT_EQ(test::intersectInto(placed, ray, kInfinity, placedHit), hitsShape);
        EXPECT_EQ(placed.occluded(ray, kInfinity), hitsShape);
        if (!hitsShape) continue;
        ++hits;
        EXPECT_EQ(placedHit.t, ownHit.t);
        EXPECT_EQ(placedHit.p, ownHit.p);
        EXPECT_EQ(placedHit.pError, ownHit.pError);
        EXPECT_EQ(placedHit.ng, ownHit.ng);
        EXPECT_EQ(placedHit.ns, ownHit.ns);
        EXPECT_EQ(placedHit.dpdu, ownHit.dpdu);
        EXPECT_EQ(placedHit.uv(), ownHit.uv());
        EXPECT_EQ(placedHit.material, &replacement);
        EXPECT_EQ(placedHit.shape, &placed);
    }
    EXPECT_GT(hits, 50);
}

TEST(InstanceTest, TransformedTriangleMatchesATriangleMadeOfTransformedVertices) {
    BlinnPhongMaterial material;
    const std::array<Vec3, 3> vertices{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    const Transform t = Transform::translate({3, 1, -2}) * Transform::rotate(50, {1, 1, 1}) *
                        Transform::scale({2, 0.5f, 1});
    const Instance instance(std::make_shared<Triangle>(vertices, &material), t);
    const Triangle moved(
        {t.applyPoint(vertices[0]), t.applyPoint(vertices[1]), t.applyPoint(vertices[2])},
        &material);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> unit(0, 1);
    for (int i = 0; i < 1000; ++i) {
        const float u = unit(rng), v = unit(rng) * (1 - u);
        const Vec3 target = t.applyPoint(Vec3(u, v, 0));
        const Vec3 origin = target + Vec3(3, 4, 5);
        Hit a, b;
        const bool hitA = test::intersectInto(instance, {origin, target - origin}, kInfinity, a);
        const bool hitB = test::intersectInto(moved, {origin, target - origin}, kInfinity, b);
        ASSERT_EQ(hitA, hitB);
        if (!hitA) continue;
        EXPECT_NEAR(a.t, b.t, 1e-5f);
        EXPECT_NEAR(dot(a.ng, b.ng), 1, 1e-5f);  // the front side is kept
        EXPECT_NEAR(a.uv().x, b.uv().x, 1e-4f);
        EXPECT_NEAR(a.uv().y, b.uv().y, 1e-4f);
    }
}

TEST(InstanceTest, OcclusionAgreesWithIntersection) {
    BlinnPhongMaterial material;
    const Instance instance(std::make_shared<Sphere>(Vec3(0), 1.0f, &material),
                            Transform::translate({0, 0, -5}) * Transform::scale({2, 1, 1}));
    Hit hit;
    EXPECT_TRUE(instance.occluded({{1.9f, 0, 0}, {0, 0, -1}}, kInfinity));
    EXPECT_FALSE(instance.occluded({{1.9f, 0, 0}, {0, 0, -1}}, 4.0f));
    EXPECT_FALSE(instance.occluded({{2.1f, 0, 0}, {0, 0, -1}}, kInfinity));
    EXPECT_TRUE(test::intersectInto(instance, {{1.9f, 0, 0}, {0, 0, -1}}, kInfinity, hit));
}

}  // namespace
}  // namespace lancer
