// The hit record's surface coordinates: set by the shape, or deferred to it until asked.

#include <gtest/gtest.h>

#include "geometry/Hit.h"
#include "geometry/Instance.h"
#include "geometry/Sphere.h"
#include "math/Transform.h"

namespace lancer {
namespace {

TEST(HitTest, ADeferredUvIsTheShapesUvOfTheLocalPointLeftWithIt) {
    const Sphere sphere(Vec3(0, 0, 0), 2, nullptr);
    const auto hit = sphere.intersect({Vec3(0, 5, 0), Vec3(0, -1, 0)}, kInfinity);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->uv(), sphere.uvAt(Vec3(0, 1, 0)));
    EXPECT_EQ(hit->uv().y, 1) << "the north pole";
}

TEST(HitTest, AUvSetAfterADeferredOneReplacesIt) {
    // A bump map evaluates its heights on copies of the record with shifted uv.
    const Sphere sphere(Vec3(0, 0, 0), 1, nullptr);
    auto hit = sphere.intersect({Vec3(5, 0, 0), Vec3(-1, 0, 0)}, kInfinity);
    ASSERT_TRUE(hit);
    Hit shifted = *hit;
    shifted.setUv({0.25f, 0.75f});
    EXPECT_EQ(shifted.uv(), Vec2(0.25f, 0.75f));
    EXPECT_EQ(hit->uv(), Vec2(0, 0.5f)) << "the original keeps its own";
}

TEST(HitTest, AnInstanceLeavesTheUvOfThePlacedShapeUntouched) {
    // The deferred point is in the placed shape's frame, not the world's.
    auto sphere = std::make_shared<Sphere>(Vec3(0, 0, 0), 1, nullptr);
    const Instance placed(
        sphere, Transform::translate(Vec3(10, 0, 0)) * Transform::rotate(90, Vec3(0, 1, 0)),
        nullptr);
    const Ray ray{Vec3(10, 0, 5), Vec3(0, 0, -1)};
    const auto world = placed.intersect(ray, kInfinity);
    const auto local =
        sphere->intersect({Vec3(-5, 0, 0), Vec3(1, 0, 0)}, kInfinity);  // the same point
    ASSERT_TRUE(world && local);
    EXPECT_NEAR(world->uv().x, local->uv().x, 1e-6f);
    EXPECT_NEAR(world->uv().y, local->uv().y, 1e-6f);
}

}  // namespace
}  // namespace lancer
