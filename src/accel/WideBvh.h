#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "accel/Bvh.h"
#include "math/Bounds3.h"
#include "math/Float4.h"
#include "math/Ray.h"
#include "util/CpuFeatures.h"

#if LANCER_HAS_AVX2_TARGET
#include <immintrin.h>
#endif

namespace lancer {

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
// subtrees, chosen so that the wide nodes' total area (the surface area heuristic's node cost)
// is the least possible, and the ray meets all eight boxes in two 4-wide SIMD slab tests. What
// limits the traversal of deep trees (meshes) on incoherent rays is the chain of dependent node
// loads and mispredicted branches, and a ray here visits a sixth as many nodes as in the binary
// tree (9.5 instead of 59 per diffuse-bounce ray on a 1M-triangle mesh). Eight children per node
// measured faster than four, even on 4-wide SSE; see docs/BENCHMARKS.md.
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
    // A tree kept from an earlier build (the model cache), its nodes as nodes() gave them.
    // Throws std::invalid_argument when they are not a tree the traversal can walk safely: an
    // interior child not after its node or past the last, bounds that are not a finite box, a path
    // deeper than Bvh::kMaxDepth, a node that is the child of two slots, an unused slot whose box
    // is not the empty box, or a leaf that `leafFits(first, count)` refuses.
    using LeafCheck = std::function<bool(std::uint32_t first, std::uint32_t count)>;
    WideBvh(const Bounds3& bounds, std::vector<WideBvhNode> nodes, const LeafCheck& leafFits);

    std::span<const WideBvhNode> nodes() const { return nodes_; }

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
#if LANCER_HAS_AVX2_TARGET
    // The same test in one 8-wide pass where the CPU has AVX2 (two 4-wide halves above): the
    // same operations lane by lane, no fused multiply-add, so the same bits.
    struct RayBoxSetup8 {
        LANCER_AVX2_TARGET explicit RayBoxSetup8(const Ray& ray) {
            for (int i = 0; i < 3; ++i) {
                const float inverse = 1.0f / ray.direction[i];
                origin[i] = _mm256_set1_ps(ray.origin[i]);
                invDirection[i] = _mm256_set1_ps(inverse);
                nearCorner[i] = inverse < 0 ? 1 : 0;
            }
        }
        LANCER_AVX2_TARGET int hits(const WideBvhNode& node, float tMax,
                                    float tNear[WideBvhNode::kWidth]) const {
            // The operands in Float4's order for max and min (a unless b is greater, or smaller),
            // so that NaN lanes come out as in RayBoxSetup::hits.
            __m256 t0 = _mm256_setzero_ps(), t1 = _mm256_set1_ps(tMax);
            for (int i = 0; i < 3; ++i) {
                const __m256 nearPlane = _mm256_load_ps(node.bounds[nearCorner[i]][i]);
                const __m256 farPlane = _mm256_load_ps(node.bounds[1 - nearCorner[i]][i]);
                const __m256 tEnter =
                    _mm256_mul_ps(_mm256_sub_ps(nearPlane, origin[i]), invDirection[i]);
                const __m256 tExit =
                    _mm256_mul_ps(_mm256_sub_ps(farPlane, origin[i]), invDirection[i]);
                t0 = _mm256_max_ps(tEnter, t0);
                t1 = _mm256_min_ps(tExit, t1);
            }
            _mm256_storeu_ps(tNear, t0);
            const __m256 reach = _mm256_mul_ps(t1, _mm256_set1_ps(kSlabWidening));
            return _mm256_movemask_ps(_mm256_cmp_ps(t0, reach, _CMP_LE_OQ));
        }

        __m256 origin[3];
        __m256 invDirection[3];
        int nearCorner[3];
    };
#endif

    // A child met by the ray, at tNear.
    struct StackEntry {
        std::uint32_t child;
        std::uint32_t primitiveCount;  // 0 for a node
        float tNear;
    };
    // Each node on the way down adds at most kWidth - 1 entries, and the wide tree is no deeper
    // than the binary one.
    static constexpr int kStackSize = (WideBvhNode::kWidth - 1) * Bvh::kMaxDepth + 1;

    // The collapse: planSlots finds, bottom-up, the least wide-node area of each binary subtree
    // for one to kWidth slots; collapse then fills the wide nodes top-down as planned.
    struct SlotPlan;
    static std::array<float, WideBvhNode::kWidth> planSlots(std::span<const BvhNode> binary,
                                                            std::uint32_t node,
                                                            std::span<SlotPlan> plans);
    static void appendSlots(std::span<const BvhNode> binary, std::uint32_t node, int slotCount,
                            std::span<const SlotPlan> plans, std::span<std::uint32_t> slots,
                            int& used);
    void collapse(std::span<const BvhNode> binary, std::uint32_t root, std::uint32_t index,
                  std::span<const SlotPlan> plans, const LeafLayout& layOutLeaf);

    // Walks the children the ray meets before tMax (which visitLeaf may lower), nearest first if
    // kNearestFirst, calling visitLeaf(leaf, count) on each leaf; stops when visitLeaf returns
    // true. With the box test of the widest instructions the CPU has (CpuFeatures).
    template <bool kNearestFirst, typename VisitLeaf, typename PrefetchLeaf>
    void traverse(const Ray& ray, const float& tMax, VisitLeaf&& visitLeaf,
                  PrefetchLeaf&& prefetchLeaf) const;
#if LANCER_HAS_AVX2_TARGET
    // The traversal compiled for AVX2 around RayBoxSetup8 (the leaves' tests inlined into it are
    // compiled so too, to the same bits).
    template <bool kNearestFirst, typename VisitLeaf, typename PrefetchLeaf>
    LANCER_AVX2_TARGET void traverseAvx2(const Ray& ray, const float& tMax, VisitLeaf&& visitLeaf,
                                         PrefetchLeaf&& prefetchLeaf) const;
#endif
    // The traversal with the baseline box test, out of line so that traverse, which only picks
    // a kernel, builds no frame of its own and can be inlined into its callers.
    template <bool kNearestFirst, typename VisitLeaf, typename PrefetchLeaf>
    LANCER_NEVER_INLINE void traverseBaseline(const Ray& ray, const float& tMax,
                                              VisitLeaf&& visitLeaf,
                                              PrefetchLeaf&& prefetchLeaf) const;
    // The traversal with a given box test, inlined into each of the above.
    template <bool kNearestFirst, typename BoxSetup, typename VisitLeaf, typename PrefetchLeaf>
    LANCER_ALWAYS_INLINE void traverseWith(const Ray& ray, const float& tMax, VisitLeaf&& visitLeaf,
                                           PrefetchLeaf&& prefetchLeaf) const;
    // The same for a tree of one node, whose children are all leaves (a scene of a few shapes):
    // one box test, then the leaves met in order, with no stack to keep.
    template <bool kNearestFirst, typename BoxSetup, typename VisitLeaf>
    LANCER_ALWAYS_INLINE void visitRootLeaves(const BoxSetup& setup, const float& tMax,
                                              VisitLeaf&& visitLeaf) const;

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
    // Widened once, as in Bvh::RayBoxSetup::hits.
    const Float4 widening(kSlabWidening);
    int mask = 0;
    for (int half = 0; half < WideBvhNode::kWidth; half += 4) {
        Float4 t0(0.0f), t1(tMax);
        for (int i = 0; i < 3; ++i) {
            const Float4 nearPlane = Float4::load(node.bounds[nearCorner[i]][i] + half);
            const Float4 farPlane = Float4::load(node.bounds[1 - nearCorner[i]][i] + half);
            const Float4 tEnter = (nearPlane - origin[i]) * invDirection[i];
            const Float4 tExit = (farPlane - origin[i]) * invDirection[i];
            // NaN (0 * inf, a ray in a slab's plane) leaves the interval unchanged.
            t0 = max(t0, tEnter);
            t1 = min(t1, tExit);
        }
        t0.store(tNear + half);
        mask |= le(t0, t1 * widening) << half;
    }
    return mask;
}

#if LANCER_HAS_AVX2_TARGET
template <bool kNearestFirst, typename VisitLeaf, typename PrefetchLeaf>
LANCER_AVX2_TARGET void WideBvh::traverseAvx2(const Ray& ray, const float& tMax,
                                              VisitLeaf&& visitLeaf,
                                              PrefetchLeaf&& prefetchLeaf) const {
    traverseWith<kNearestFirst, RayBoxSetup8>(ray, tMax, visitLeaf, prefetchLeaf);
}
#endif

template <bool kNearestFirst, typename VisitLeaf, typename PrefetchLeaf>
void WideBvh::traverseBaseline(const Ray& ray, const float& tMax, VisitLeaf&& visitLeaf,
                               PrefetchLeaf&& prefetchLeaf) const {
    traverseWith<kNearestFirst, RayBoxSetup>(ray, tMax, visitLeaf, prefetchLeaf);
}

template <bool kNearestFirst, typename VisitLeaf, typename PrefetchLeaf>
void WideBvh::traverse(const Ray& ray, const float& tMax, VisitLeaf&& visitLeaf,
                       PrefetchLeaf&& prefetchLeaf) const {
    // A ray of NaN or infinite numbers meets nothing; in the slab test it would meet every box,
    // the unused slots' empty ones too (whose child 0 is the root: a loop). x * 0 is 0 for a
    // finite x and NaN otherwise: the six numbers in two overlapping SIMD rows, one branch.
    static_assert(sizeof(Ray) == 6 * sizeof(float));
    const float* numbers = &ray.origin.x;
    const Float4 zero(0.0f);
    if (ne(Float4::loadUnaligned(numbers) * zero + Float4::loadUnaligned(numbers + 2) * zero,
           zero) != 0)
        return;
#if LANCER_HAS_AVX2_TARGET
    if (CpuFeatures::avx2()) {
        traverseAvx2<kNearestFirst>(ray, tMax, visitLeaf, prefetchLeaf);
        return;
    }
#endif
    traverseBaseline<kNearestFirst>(ray, tMax, visitLeaf, prefetchLeaf);
}

template <bool kNearestFirst, typename BoxSetup, typename VisitLeaf, typename PrefetchLeaf>
void WideBvh::traverseWith(const Ray& ray, const float& tMax, VisitLeaf&& visitLeaf,
                           PrefetchLeaf&& prefetchLeaf) const {
    if (nodes_.empty()) return;
    const BoxSetup setup(ray);
    if (nodes_.size() == 1) {
        visitRootLeaves<kNearestFirst>(setup, tMax, visitLeaf);
        return;
    }
    const WideBvhNode* nodes = nodes_.data();
    StackEntry stack[kStackSize];
    int stackSize = 0;
    StackEntry current{0, 0, 0};  // the root
    // Takes the next entry still within reach into current; false when none is left.
    const auto pop = [&]() LANCER_INLINE_LAMBDA {
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
        const auto entry = [&](int slot) LANCER_INLINE_LAMBDA {
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

template <bool kNearestFirst, typename BoxSetup, typename VisitLeaf>
void WideBvh::visitRootLeaves(const BoxSetup& setup, const float& tMax,
                              VisitLeaf&& visitLeaf) const {
    const WideBvhNode& root = nodes_.front();
    float tNear[WideBvhNode::kWidth];
    int slots[WideBvhNode::kWidth];
    int count = 0;
    for (int mask = setup.hits(root, tMax, tNear); mask != 0; mask &= mask - 1) {
        int i = count++;
        slots[i] = std::countr_zero(static_cast<unsigned>(mask));
        if (kNearestFirst) {
            for (; i > 0 && tNear[slots[i]] < tNear[slots[i - 1]]; --i)
                std::swap(slots[i], slots[i - 1]);
        }
    }
    for (int i = 0; i < count; ++i) {
        const int slot = slots[i];
        // A closer hit found since the box test may have put the leaf out of reach.
        if (i > 0 && tNear[slot] > tMax * kSlabWidening) {
            if (kNearestFirst) return;  // and every one after it
            continue;
        }
        if (visitLeaf(root.child[slot], root.primitiveCount[slot])) return;
    }
}

template <typename F, typename P>
bool WideBvh::intersect(const Ray& ray, float& tMax, F&& intersectLeaf, P&& prefetchLeaf) const {
    bool hit = false;
    const auto visitLeaf = [&](std::uint32_t leaf, std::uint32_t count) LANCER_INLINE_LAMBDA {
        if (intersectLeaf(leaf, count, tMax)) hit = true;
        return false;
    };
    traverse<true>(ray, tMax, visitLeaf, prefetchLeaf);
    return hit;
}

template <typename F, typename P>
bool WideBvh::occluded(const Ray& ray, float tMax, F&& occludedLeaf, P&& prefetchLeaf) const {
    bool blocked = false;
    const auto visitLeaf = [&](std::uint32_t leaf, std::uint32_t count) LANCER_INLINE_LAMBDA {
        blocked = occludedLeaf(leaf, count, tMax);
        return blocked;
    };
    traverse<false>(ray, tMax, visitLeaf, prefetchLeaf);
    return blocked;
}

}  // namespace lancer
