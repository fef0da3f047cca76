#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "math/Bounds3.h"
#include "math/Float.h"
#include "math/Float4.h"
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
// up front, so that each axis costs two subtractions, two products and no swap. tMax is widened
// like the far distances: the entry distance, rounded up, may pass a primitive's t, rounded
// down, by an ulp or two, and a box around a primitive hit just before tMax must still be entered.
inline bool Bvh::RayBoxSetup::hits(const BvhNode& node, float tMax) const {
    float t0 = 0, t1 = tMax * kSlabWidening;
    for (int i = 0; i < 3; ++i) {
        const float tNear = (node.bounds[nearCorner[i]][i] - origin[i]) * invDirection[i];
        const float tFar =
            (node.bounds[1 - nearCorner[i]][i] - origin[i]) * invDirection[i] * kSlabWidening;
        // NaN (0 * inf, a ray in a slab's plane) leaves the interval unchanged.
        t0 = tNear > t0 ? tNear : t0;
        t1 = tFar < t1 ? tFar : t1;
    }
    return t0 <= t1;
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

// One node of a WideBvh: the boxes of up to eight children side by side, one axis of all eight
// in one 32-byte row, so that two 4-wide SIMD slab tests cover them all. Four cache lines.
struct alignas(64) WideBvhNode {
    static constexpr int kWidth = 8;

    // bounds[corner][axis][slot], corner 0 being the min corner. An unused slot holds an empty box
    // (min +inf, max -inf), which no ray enters.
    float bounds[2][3][kWidth];
    // An interior child's node index, or what the owner made of a leaf child (see WideBvh).
    std::uint32_t child[kWidth];
    std::uint16_t primitiveCount[kWidth];  // 0 for an interior child or an unused slot
    std::uint8_t padding[16];
};
static_assert(sizeof(WideBvhNode) == 256);

// An 8-wide BVH collapsed from a binary one: each node takes up to eight of the binary tree's
// nodes, opening the largest first, and the ray meets all eight boxes in two 4-wide SIMD slab
// tests. What limits the traversal of deep trees (meshes) on incoherent rays is the chain of
// dependent node loads and mispredicted branches, and a ray here visits a sixth as many nodes as
// in the binary tree (9.5 instead of 59 per diffuse-bounce ray on a 1M-triangle mesh). Eight
// children per node measured faster than four, even on 4-wide SSE; see docs/BENCHMARKS.md.
//
// The owner lays out each leaf's primitives as it likes while the tree is collapsed (to pad
// them, say, to a SIMD width), and the traversal hands its leaves back as the owner made them.
class WideBvh {
public:
    // Called once per leaf of the binary tree with the leaf's primitives [first, first + count)
    // in its leaf order; returns what the traversal then hands back for that leaf.
    using LeafLayout = std::function<std::uint32_t(std::uint32_t first, std::uint32_t count)>;

    // An empty hierarchy: nothing is ever hit.
    WideBvh() = default;
    WideBvh(const Bvh& bvh, const LeafLayout& layOutLeaf);

    const Bounds3& bounds() const { return bounds_; }
    std::size_t memoryBytes() const { return nodes_.size() * sizeof(WideBvhNode); }

    // As Bvh::intersect, children visited nearest first, but the callable tests a whole leaf:
    // intersectLeaf(leaf, count, tMax) -> bool tests the count primitives of the leaf that the
    // LeafLayout made `leaf` and, on a hit closer than tMax, lowers tMax to it and returns true.
    // prefetchLeaf(leaf) is called on each leaf the ray meets as soon as it is known, so that
    // its primitives can be on their way from memory while other children are visited.
    template <typename F, typename P>
    bool intersect(const Ray& ray, float& tMax, F&& intersectLeaf, P&& prefetchLeaf) const;
    // As Bvh::occluded: occludedLeaf(leaf, count, tMax) -> bool says whether a primitive of the
    // leaf blocks the ray before tMax; the traversal stops at the first leaf that does.
    template <typename F, typename P>
    bool occluded(const Ray& ray, float tMax, F&& occludedLeaf, P&& prefetchLeaf) const;

private:
    // The slab test of Bvh::RayBoxSetup, on a node's eight boxes at once.
    struct RayBoxSetup {
        explicit RayBoxSetup(const Ray& ray);
        // Bit i set when the ray enters slot i's box before tMax; tNear[i] is where.
        int hits(const WideBvhNode& node, float tMax, float tNear[WideBvhNode::kWidth]) const;

        Float4 origin[3];
        Float4 invDirection[3];
        int nearCorner[3];  // 1 where the direction is negative (including -0)
    };

    // A child met by the ray, at tNear.
    struct StackEntry {
        std::uint32_t child;
        std::uint32_t primitiveCount;  // 0 for a node
        float tNear;
    };
    // Each node on the way down adds at most kWidth - 1 entries, and the wide tree is no deeper
    // than the binary one.
    static constexpr int kStackSize = (WideBvhNode::kWidth - 1) * Bvh::kMaxDepth + 1;

    void collapse(std::span<const BvhNode> binary, std::uint32_t root, std::uint32_t index,
                  const LeafLayout& layOutLeaf);

    // Walks the children the ray meets before tMax (which visitLeaf may lower), nearest first if
    // kNearestFirst, calling visitLeaf(leaf, count) on each leaf; stops when visitLeaf returns
    // true.
    template <bool kNearestFirst, typename VisitLeaf, typename PrefetchLeaf>
    void traverse(const Ray& ray, const float& tMax, VisitLeaf&& visitLeaf,
                  PrefetchLeaf&& prefetchLeaf) const;

    Bounds3 bounds_;
    std::vector<WideBvhNode> nodes_;
};

inline WideBvh::RayBoxSetup::RayBoxSetup(const Ray& ray) {
    for (int i = 0; i < 3; ++i) {
        const float inverse = 1.0f / ray.direction[i];
        origin[i] = Float4(ray.origin[i]);
        invDirection[i] = Float4(inverse);
        nearCorner[i] = inverse < 0 ? 1 : 0;
    }
}

inline int WideBvh::RayBoxSetup::hits(const WideBvhNode& node, float tMax,
                                      float tNear[WideBvhNode::kWidth]) const {
    const Float4 widening(kSlabWidening);
    int mask = 0;
    for (int half = 0; half < WideBvhNode::kWidth; half += 4) {
        Float4 t0(0.0f), t1(tMax * kSlabWidening);
        for (int i = 0; i < 3; ++i) {
            const Float4 nearPlane = Float4::load(node.bounds[nearCorner[i]][i] + half);
            const Float4 farPlane = Float4::load(node.bounds[1 - nearCorner[i]][i] + half);
            const Float4 tEnter = (nearPlane - origin[i]) * invDirection[i];
            const Float4 tExit = (farPlane - origin[i]) * invDirection[i] * widening;
            // NaN (0 * inf, a ray in a slab's plane) leaves the interval unchanged.
            t0 = max(t0, tEnter);
            t1 = min(t1, tExit);
        }
        t0.store(tNear + half);
        mask |= le(t0, t1) << half;
    }
    return mask;
}

template <bool kNearestFirst, typename VisitLeaf, typename PrefetchLeaf>
void WideBvh::traverse(const Ray& ray, const float& tMax, VisitLeaf&& visitLeaf,
                       PrefetchLeaf&& prefetchLeaf) const {
    if (nodes_.empty()) return;
    const RayBoxSetup setup(ray);
    const WideBvhNode* nodes = nodes_.data();
    StackEntry stack[kStackSize];
    int stackSize = 0;
    StackEntry current{0, 0, 0};  // the root
    // Takes the next entry still within reach into current; false when none is left.
    const auto pop = [&] {
        while (stackSize > 0) {
            current = stack[--stackSize];
            // A closer hit found since the entry was pushed may have put it out of reach.
            if (current.tNear <= tMax * kSlabWidening) return true;
        }
        return false;
    };
    for (;;) {
        if (current.primitiveCount != 0) {
            if (visitLeaf(current.child, current.primitiveCount) || !pop()) return;
            continue;
        }
        const WideBvhNode& node = nodes[current.child];
        float tNear[WideBvhNode::kWidth];
        int mask = setup.hits(node, tMax, tNear);
        if (mask == 0) {
            if (!pop()) return;
            continue;
        }
        const auto entry = [&](int slot) {
            if (node.primitiveCount[slot] == 0) {
                const auto* child = reinterpret_cast<const char*>(nodes + node.child[slot]);
                for (std::size_t line = 0; line < sizeof(WideBvhNode); line += 64)
                    prefetch(child + line);
            } else {
                prefetchLeaf(node.child[slot]);
            }
            return StackEntry{node.child[slot], node.primitiveCount[slot], tNear[slot]};
        };
        // Most nodes meet one or two children, which need no sort.
        const int first = std::countr_zero(static_cast<unsigned>(mask));
        mask &= mask - 1;
        current = entry(first);
        if (mask == 0) continue;
        const int second = std::countr_zero(static_cast<unsigned>(mask));
        mask &= mask - 1;
        StackEntry other = entry(second);
        if (kNearestFirst && other.tNear < current.tNear) std::swap(current, other);
        stack[stackSize++] = other;
        if (mask == 0) continue;
        // Three or more: all on the stack, farthest first, the nearest taken back off.
        const int base = stackSize - 1;
        stack[stackSize++] = current;
        while (mask != 0) {
            const int slot = std::countr_zero(static_cast<unsigned>(mask));
            mask &= mask - 1;
            stack[stackSize++] = entry(slot);
        }
        if (kNearestFirst) {
            for (int i = base + 1; i < stackSize; ++i)
                for (int j = i; j > base && stack[j - 1].tNear < stack[j].tNear; --j)
                    std::swap(stack[j - 1], stack[j]);
        }
        current = stack[--stackSize];
    }
}

template <typename F, typename P>
bool WideBvh::intersect(const Ray& ray, float& tMax, F&& intersectLeaf, P&& prefetchLeaf) const {
    bool hit = false;
    const auto visitLeaf = [&](std::uint32_t leaf, std::uint32_t count) {
        if (intersectLeaf(leaf, count, tMax)) hit = true;
        return false;
    };
    traverse<true>(ray, tMax, visitLeaf, prefetchLeaf);
    return hit;
}

template <typename F, typename P>
bool WideBvh::occluded(const Ray& ray, float tMax, F&& occludedLeaf, P&& prefetchLeaf) const {
    bool blocked = false;
    const auto visitLeaf = [&](std::uint32_t leaf, std::uint32_t count) {
        blocked = occludedLeaf(leaf, count, tMax);
        return blocked;
    };
    traverse<false>(ray, tMax, visitLeaf, prefetchLeaf);
    return blocked;
}

}  // namespace lancer
