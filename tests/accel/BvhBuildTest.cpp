// The shape of the tree: node layout, primitive order, leaves, depth, degenerate inputs, and the
// independence of the build from the number of threads.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "BvhTestSupport.h"
#include "accel/Bvh.h"

namespace lancer::test {
namespace {

TEST(BvhBuild, NodeIs32BytesAndCacheAligned) {
    EXPECT_EQ(sizeof(BvhNode), 32u);
    EXPECT_EQ(alignof(BvhNode), 32u);
    const TriangleSoup soup = randomSoup(1000, 0.02f, 1);
    const Bvh bvh(soup.bounds());
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(bvh.nodes().data()) % 32, 0u);
    EXPECT_EQ(bvh.memoryBytes(), bvh.nodeCount() * 32 + soup.size() * 4);
}

TEST(BvhBuild, EmptyBvhHitsNothing) {
    for (const Bvh& bvh : {Bvh(), Bvh(std::span<const Bounds3>())}) {
        EXPECT_EQ(bvh.nodeCount(), 0u);
        EXPECT_EQ(bvh.primitiveCount(), 0u);
        EXPECT_EQ(bvh.memoryBytes(), 0u);
        EXPECT_TRUE(bvh.bounds().isEmpty());
        const Ray ray{{0, 0, 0}, {0, 0, 1}};
        float tMax = kInfinity;
        int calls = 0;
        const auto count = [&](std::uint32_t, const Ray&, float) {
            ++calls;
            return true;
        };
        EXPECT_FALSE(bvh.intersect(ray, tMax, count));
        EXPECT_FALSE(bvh.occluded(ray, kInfinity, count));
        EXPECT_EQ(calls, 0);
        EXPECT_EQ(tMax, kInfinity);
    }
}

TEST(BvhBuild, SinglePrimitiveIsOneLeaf) {
    TriangleSoup soup;
    soup.add({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const std::vector<Bounds3> bounds = soup.bounds();
    const Bvh bvh(bounds);
    ASSERT_EQ(bvh.nodeCount(), 1u);
    EXPECT_TRUE(bvh.nodes()[0].isLeaf());
    EXPECT_EQ(bvh.nodes()[0].offset, 0u);
    EXPECT_EQ(bvh.nodes()[0].primitiveCount, 1);
    ASSERT_EQ(bvh.primitiveOrder().size(), 1u);
    EXPECT_EQ(bvh.primitiveOrder()[0], 0u);
    checkTree(bvh, bounds);

    const auto test = [&](std::uint32_t k, const Ray& r, float tMax) {
        return soup.intersect(k, r, tMax);
    };
    const ClosestHit hit = bvhClosest(bvh, {{0.25f, 0.25f, 2}, {0, 0, -1}}, test);
    EXPECT_EQ(hit.primitive, 0);
    EXPECT_EQ(hit.t, 2.0f);
    EXPECT_EQ(bvhClosest(bvh, {{0.75f, 0.75f, 2}, {0, 0, -1}}, test).primitive, -1);
    EXPECT_TRUE(bvhOccluded(bvh, {{0.25f, 0.25f, 2}, {0, 0, -1}}, 2.5f, test));
    EXPECT_FALSE(bvhOccluded(bvh, {{0.25f, 0.25f, 2}, {0, 0, -1}}, 1.5f, test));
}

TEST(BvhBuild, EveryPrimitiveAppearsOnceInOrder) {
    for (const std::uint32_t n : {2u, 3u, 5u, 17u, 1000u, 100000u}) {
        const TriangleSoup soup = randomSoup(n, 0.01f, n);
        const Bvh bvh(soup.bounds());
        std::vector<std::uint32_t> order(bvh.primitiveOrder().begin(), bvh.primitiveOrder().end());
        ASSERT_EQ(order.size(), n);
        std::sort(order.begin(), order.end());
        for (std::uint32_t i = 0; i < n; ++i)
            ASSERT_EQ(order[i], i) << "n = " << n;
    }
}

TEST(BvhBuild, TreeInvariantsHold) {
    const TriangleSoup soup = randomSoup(50000, 0.02f, 7);
    const std::vector<Bounds3> soupBounds = soup.bounds();
    const TreeStats soupStats = checkTree(Bvh(soupBounds), soupBounds);
    EXPECT_LE(soupStats.maxLeafSize, static_cast<std::uint32_t>(Bvh::kDefaultMaxLeafSize));
    EXPECT_LE(soupStats.maxDepth, Bvh::kMaxDepth);

    const TriangleSoup sphere = bumpySphere(5);
    const std::vector<Bounds3> sphereBounds = sphere.bounds();
    const Bvh sphereBvh(sphereBounds);
    const TreeStats sphereStats = checkTree(sphereBvh, sphereBounds);
    EXPECT_LE(sphereStats.maxLeafSize, static_cast<std::uint32_t>(Bvh::kDefaultMaxLeafSize));
    EXPECT_EQ(sphereBvh.nodeCount(), 2 * sphereStats.leafCount - 1);
}

TEST(BvhBuild, MaxLeafSizeIsRespected) {
    const TriangleSoup soup = randomSoup(20000, 0.02f, 3);
    const std::vector<Bounds3> bounds = soup.bounds();
    for (const int maxLeafSize : {1, 2, 8, 16}) {
        const TreeStats stats = checkTree(Bvh(bounds, maxLeafSize), bounds);
        EXPECT_LE(stats.maxLeafSize, static_cast<std::uint32_t>(maxLeafSize));
        if (maxLeafSize == 1) {
            EXPECT_EQ(stats.leafCount, soup.size());
        }
    }
    EXPECT_THROW(Bvh(bounds, 0), std::invalid_argument);
    EXPECT_THROW(Bvh(bounds, Bvh::kLeafCapacity + 1), std::invalid_argument);
}

TEST(BvhBuild, GivenCentroidsAreUsed) {
    const TriangleSoup soup = randomSoup(5000, 0.02f, 11);
    const std::vector<Bounds3> bounds = soup.bounds();
    std::vector<Vec3> centroids;
    for (std::uint32_t i = 0; i < soup.size(); ++i)
        centroids.push_back(
            (soup.vertices[3 * i] + soup.vertices[3 * i + 1] + soup.vertices[3 * i + 2]) / 3.0f);
    const Bvh bvh(bounds, centroids);
    checkTree(bvh, bounds);
    // Centroids all in one point leave nothing to split.
    const std::vector<Vec3> onePoint(bounds.size(), Vec3(0.5f));
    EXPECT_EQ(Bvh(bounds, onePoint).nodeCount(), 1u);
    EXPECT_THROW(Bvh(bounds, std::span<const Vec3>(centroids).first(10)), std::invalid_argument);
}

TEST(BvhBuild, CoincidentCentroidsMakeOneLeaf) {
    const TriangleSoup soup = sameCentroidSoup(1000, 5);
    const std::vector<Bounds3> bounds = soup.bounds();
    const Bvh bvh(bounds);
    ASSERT_EQ(bvh.nodeCount(), 1u);
    EXPECT_EQ(bvh.nodes()[0].primitiveCount, 1000);
    checkTree(bvh, bounds);
}

TEST(BvhBuild, CoincidentCentroidsBeyondLeafCapacityAreHalved) {
    const TriangleSoup soup = sameCentroidSoup(150000, 6);
    const std::vector<Bounds3> bounds = soup.bounds();
    const Bvh bvh(bounds);
    const TreeStats stats = checkTree(bvh, bounds);
    EXPECT_GT(stats.leafCount, 1u);
    EXPECT_LE(stats.maxLeafSize, static_cast<std::uint32_t>(Bvh::kLeafCapacity));
}

// Triangles at x = 2^k over the whole range of normal floats: every heuristic split peels off the
// last few, which without a depth limit would make a tree over 100 levels deep.
TEST(BvhBuild, DepthStaysWithinTheTraversalStack) {
    TriangleSoup soup;
    for (int k = -126; k <= 127; ++k) {
        const float x = std::ldexp(1.0f, k);
        soup.add({x, 0, 0}, {x, 1, 0}, {x, 0, 1});
    }
    const std::vector<Bounds3> bounds = soup.bounds();
    const Bvh bvh(bounds, 1);
    const TreeStats stats = checkTree(bvh, bounds);
    EXPECT_EQ(stats.maxDepth, Bvh::kMaxDepth);
    EXPECT_EQ(stats.leafCount, soup.size());

    // Rays along +x and -x from between two triangles hit the next one. (Much farther than 2^20
    // times their size, the triangle test's bound on the error of t rejects such unit triangles.)
    const TriangleSoup ordered = soup.reordered(bvh.primitiveOrder());
    const BruteForce bruteForce(bounds);
    for (int k = -125; k <= 20; ++k) {
        for (const float direction : {1.0f, -1.0f}) {
            const Ray ray{{0.75f * std::ldexp(1.0f, k), 0.25f, 0.25f}, {direction, 0, 0}};
            const ClosestHit expected =
                bruteForce.closest(ray, [&](std::uint32_t i, const Ray& r, float tMax) {
                    return soup.intersect(i, r, tMax);
                });
            const ClosestHit actual =
                bvhClosest(bvh, ray, [&](std::uint32_t i, const Ray& r, float tMax) {
                    return ordered.intersect(i, r, tMax);
                });
            EXPECT_EQ(actual.primitive, expected.primitive) << "k = " << k;
            EXPECT_EQ(actual.t, expected.t) << "k = " << k;
            EXPECT_EQ(expected.primitive, direction > 0 ? k + 126 : k + 125) << "k = " << k;
        }
    }
}

TEST(BvhBuild, TreeDoesNotDependOnThreadCount) {
    const TriangleSoup soup = randomSoup(300000, 0.005f, 21);
    const std::vector<Bounds3> bounds = soup.bounds();
    const auto buildWith = [&](std::size_t threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return Bvh(bounds);
    };
    const Bvh one = buildWith(1), two = buildWith(2), again = buildWith(2);
    for (const Bvh* other : {&two, &again}) {
        ASSERT_EQ(one.nodeCount(), other->nodeCount());
        EXPECT_EQ(std::memcmp(one.nodes().data(), other->nodes().data(),
                              one.nodeCount() * sizeof(BvhNode)),
                  0);
        EXPECT_TRUE(std::equal(one.primitiveOrder().begin(), one.primitiveOrder().end(),
                               other->primitiveOrder().begin()));
    }
}

}  // namespace
}  // namespace lancer::test
