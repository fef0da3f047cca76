#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "math/Bounds3.h"
#include "math/Float.h"
#include "math/Ray.h"
#include "math/Vec3.h"

namespace lancer {

// The slab tests widen their far distances, and tMax, by 2 gamma(3), so that rounding never
// misses a box a ray just touches (pbrt 6.8.2).
inline constexpr float kSlabWidening = 1 + 2 * gamma(3);

// Asks the cache for the line holding p, which the traversal will read soon.
inline void prefetch(const void* p) {
#if defined(__GNUC__)
    __builtin_prefetch(p);
#else
    static_cast<void>(p);
#endif
}

// One node of the flattened tree, 32 bytes so that two share a cache line and none straddles one.
// Nodes are stored depth-first: an interior node's first child is the node right after it.
struct alignas(32) BvhNode {
    float bounds[2][3];  // bounds[0] is the min corner, bounds[1] the max corner
    // A leaf's first primitive (an index into primitiveOrder), or an interior node's second child.
    std::uint32_t offset;
    std::uint16_t primitiveCount;  // 0 for an interior node
    std::uint8_t axis;             // the axis an interior node was split along
    std::uint8_t padding;

    bool isLeaf() const { return primitiveCount > 0; }
    Bounds3 box() const {
        return Bounds3(Vec3(bounds[0][0], bounds[0][1], bounds[0][2]),
                       Vec3(bounds[1][0], bounds[1][1], bounds[1][2]));
    }
};
static_assert(sizeof(BvhNode) == 32);

// A bounding volume hierarchy over primitives it knows only by their bounds. The owner keeps the
// primitives: after the build it reorders them by primitiveOrder(), so that every leaf covers a
// contiguous range [offset, offset + primitiveCount) of them, and it supplies the primitive test
// to the traversal as a callable, which the templates below inline.
//
// The build is a binned surface area heuristic build, run in parallel with oneTBB; the tree does
// not depend on the number of threads.
class Bvh {
public:
    static constexpr int kDefaultMaxLeafSize = 4;
    // Leaves count their primitives on 16 bits.
    static constexpr int kLeafCapacity = 0xffff;
    // No leaf is deeper than this (the root being at depth 0), which bounds the traversal stack.
    static constexpr int kMaxDepth = 64;

    // An empty hierarchy: nothing is ever hit.
    Bvh() = default;
    // Builds over primitives with the given bounds, binned by the centres of their boxes.
    // maxLeafSize (1 to kLeafCapacity) caps the leaves the heuristic may choose to make; only
    // primitives whose centroids coincide can end up in larger leaves. primitivesPerTest (at
    // least 1) is how many primitives the owner tests at once (SIMD): a leaf of n then costs
    // ceil(n / primitivesPerTest) tests, which the heuristic weighs.
    explicit Bvh(std::span<const Bounds3> primitiveBounds, int maxLeafSize = kDefaultMaxLeafSize,
                 int primitivesPerTest = 1);
    // The same, binned by the given centroids (one per primitive, each inside its bounds).
    Bvh(std::span<const Bounds3> primitiveBounds, std::span<const Vec3> centroids,
        int maxLeafSize = kDefaultMaxLeafSize, int primitivesPerTest = 1);

    // The union of the primitives' bounds (empty when there are none).
    const Bounds3& bounds() const { return bounds_; }
    std::size_t nodeCount() const { return nodes_.size(); }
    std::size_t primitiveCount() const { return primitiveOrder_.size(); }
    std::span<const BvhNode> nodes() const { return nodes_; }
    // primitiveOrder()[k] is the original index of the k-th primitive in leaf order.
    std::span<const std::uint32_t> primitiveOrder() const { return primitiveOrder_; }
    // The nodes and the primitive order.
    std::size_t memoryBytes() const {
        return nodes_.size() * sizeof(BvhNode) + primitiveOrder_.size() * sizeof(std::uint32_t);
    }

    // Finds the closest hit along the ray. intersectPrimitive(k, ray, tMax) -> bool tests the
    // k-th primitive in leaf order and, on a hit closer than tMax, lowers tMax to it and returns
    // true. Returns whether anything was hit; tMax is then the closest hit's t.
    template <typename F>
    bool intersect(const Ray& ray, float& tMax, F&& intersectPrimitive) const;

    // Whether anything blocks the ray before tMax. occludedPrimitive(k, ray, tMax) -> bool tests
    // the k-th primitive in leaf order; the traversal stops at the first primitive that says yes.
    template <typename F>
    bool occluded(const Ray& ray, float tMax, F&& occludedPrimitive) const;

private:
    // What the slab tests of one ray share: the reciprocal direction and, per axis, which corner
    // of a box the ray enters by.
    struct RayBoxSetup {
        explicit RayBoxSetup(const Ray& ray);
        bool hits(const BvhNode& node, float tMax) const;

        float origin[3];
        float invDirection[3];
        int nearCorner[3];  // 1 where the direction is negative (including -0)
    };

    // Walks the nodes the ray can reach before tMax (which visitLeaf may lower), nearest child
    // first, calling visitLeaf(leaf) on each leaf it reaches; stops when visitLeaf returns true.
    template <typename VisitLeaf>
    void traverse(const Ray& ray, const float& tMax, VisitLeaf&& visitLeaf) const;

    Bounds3 bounds_;
    std::vector<BvhNode> nodes_;
    std::vector<std::uint32_t> primitiveOrder_;
};

inline Bvh::RayBoxSetup::RayBoxSetup(const Ray& ray) {
    for (int i = 0; i < 3; ++i) {
        origin[i] = ray.origin[i];
        // A zero component gives an infinite reciprocal of the zero's sign, which the slab test
        // handles; the direction itself is never zero on all axes for a meaningful ray.
        invDirection[i] = 1.0f / ray.direction[i];
        nearCorner[i] = invDirection[i] < 0 ? 1 : 0;
    }
}

// The slab test (pbrt 6.8.2), unrolled on the node's floats with the entry corner chosen per axis
// up front, so that each axis costs two subtractions, two products and no swap. The far
// distances and tMax are widened: the entry distance, rounded up, may pass a primitive's t,
// rounded down, by an ulp or two, and a box around a primitive hit just before tMax must still be
// entered. Rounding a product is monotone in it, so widening the nearest of them once gives the
// nearest of the widened ones.
inline bool Bvh::RayBoxSetup::hits(const BvhNode& node, float tMax) const {
    float t0 = 0, t1 = tMax;
    for (int i = 0; i < 3; ++i) {
        const float tNear = (node.bounds[nearCorner[i]][i] - origin[i]) * invDirection[i];
        const float tFar = (node.bounds[1 - nearCorner[i]][i] - origin[i]) * invDirection[i];
        // NaN (0 * inf, a ray in a slab's plane) leaves the interval unchanged.
        t0 = tNear > t0 ? tNear : t0;
        t1 = tFar < t1 ? tFar : t1;
    }
    return t0 <= t1 * kSlabWidening;
}

template <typename VisitLeaf>
void Bvh::traverse(const Ray& ray, const float& tMax, VisitLeaf&& visitLeaf) const {
    if (nodes_.empty()) return;
    const RayBoxSetup setup(ray);
    const BvhNode* nodes = nodes_.data();
    std::uint32_t stack[kMaxDepth];
    int stackSize = 0;
    std::uint32_t current = 0;
    for (;;) {
        const BvhNode& node = nodes[current];
        if (setup.hits(node, tMax)) {
            if (!node.isLeaf()) {
                // The far child is visited after the near one's subtree: its fetch from memory
                // overlaps that work.
                prefetch(nodes + node.offset);
                // The first child holds the primitives below the split: nearer when the ray runs
                // towards +axis.
                if (setup.nearCorner[node.axis]) {
                    stack[stackSize++] = current + 1;
                    current = node.offset;
                } else {
                    stack[stackSize++] = node.offset;
                    current = current + 1;
                }
                continue;
            }
            if (visitLeaf(node)) return;
        }
        if (stackSize == 0) return;
        current = stack[--stackSize];
    }
}

template <typename F>
bool Bvh::intersect(const Ray& ray, float& tMax, F&& intersectPrimitive) const {
    bool hit = false;
    traverse(ray, tMax, [&](const BvhNode& leaf) {
        const std::uint32_t end = leaf.offset + leaf.primitiveCount;
        for (std::uint32_t k = leaf.offset; k < end; ++k)
            if (intersectPrimitive(k, ray, tMax)) hit = true;
        return false;
    });
    return hit;
}

template <typename F>
bool Bvh::occluded(const Ray& ray, float tMax, F&& occludedPrimitive) const {
    bool blocked = false;
    traverse(ray, tMax, [&](const BvhNode& leaf) {
        const std::uint32_t end = leaf.offset + leaf.primitiveCount;
        for (std::uint32_t k = leaf.offset; k < end; ++k) {
            if (occludedPrimitive(k, ray, tMax)) {
                blocked = true;
                break;
            }
        }
        return blocked;
    });
    return blocked;
}

}  // namespace lancer
