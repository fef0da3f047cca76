// Closest hits and occlusion through the BVH against brute force, on random soups, a closed mesh,
// spheres and a mix of shapes, for random, inside, axis-parallel and boundary rays.

#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "BvhTestSupport.h"
#include "IntersectInto.h"
#include "accel/Bvh.h"
#include "geometry/Hit.h"
#include "geometry/Shape.h"
#include "geometry/Sphere.h"
#include "geometry/Triangle.h"

namespace lancer::test {
namespace {

// Brute force is the cost of these tests: the sanitizers make it about 3x slower.
#ifdef LANCER_SANITIZED
constexpr int kRayCount = 30000;
#else
constexpr int kRayCount = 100000;
#endif

// Checks for every ray that the BVH's closest hit is brute force's (the same t to the bit, the same
// primitive unless two are hit at exactly that t) and that occluded(ray, tMax) == (closest t <
// tMax). original(i, ray, tMax) tests primitive i in its original order, leafOrder(k, ray, tMax)
// primitive k in the BVH's leaf order; both return the t of a hit in (0, tMax) or nothing.
template <typename IntersectOriginal, typename IntersectLeafOrder>
void expectBvhMatchesBruteForce(const Bvh& bvh, const BruteForce& bruteForce,
                                const std::vector<Ray>& rays, IntersectOriginal&& original,
                                IntersectLeafOrder&& leafOrder, bool mustHit = false) {
    struct Result {
        ClosestHit expected, actual;
        bool occludedBeyond, occludedAfterHit, occludedAtHit, occludedBefore;
    };
    std::vector<Result> results(rays.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size()), [&](const auto& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            Result& r = results[i];
            r.expected = bruteForce.closest(rays[i], original);
            r.actual = bvhClosest(bvh, rays[i], leafOrder);
            // tMax beyond, after, at and before the closest hit.
            r.occludedBeyond = bvhOccluded(bvh, rays[i], kInfinity, leafOrder);
            r.occludedAfterHit = bvhOccluded(bvh, rays[i], 1.5f * r.expected.t, leafOrder);
            r.occludedAtHit = bvhOccluded(bvh, rays[i], r.expected.t, leafOrder);
            r.occludedBefore = bvhOccluded(bvh, rays[i], 0.5f * r.expected.t, leafOrder);
        }
    });

    int hits = 0, ties = 0, failures = 0;
    for (std::size_t i = 0; i < rays.size() && failures < 10; ++i) {
        const Result& r = results[i];
        const bool hit = r.expected.primitive >= 0;
        hits += hit;
        const auto where = [&] { return "ray " + std::to_string(i) + " " + describe(rays[i]); };
        bool ok =
            std::bit_cast<std::uint32_t>(r.actual.t) == std::bit_cast<std::uint32_t>(r.expected.t);
        EXPECT_EQ(r.actual.t, r.expected.t) << where();
        if (r.actual.primitive != r.expected.primitive) {
            // Two primitives hit at exactly the same t (a shared edge or vertex): either is right.
            const bool tie = ok && r.actual.primitive >= 0 &&
                             original(static_cast<std::uint32_t>(r.actual.primitive), rays[i],
                                      kInfinity) == std::optional<float>(r.expected.t);
            ties += tie;
            ok = ok && tie;
            EXPECT_TRUE(tie) << where() << ": primitive " << r.actual.primitive << " instead of "
                             << r.expected.primitive;
        }
        EXPECT_EQ(r.occludedBeyond, hit) << where();
        EXPECT_EQ(r.occludedAfterHit, hit) << where();
        EXPECT_FALSE(r.occludedAtHit) << where();
        EXPECT_FALSE(r.occludedBefore) << where();
        if (mustHit) {
            EXPECT_TRUE(hit) << where();
        }
        ok = ok && r.occludedBeyond == hit && r.occludedAfterHit == hit && !r.occludedAtHit &&
             !r.occludedBefore && (!mustHit || hit);
        failures += !ok;
    }
    // Rays that all miss would prove nothing.
    EXPECT_GT(hits, static_cast<int>(rays.size() / 50));
    testing::Test::RecordProperty("hits", hits);
    testing::Test::RecordProperty("ties", ties);
}

// A triangle soup with its BVH, brute force and tests in both orders.
struct SoupScene {
    explicit SoupScene(TriangleSoup triangles)
        : soup(std::move(triangles)),
          bounds(soup.bounds()),
          bvh(bounds),
          bruteForce(bounds),
          leafOrdered(soup.reordered(bvh.primitiveOrder())) {}

    void expectMatches(const std::vector<Ray>& rays, bool mustHit = false) const {
        expectBvhMatchesBruteForce(
            bvh, bruteForce, rays,
            [&](std::uint32_t i, const Ray& r, float tMax) { return soup.intersect(i, r, tMax); },
            [&](std::uint32_t k, const Ray& r, float tMax) {
                return leafOrdered.intersect(k, r, tMax);
            },
            mustHit);
    }

    TriangleSoup soup;
    std::vector<Bounds3> bounds;
    Bvh bvh;
    BruteForce bruteForce;
    TriangleSoup leafOrdered;
};

// Rays along the axes, with zero direction components of both signs, starting in the scene.
std::vector<Ray> axisParallelRays(const Bounds3& scene, int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> pick(0, 5);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const int axis = pick(rng) % 3;
        Vec3 d(pick(rng) % 2 ? -0.0f : 0.0f, pick(rng) % 2 ? -0.0f : 0.0f,
               pick(rng) % 2 ? -0.0f : 0.0f);
        d[axis] = pick(rng) % 2 ? -1.0f : 1.0f;
        rays.push_back({randomPointIn(scene, rng), d});
    }
    return rays;
}

// Rays starting exactly on the faces and corners of the BVH's nodes, in random directions, along
// the axes, and lying in the face they start on (where the slab test meets 0 * inf).
std::vector<Ray> nodeBoundaryRays(const Bvh& bvh, int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::size_t> pickNode(0, bvh.nodeCount() - 1);
    std::uniform_int_distribution<int> pick(0, 5);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const Bounds3 box = bvh.nodes()[pickNode(rng)].box();
        const int axis = pick(rng) % 3;
        const bool atMax = pick(rng) % 2;
        Vec3 origin = randomPointIn(box, rng);
        origin[axis] = atMax ? box.max[axis] : box.min[axis];
        if (i % 5 == 0) origin = atMax ? box.max : box.min;
        Vec3 d;
        switch (i % 3) {
            case 0:
                d = randomDirection(rng);
                break;
            case 1:
                d[pick(rng) % 3] = pick(rng) % 2 ? -1.0f : 1.0f;
                break;
            default:
                d = randomDirection(rng);
                d[axis] = 0;  // in the face's plane
                if (lengthSquared(d) == 0) d[(axis + 1) % 3] = 1;
                break;
        }
        rays.push_back({origin, d});
    }
    return rays;
}

TEST(BvhTraversal, SmallRandomTrianglesMatchBruteForce) {
    SoupScene(randomSoup(20000, 0.03f, 1))
        .expectMatches(randomRays({Vec3(0), Vec3(1)}, kRayCount, 2));
}

TEST(BvhTraversal, LargeOverlappingTrianglesMatchBruteForce) {
    SoupScene(randomSoup(2000, 0.15f, 3))
        .expectMatches(randomRays({Vec3(0), Vec3(1)}, kRayCount, 4));
}

TEST(BvhTraversal, SliversOfManySizesMatchBruteForce) {
    TriangleSoup slivers;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 a(u(rng), u(rng), u(rng));
        const float size = 0.1f * std::pow(10.0f, -2 * u(rng));
        const Vec3 along = size * randomDirection(rng);
        slivers.add(a, a + along, a + along + 0.05f * size * randomDirection(rng));
    }
    SoupScene(std::move(slivers)).expectMatches(randomRays({Vec3(0), Vec3(1)}, kRayCount, 6));
}

TEST(BvhTraversal, ClosedMeshMatchesBruteForce) {
    const SoupScene mesh(bumpySphere(6));  // 81920 triangles
    ASSERT_EQ(mesh.soup.size(), 81920u);
    mesh.expectMatches(randomRays(mesh.bvh.bounds(), kRayCount, 7));
}

TEST(BvhTraversal, RaysFromInsideTheClosedMeshAlwaysHit) {
    const SoupScene mesh(bumpySphere(6));
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> radius(0, 0.75f);
    std::vector<Ray> rays;
    for (int i = 0; i < kRayCount; ++i)
        rays.push_back({radius(rng) * randomDirection(rng), randomDirection(rng)});
    mesh.expectMatches(rays, true);
    // Along the axes, with zero components of both signs.
    mesh.expectMatches(axisParallelRays({Vec3(-0.4f), Vec3(0.4f)}, kRayCount, 9), true);
}

TEST(BvhTraversal, AxisParallelRaysMatchBruteForce) {
    const SoupScene soup(randomSoup(20000, 0.03f, 10));
    soup.expectMatches(axisParallelRays(soup.bvh.bounds(), kRayCount, 11));
    // Squares of two triangles on the planes x, y, z = 0, 1/4, ..., 1, cut into a 4 x 4 grid; rays
    // along the axes starting on multiples of 1/8 run along their planes, through their shared
    // edges and their vertices.
    TriangleSoup grid;
    for (int normalAxis = 0; normalAxis < 3; ++normalAxis) {
        const int u = (normalAxis + 1) % 3, v = (normalAxis + 2) % 3;
        for (int i = 0; i <= 4; ++i)
            for (int j = 0; j < 4; ++j)
                for (int k = 0; k < 4; ++k) {
                    Vec3 corner;
                    corner[normalAxis] = 0.25f * static_cast<float>(i);
                    corner[u] = 0.25f * static_cast<float>(j);
                    corner[v] = 0.25f * static_cast<float>(k);
                    Vec3 du, dv;
                    du[u] = dv[v] = 0.25f;
                    grid.add(corner, corner + du, corner + du + dv);
                    grid.add(corner, corner + du + dv, corner + dv);
                }
    }
    const SoupScene gridScene(std::move(grid));
    std::vector<Ray> rays = axisParallelRays(enlarged(gridScene.bvh.bounds(), 0.1f), kRayCount, 12);
    std::mt19937 rng(13);
    std::uniform_int_distribution<int> eighths(-1, 9);
    for (Ray& ray : rays)
        for (int axis = 0; axis < 3; ++axis)
            if (eighths(rng) % 2 == 0) ray.origin[axis] = 0.125f * static_cast<float>(eighths(rng));
    gridScene.expectMatches(rays);
}

TEST(BvhTraversal, RaysStartingOnNodeBoundariesMatchBruteForce) {
    const SoupScene soup(randomSoup(20000, 0.03f, 14));
    soup.expectMatches(nodeBoundaryRays(soup.bvh, kRayCount, 15));
    const SoupScene mesh(bumpySphere(5));
    mesh.expectMatches(nodeBoundaryRays(mesh.bvh, kRayCount, 16));
}

TEST(BvhTraversal, CoincidentCentroidsMatchBruteForce) {
    const SoupScene scene(sameCentroidSoup(2000, 16));
    ASSERT_EQ(scene.bvh.nodeCount(), 1u);
    scene.expectMatches(randomRays(scene.bvh.bounds(), 10000, 17));
}

TEST(BvhTraversal, LeafSizesMatchBruteForce) {
    const TriangleSoup soup = randomSoup(20000, 0.01f, 18);
    const std::vector<Bounds3> bounds = soup.bounds();
    const BruteForce bruteForce(bounds);
    for (const int maxLeafSize : {1, 8, 255}) {
        const Bvh bvh(bounds, maxLeafSize);
        const TriangleSoup ordered = soup.reordered(bvh.primitiveOrder());
        expectBvhMatchesBruteForce(
            bvh, bruteForce, randomRays({Vec3(0), Vec3(1)}, 20000, 19),
            [&](std::uint32_t i, const Ray& r, float tMax) { return soup.intersect(i, r, tMax); },
            [&](std::uint32_t k, const Ray& r, float tMax) {
                return ordered.intersect(k, r, tMax);
            });
    }
}

// Spheres and triangles in one tree, through the Shape interface the renderer uses.
TEST(BvhTraversal, SpheresAndTrianglesMatchBruteForce) {
    std::mt19937 rng(20);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<std::unique_ptr<Shape>> shapes;
    for (int i = 0; i < 10000; ++i) {
        const Vec3 c(u(rng), u(rng), u(rng));
        if (i % 2 == 0) {
            shapes.push_back(std::make_unique<Sphere>(c, 0.02f * u(rng) + 0.001f, nullptr));
        } else {
            const std::array<Vec3, 3> v = {c + 0.02f * randomDirection(rng),
                                           c + 0.02f * randomDirection(rng),
                                           c + 0.02f * randomDirection(rng)};
            shapes.push_back(std::make_unique<Triangle>(v, nullptr));
        }
    }
    std::vector<Bounds3> bounds;
    for (const auto& shape : shapes)
        bounds.push_back(shape->bounds());
    const Bvh bvh(bounds);
    std::vector<const Shape*> ordered;
    for (const std::uint32_t i : bvh.primitiveOrder())
        ordered.push_back(shapes[i].get());
    // A sphere solves for t in double: rounded to float, a t just below tMax can become tMax.
    // The strict t < tMax that the occlusion checks rely on is restored here.
    const auto test = [](const Shape& shape, const Ray& r, float tMax) -> std::optional<float> {
        Hit hit;
        if (!intersectInto(shape, r, tMax, hit) || !(hit.t < tMax)) return std::nullopt;
        return hit.t;
    };
    expectBvhMatchesBruteForce(
        bvh, BruteForce(bounds), randomRays({Vec3(0), Vec3(1)}, kRayCount, 21),
        [&](std::uint32_t i, const Ray& r, float tMax) { return test(*shapes[i], r, tMax); },
        [&](std::uint32_t k, const Ray& r, float tMax) { return test(*ordered[k], r, tMax); });
}

}  // namespace
}  // namespace lancer::test
