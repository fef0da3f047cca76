// The scene's own search (Scene::cross and occluded) against every shape tested one by one: its
// hierarchy over the bounded shapes (one node for a few of them, a tree for more), the lone
// triangles it tests itself with one set-up per ray, and the planes outside the hierarchy.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <tuple>
#include <vector>

#include "BvhTestSupport.h"
#include "geometry/Plane.h"
#include "geometry/Shape.h"
#include "geometry/Sphere.h"
#include "geometry/Triangle.h"
#include "materials/BlinnPhongMaterial.h"
#include "scene/Scene.h"

namespace lancer::test {
namespace {

#ifdef LANCER_SANITIZED
constexpr int kRayCount = 5000;
#else
constexpr int kRayCount = 20000;
#endif

// A scene of `count` shapes in the unit cube, lone triangles and spheres taking turns (a triangle
// first), with a plane under them when asked; `shapes` gets them in the order they were added.
Scene makeScene(int count, bool withPlane, std::uint32_t seed, std::vector<const Shape*>& shapes) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0, 1);
    Scene scene;
    const auto add = [&](std::unique_ptr<Shape> shape) {
        shapes.push_back(shape.get());
        scene.addShape(std::move(shape));
    };
    for (int i = 0; i < count; ++i) {
        const Vec3 c(u(rng), u(rng), u(rng));
        const float size = 0.3f * u(rng) + 0.01f;
        if (i % 2 == 0) {
            add(std::make_unique<Triangle>(std::array<Vec3, 3>{c + size * randomDirection(rng),
                                                               c + size * randomDirection(rng),
                                                               c + size * randomDirection(rng)},
                                           nullptr));
        } else {
            add(std::make_unique<Sphere>(c, 0.3f * size, nullptr));
        }
    }
    if (withPlane) add(std::make_unique<Plane>(Vec3(0, 0.1f, 0), Vec3(0, 1, 0), nullptr));
    scene.buildAccelerationStructure();
    return scene;
}

// The nearest crossing of every shape tested one by one (the first added, of several at exactly
// the nearest t).
std::optional<SceneCrossing> bruteForce(const std::vector<const Shape*>& shapes, const Ray& ray,
                                        float tMax) {
    std::optional<SceneCrossing> nearest;
    for (const Shape* shape : shapes) {
        if (const std::optional<SurfaceCrossing> crossing = shape->cross(ray, tMax)) {
            nearest = SceneCrossing{shape, *crossing};
            tMax = static_cast<float>(crossing->t);
        }
    }
    return nearest;
}

// kRayCount rays: half in random directions, half aimed at a point in the box of one of the
// first `count` shapes (the bounded ones).
std::vector<Ray> raysAtShapes(const std::vector<const Shape*>& shapes, int count,
                              std::uint32_t seed) {
    std::vector<Ray> rays = randomRays(Bounds3(Vec3(0), Vec3(1)), kRayCount / 2, seed);
    std::mt19937 rng(seed + 1);
    std::uniform_int_distribution<std::size_t> pickShape(0, static_cast<std::size_t>(count) - 1);
    while (rays.size() < static_cast<std::size_t>(kRayCount)) {
        const Vec3 origin = Vec3(0.5f) + 2.0f * randomDirection(rng);
        rays.push_back({origin, randomPointIn(shapes[pickShape(rng)]->bounds(), rng) - origin});
    }
    return rays;
}

void expectSceneMatchesBruteForce(int count, bool withPlane, std::uint32_t seed) {
    std::vector<const Shape*> shapes;
    const Scene scene = makeScene(count, withPlane, seed, shapes);
    const std::vector<Ray> rays = raysAtShapes(shapes, count, seed + 1);
    std::mt19937 rng(seed + 2);
    std::uniform_real_distribution<float> u(0, 1);
    int hits = 0;
    for (const Ray& ray : rays) {
        const float tMax = u(rng) < 0.5f ? kInfinity : 3 * u(rng);
        const std::optional<SceneCrossing> expected = bruteForce(shapes, ray, tMax);
        const std::optional<SceneCrossing> actual = scene.cross(ray, tMax);
        ASSERT_EQ(actual.has_value(), expected.has_value()) << describe(ray);
        ASSERT_EQ(scene.occluded(ray, tMax), expected.has_value()) << describe(ray);
        if (!expected) continue;
        ++hits;
        // The same t to the bit, and the same numbers of the same shape, unless two shapes are
        // crossed at exactly that t.
        ASSERT_EQ(actual->crossing.t, expected->crossing.t) << describe(ray);
        if (actual->shape != expected->shape) continue;
        EXPECT_EQ(actual->crossing.tShape, expected->crossing.tShape) << describe(ray);
        EXPECT_EQ(actual->crossing.primitive, expected->crossing.primitive) << describe(ray);
        EXPECT_EQ(actual->crossing.b0, expected->crossing.b0) << describe(ray);
        EXPECT_EQ(actual->crossing.b1, expected->crossing.b1) << describe(ray);
        EXPECT_EQ(actual->crossing.b2, expected->crossing.b2) << describe(ray);
    }
    // Enough rays meet something for the comparison to mean something.
    EXPECT_GT(hits, kRayCount / 8);
}

// Up to eight bounded shapes make a hierarchy of one node. Of two, one is a lone triangle, which
// the scene leaves to test itself; from three on, two are.
TEST(SceneTraversal, AFewShapesMatchBruteForce) {
    expectSceneMatchesBruteForce(2, false, 7);
    expectSceneMatchesBruteForce(3, false, 1);
    expectSceneMatchesBruteForce(8, false, 2);
}

TEST(SceneTraversal, ManyShapesMatchBruteForce) {
    expectSceneMatchesBruteForce(200, false, 3);
}

TEST(SceneTraversal, ShapesOverAPlaneMatchBruteForce) {
    expectSceneMatchesBruteForce(5, true, 4);
    expectSceneMatchesBruteForce(60, true, 5);
}

// Every crossing of a segment with every shape tested one by one, in increasing t.
std::vector<SceneCrossing> everyCrossing(const std::vector<const Shape*>& shapes, const Ray& ray,
                                         float tMax) {
    std::vector<SceneCrossing> all;
    for (const Shape* shape : shapes) {
        SurfaceCrossings crossings;
        shape->crossSegment(ray, tMax, crossings);
        for (const SurfaceCrossing& crossing : crossings)
            all.push_back({shape, crossing});
    }
    std::stable_sort(all.begin(), all.end(), [](const SceneCrossing& a, const SceneCrossing& b) {
        return a.crossing.t < b.crossing.t;
    });
    return all;
}

// The scene's one search along a segment finds what every shape finds on its own, in order;
// with shapes of no material nothing stops it.
TEST(SceneTraversal, ASegmentCrossesWhatEveryShapeCrossesInOrder) {
    for (const auto& [count, withPlane, seed] :
         {std::tuple{3, false, 11u}, {8, true, 12u}, {200, true, 13u}}) {
        std::vector<const Shape*> shapes;
        const Scene scene = makeScene(count, withPlane, seed, shapes);
        const std::vector<Ray> rays = raysAtShapes(shapes, count, seed + 1);
        std::mt19937 rng(seed + 2);
        std::uniform_real_distribution<float> u(0, 1);
        std::size_t several = 0;
        std::vector<SceneCrossing> crossings;
        for (const Ray& ray : rays) {
            const float tMax = u(rng) < 0.5f ? kInfinity : 3 * u(rng);
            const std::vector<SceneCrossing> expected = everyCrossing(shapes, ray, tMax);
            ASSERT_TRUE(scene.crossSegment(ray, tMax, crossings)) << describe(ray);
            ASSERT_EQ(crossings.size(), expected.size()) << describe(ray);
            for (std::size_t k = 0; k < crossings.size(); ++k) {
                ASSERT_EQ(crossings[k].crossing.t, expected[k].crossing.t) << describe(ray);
                EXPECT_EQ(crossings[k].crossing.primitive, expected[k].crossing.primitive);
            }
            several += crossings.size() > 1;
        }
        // Many rays meet two crossings or more (the aimed ones cross both sides of a sphere).
        EXPECT_GT(several, rays.size() / 20) << count << " shapes";
    }
}

// A segment that crosses an opaque surface anywhere on it is blocked; one that crosses only
// glass lists it.
TEST(SceneTraversal, ASegmentIsBlockedByAnyOpaqueSurfaceOnIt) {
    Scene scene;
    BlinnPhongMaterial::Parameters clear;
    clear.transmission = Color(0.9f);
    const Material* glass = scene.addMaterial(std::make_unique<BlinnPhongMaterial>(clear));
    const Material* opaque = scene.addMaterial(std::make_unique<BlinnPhongMaterial>());
    std::vector<const Shape*> shapes;
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 40; ++i) {
        auto sphere = std::make_unique<Sphere>(Vec3(u(rng), u(rng), u(rng)), 0.05f + 0.1f * u(rng),
                                               i % 4 == 0 ? opaque : glass);
        shapes.push_back(sphere.get());
        scene.addShape(std::move(sphere));
    }
    scene.buildAccelerationStructure();
    int blocked = 0, throughGlass = 0;
    std::vector<SceneCrossing> crossings;
    for (const Ray& ray : randomRays(Bounds3(Vec3(0), Vec3(1)), kRayCount / 4, 22)) {
        const float tMax = u(rng) < 0.5f ? kInfinity : 2 * u(rng);
        const std::vector<SceneCrossing> expected = everyCrossing(shapes, ray, tMax);
        const bool opaqueOnIt =
            std::any_of(expected.begin(), expected.end(),
                        [&](const SceneCrossing& c) { return c.shape->material() == opaque; });
        ASSERT_EQ(scene.crossSegment(ray, tMax, crossings), !opaqueOnIt) << describe(ray);
        if (opaqueOnIt) {
            ++blocked;
            continue;
        }
        ASSERT_EQ(crossings.size(), expected.size()) << describe(ray);
        throughGlass += !crossings.empty();
    }
    EXPECT_GT(blocked, kRayCount / 40);
    EXPECT_GT(throughGlass, kRayCount / 40);
}

// The crossing of a lone triangle the scene tests itself is the triangle's own, the record too.
TEST(SceneTraversal, ALoneTriangleIsRecordedByItsShape) {
    std::vector<const Shape*> shapes;
    const Scene scene = makeScene(1, false, 6, shapes);
    const std::array<Vec3, 3> corners = *shapes[0]->loneTriangle();
    const Vec3 centre = (corners[0] + corners[1] + corners[2]) / 3.0f;
    const Ray ray{centre + Vec3(0.1f, 0.2f, 2), Vec3(-0.1f, -0.2f, -2)};
    const std::optional<SceneCrossing> crossing = scene.cross(ray, kInfinity);
    ASSERT_TRUE(crossing.has_value());
    EXPECT_EQ(crossing->shape, shapes[0]);
    const std::optional<Hit> own = shapes[0]->intersect(ray, kInfinity);
    ASSERT_TRUE(own.has_value());
    const Hit hit = scene.record(ray, *crossing);
    EXPECT_EQ(hit.t, own->t);
    EXPECT_EQ(hit.p, own->p);
    EXPECT_EQ(hit.ng, own->ng);
    EXPECT_EQ(hit.shape, shapes[0]);
}

}  // namespace
}  // namespace lancer::test
