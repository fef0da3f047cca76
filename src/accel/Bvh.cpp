#include "accel/Bvh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

namespace lancer {

namespace {

constexpr int kBinCount = 16;
// Nodes with at most this many primitives try every cut instead of binning.
constexpr std::uint32_t kSweepSize = 8;
// The cost of visiting a node, in units of one primitive test. Incoherent rays wait on memory for
// the nodes more than they compute: measured on 1M-triangle meshes, 2 gives the fastest traversal
// and half the nodes of 1. (With tests of four primitives at once, leaves of up to four are never
// split whatever this cost.)
constexpr float kNodeVisitCost = 2.0f;
// Nodes with at most this many primitives are built, with their whole subtree, by one task.
constexpr std::uint32_t kSequentialSubtreeSize = 4096;
// Nodes with more primitives than this bin them in parallel.
constexpr std::uint32_t kParallelBinningSize = 64 * 1024;
constexpr std::size_t kGrainSize = 8 * 1024;

struct BuildPrimitive {
    Bounds3 bounds;
    Vec3 centroid;
    std::uint32_t index;
};

// A node's primitives: a range of the build array, their bounds and the bounds of their centroids.
struct NodeRange {
    std::uint32_t begin, end;
    Bounds3 bounds;
    Bounds3 centroidBounds;
    int depth;

    std::uint32_t count() const { return end - begin; }
};

// Maps centroids to kBinCount equal slices of the centroid bounds, per axis.
struct BinMapping {
    explicit BinMapping(const Bounds3& centroidBounds) : origin(centroidBounds.min) {
        for (int axis = 0; axis < 3; ++axis) {
            const float extent = centroidBounds.max[axis] - centroidBounds.min[axis];
            const float s = extent > 0 ? kBinCount / extent : 0;
            // A denormal extent overflows the scale: such an axis is treated as flat.
            scale[axis] = std::isfinite(s) ? s : 0;
        }
    }
    bool canSplit(int axis) const { return scale[axis] > 0; }
    // The centroid at min maps to bin 0, the one at max to the last bin.
    int bin(const Vec3& centroid, int axis) const {
        const int b = static_cast<int>((centroid[axis] - origin[axis]) * scale[axis]);
        return std::min(b, kBinCount - 1);
    }

    Vec3 origin;
    float scale[3];
};

struct Bin {
    Bounds3 bounds;
    std::uint32_t count = 0;
};

// The primitives of a node sorted into bins along each of the three axes.
struct Binning {
    std::array<std::array<Bin, kBinCount>, 3> bins;

    void add(const BuildPrimitive& primitive, const BinMapping& mapping) {
        for (int axis = 0; axis < 3; ++axis) {
            Bin& b = bins[axis][mapping.bin(primitive.centroid, axis)];
            b.bounds = merge(b.bounds, primitive.bounds);
            ++b.count;
        }
    }
    // Min, max and integer sums: the result does not depend on how the work was split.
    void add(const Binning& other) {
        for (int axis = 0; axis < 3; ++axis) {
            for (int i = 0; i < kBinCount; ++i) {
                bins[axis][i].bounds = merge(bins[axis][i].bounds, other.bins[axis][i].bounds);
                bins[axis][i].count += other.bins[axis][i].count;
            }
        }
    }
};

// Orders primitives along an axis by centroid, then by index: a total order, so that sorting
// gives the same result whatever the algorithm.
struct CentroidOrder {
    int axis;

    bool operator()(const BuildPrimitive& a, const BuildPrimitive& b) const {
        const float ca = a.centroid[axis], cb = b.centroid[axis];
        return ca < cb || (ca == cb && a.index < b.index);
    }
    bool operator()(const BuildPrimitive* a, const BuildPrimitive* b) const {
        return (*this)(*a, *b);
    }
};

// What to do with a node.
struct SplitDecision {
    enum class Kind {
        kLeaf,
        kBinned,  // split at a bin boundary
        kSorted,  // sort by centroid along the axis and cut after leftCount primitives
        kMedian,  // the same, cutting in the middle
    };
    Kind kind = Kind::kLeaf;
    int axis = 0;
    int firstRightBin = 0;            // kBinned: bins below go to the first child
    Bounds3 leftBounds, rightBounds;  // kBinned
    std::uint32_t leftCount = 0;      // kSorted
};

struct BoundsPair {
    Bounds3 bounds, centroidBounds;

    void add(const BuildPrimitive& p) {
        bounds = merge(bounds, p.bounds);
        centroidBounds = merge(centroidBounds, p.centroid);
    }
    void add(const BoundsPair& other) {
        bounds = merge(bounds, other.bounds);
        centroidBounds = merge(centroidBounds, other.centroidBounds);
    }
};

// Part of the tree built by one task. A node split into parallel tasks keeps only itself in
// nodes and its two subtrees in children; the nodes of a sequential subtree are depth-first with
// second-child offsets relative to nodes[0].
struct Subtree {
    std::vector<BvhNode> nodes;
    std::unique_ptr<Subtree> children[2];
    std::size_t nodeCount = 0;  // of the whole subtree
};

BvhNode makeNode(const Bounds3& bounds) {
    BvhNode node{};
    for (int i = 0; i < 3; ++i) {
        node.bounds[0][i] = bounds.min[i];
        node.bounds[1][i] = bounds.max[i];
    }
    return node;
}

BvhNode makeLeaf(const NodeRange& range) {
    BvhNode node = makeNode(range.bounds);
    node.offset = range.begin;
    node.primitiveCount = static_cast<std::uint16_t>(range.count());
    return node;
}

BvhNode makeInterior(const NodeRange& range, int axis) {
    BvhNode node = makeNode(range.bounds);
    node.axis = static_cast<std::uint8_t>(axis);
    return node;
}

class Builder {
public:
    Builder(std::span<BuildPrimitive> primitives, int maxLeafSize, int primitivesPerTest)
        : primitives_(primitives),
          maxLeafSize_(static_cast<std::uint32_t>(maxLeafSize)),
          primitivesPerTest_(static_cast<std::uint32_t>(primitivesPerTest)) {}

    std::vector<BvhNode> build(const NodeRange& root) {
        const std::unique_ptr<Subtree> tree = buildSubtree(root);
        std::vector<BvhNode> nodes(tree->nodeCount);
        flatten(*tree, 0, nodes.data());
        return nodes;
    }

private:
    std::unique_ptr<Subtree> buildSubtree(const NodeRange& range) {
        auto tree = std::make_unique<Subtree>();
        if (range.count() <= kSequentialSubtreeSize) {
            buildSequential(range, tree->nodes);
            tree->nodeCount = tree->nodes.size();
            return tree;
        }
        const SplitDecision decision = decide(range);
        if (decision.kind == SplitDecision::Kind::kLeaf) {
            tree->nodes.push_back(makeLeaf(range));
            tree->nodeCount = 1;
            return tree;
        }
        const auto [left, right] = split(range, decision);
        tree->nodes.push_back(makeInterior(range, decision.axis));
        tbb::parallel_invoke([&, l = left] { tree->children[0] = buildSubtree(l); },
                             [&, r = right] { tree->children[1] = buildSubtree(r); });
        tree->nodeCount = 1 + tree->children[0]->nodeCount + tree->children[1]->nodeCount;
        return tree;
    }

    void buildSequential(const NodeRange& range, std::vector<BvhNode>& nodes) {
        const SplitDecision decision = decide(range);
        if (decision.kind == SplitDecision::Kind::kLeaf) {
            nodes.push_back(makeLeaf(range));
            return;
        }
        const auto [left, right] = split(range, decision);
        const std::size_t self = nodes.size();
        nodes.push_back(makeInterior(range, decision.axis));
        buildSequential(left, nodes);
        nodes[self].offset = static_cast<std::uint32_t>(nodes.size());
        buildSequential(right, nodes);
    }

    // Writes the subtree's nodes at out[base...], turning relative offsets into absolute ones.
    static void flatten(const Subtree& tree, std::uint32_t base, BvhNode* out) {
        if (tree.children[0]) {
            BvhNode& node = out[base] = tree.nodes[0];
            node.offset = base + 1 + static_cast<std::uint32_t>(tree.children[0]->nodeCount);
            tbb::parallel_invoke([&] { flatten(*tree.children[0], base + 1, out); },
                                 [&] { flatten(*tree.children[1], node.offset, out); });
            return;
        }
        for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
            out[base + i] = tree.nodes[i];
            if (!tree.nodes[i].isLeaf()) out[base + i].offset += base;
        }
    }

    SplitDecision decide(const NodeRange& range) const {
        const std::uint32_t count = range.count();
        if (count == 1) return {};
        const auto leafOrMedian = [&](std::uint32_t maxLeafSize) {
            SplitDecision decision;
            if (count <= maxLeafSize) return decision;
            decision.kind = SplitDecision::Kind::kMedian;
            decision.axis = range.centroidBounds.maxExtentAxis();
            return decision;
        };
        // All centroids coincide: no plane separates them, so one leaf serves best.
        if (range.centroidBounds.min == range.centroidBounds.max)
            return leafOrMedian(Bvh::kLeafCapacity);
        // Heuristic splits may be lopsided; below the depth where halving is the only way to keep
        // every leaf within kMaxDepth, split at the median.
        const int halvingDepth = std::bit_width(count - 1);
        if (range.depth + 1 + halvingDepth > Bvh::kMaxDepth) return leafOrMedian(maxLeafSize_);

        // Costs are compared multiplied by the node's area: leaf = count * area, split = visit *
        // area + leftCount * leftArea + rightCount * rightArea. This also covers nodes of zero
        // area.
        SplitDecision decision;
        const float childrenCost =
            count <= kSweepSize ? sweepSplit(range, decision) : binnedSplit(range, decision);
        // No cut found (extents or areas beyond the float range): the median still separates.
        if (childrenCost == kInfinity) return leafOrMedian(maxLeafSize_);
        const float nodeArea = range.bounds.surfaceArea();
        if (count <= maxLeafSize_ &&
            testCost(count) * nodeArea <= kNodeVisitCost * nodeArea + childrenCost)
            return {};
        return decision;
    }

    // The cheapest cut between bins along any axis. Returns its cost, infinite if there is none.
    float binnedSplit(const NodeRange& range, SplitDecision& decision) const {
        const std::uint32_t count = range.count();
        const BinMapping mapping(range.centroidBounds);
        const Binning binning = bin(range, mapping);
        float bestCost = kInfinity;
        for (int axis = 0; axis < 3; ++axis) {
            if (!mapping.canSplit(axis)) continue;
            const auto& bins = binning.bins[axis];
            // leftCost[i]: count * area of bins [0, i], left of the boundary after bin i.
            std::array<float, kBinCount - 1> leftCost;
            Bounds3 below;
            std::uint32_t belowCount = 0;
            for (int i = 0; i < kBinCount - 1; ++i) {
                below = merge(below, bins[i].bounds);
                belowCount += bins[i].count;
                leftCost[i] = testCost(belowCount) * below.surfaceArea();
            }
            Bounds3 above;
            std::uint32_t aboveCount = 0;
            for (int i = kBinCount - 1; i > 0; --i) {
                above = merge(above, bins[i].bounds);
                aboveCount += bins[i].count;
                if (aboveCount == 0 || aboveCount == count) continue;
                const float cost = leftCost[i - 1] + testCost(aboveCount) * above.surfaceArea();
                if (cost < bestCost) {
                    bestCost = cost;
                    decision.axis = axis;
                    decision.firstRightBin = i;
                }
            }
        }
        if (bestCost == kInfinity) return bestCost;
        decision.kind = SplitDecision::Kind::kBinned;
        for (int i = 0; i < kBinCount; ++i) {
            Bounds3& side = i < decision.firstRightBin ? decision.leftBounds : decision.rightBounds;
            side = merge(side, binning.bins[decision.axis][i].bounds);
        }
        return bestCost;
    }

    // For a few primitives, sorting them along each axis and trying every cut is cheaper than
    // binning, and exact. Returns the cost of the cheapest cut.
    float sweepSplit(const NodeRange& range, SplitDecision& decision) const {
        const std::uint32_t count = range.count();
        std::array<const BuildPrimitive*, kSweepSize> sorted;
        std::array<float, kSweepSize> rightCost;  // rightCost[i]: of the primitives from i on
        float bestCost = kInfinity;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(range.centroidBounds.max[axis] > range.centroidBounds.min[axis])) continue;
            // Insertion sort: the quickest for so few.
            const CentroidOrder order{axis};
            for (std::uint32_t i = 0; i < count; ++i) {
                const BuildPrimitive* p = &primitives_[range.begin + i];
                std::uint32_t j = i;
                for (; j > 0 && order(p, sorted[j - 1]); --j)
                    sorted[j] = sorted[j - 1];
                sorted[j] = p;
            }
            Bounds3 above;
            for (std::uint32_t i = count - 1; i > 0; --i) {
                above = merge(above, sorted[i]->bounds);
                rightCost[i] = testCost(count - i) * above.surfaceArea();
            }
            Bounds3 below;
            for (std::uint32_t i = 1; i < count; ++i) {
                below = merge(below, sorted[i - 1]->bounds);
                const float cost = testCost(i) * below.surfaceArea() + rightCost[i];
                if (cost < bestCost) {
                    bestCost = cost;
                    decision.axis = axis;
                    decision.leftCount = i;
                }
            }
        }
        decision.kind = SplitDecision::Kind::kSorted;
        return bestCost;
    }

    Binning bin(const NodeRange& range, const BinMapping& mapping) const {
        if (range.count() <= kParallelBinningSize) {
            Binning binning;
            for (std::uint32_t i = range.begin; i < range.end; ++i)
                binning.add(primitives_[i], mapping);
            return binning;
        }
        return tbb::parallel_reduce(
            tbb::blocked_range<std::uint32_t>(range.begin, range.end, kGrainSize), Binning{},
            [&](const tbb::blocked_range<std::uint32_t>& r, Binning binning) {
                for (std::uint32_t i = r.begin(); i < r.end(); ++i)
                    binning.add(primitives_[i], mapping);
                return binning;
            },
            [](Binning a, const Binning& b) {
                a.add(b);
                return a;
            });
    }

    std::pair<NodeRange, NodeRange> split(const NodeRange& range, const SplitDecision& decision) {
        NodeRange left{range.begin, 0, {}, {}, range.depth + 1};
        NodeRange right{0, range.end, {}, {}, range.depth + 1};
        if (decision.kind == SplitDecision::Kind::kBinned) {
            left.end = right.begin =
                partitionByBin(range, decision, left.centroidBounds, right.centroidBounds);
            left.bounds = decision.leftBounds;
            right.bounds = decision.rightBounds;
            return {left, right};
        }
        const auto first = primitives_.begin() + range.begin,
                   last = primitives_.begin() + range.end;
        if (decision.kind == SplitDecision::Kind::kSorted) {
            left.end = right.begin = range.begin + decision.leftCount;
            std::sort(first, last, CentroidOrder{decision.axis});
        } else {
            left.end = right.begin = range.begin + range.count() / 2;
            std::nth_element(first, primitives_.begin() + left.end, last,
                             CentroidOrder{decision.axis});
        }
        for (NodeRange* side : {&left, &right}) {
            BoundsPair b;
            for (std::uint32_t i = side->begin; i < side->end; ++i)
                b.add(primitives_[i]);
            side->bounds = b.bounds;
            side->centroidBounds = b.centroidBounds;
        }
        return {left, right};
    }

    // Moves the primitives of the bins below the split to the front of the range, gathering the
    // centroid bounds of both sides on the way. Returns where the second side starts.
    std::uint32_t partitionByBin(const NodeRange& range, const SplitDecision& decision,
                                 Bounds3& leftCentroids, Bounds3& rightCentroids) {
        const BinMapping mapping(range.centroidBounds);
        const auto goesLeft = [&](const BuildPrimitive& p) {
            return mapping.bin(p.centroid, decision.axis) < decision.firstRightBin;
        };
        std::uint32_t i = range.begin, j = range.end;
        for (;;) {
            while (i < j && goesLeft(primitives_[i]))
                leftCentroids = merge(leftCentroids, primitives_[i++].centroid);
            while (i < j && !goesLeft(primitives_[j - 1]))
                rightCentroids = merge(rightCentroids, primitives_[--j].centroid);
            if (i == j) return i;
            std::swap(primitives_[i], primitives_[j - 1]);
        }
    }

    // The cost of testing n primitives in a leaf.
    float testCost(std::uint32_t n) const {
        return static_cast<float>((n + primitivesPerTest_ - 1) / primitivesPerTest_);
    }

    std::span<BuildPrimitive> primitives_;
    std::uint32_t maxLeafSize_;
    std::uint32_t primitivesPerTest_;
};

}  // namespace

Bvh::Bvh(std::span<const Bounds3> primitiveBounds, int maxLeafSize, int primitivesPerTest)
    : Bvh(primitiveBounds, {}, maxLeafSize, primitivesPerTest) {}

Bvh::Bvh(std::span<const Bounds3> primitiveBounds, std::span<const Vec3> centroids, int maxLeafSize,
         int primitivesPerTest) {
    if (maxLeafSize < 1 || maxLeafSize > kLeafCapacity)
        throw std::invalid_argument("BVH maximum leaf size must be between 1 and 65535");
    if (primitivesPerTest < 1)
        throw std::invalid_argument("BVH primitives per test must be at least 1");
    if (!centroids.empty() && centroids.size() != primitiveBounds.size())
        throw std::invalid_argument("BVH needs one centroid per primitive");
    // A tree of n primitives has at most 2n - 1 nodes, all addressed with 32 bits.
    if (primitiveBounds.size() > std::size_t{1} << 31)
        throw std::length_error("too many primitives for one BVH");
    if (primitiveBounds.empty()) return;

    const auto count = static_cast<std::uint32_t>(primitiveBounds.size());
    std::vector<BuildPrimitive> primitives(count);
    const tbb::blocked_range<std::uint32_t> all(0, count, kGrainSize);
    const BoundsPair rootBounds = tbb::parallel_reduce(
        all, BoundsPair{},
        [&](const tbb::blocked_range<std::uint32_t>& r, BoundsPair b) {
            for (std::uint32_t i = r.begin(); i < r.end(); ++i) {
                const Bounds3& box = primitiveBounds[i];
                // Halved before the sum, which could overflow.
                const Vec3 centre = 0.5f * box.min + 0.5f * box.max;
                primitives[i] = {box, centroids.empty() ? centre : centroids[i], i};
                b.add(primitives[i]);
            }
            return b;
        },
        [](BoundsPair a, const BoundsPair& b) {
            a.add(b);
            return a;
        });

    bounds_ = rootBounds.bounds;
    Builder builder(primitives, maxLeafSize, primitivesPerTest);
    nodes_ = builder.build({0, count, rootBounds.bounds, rootBounds.centroidBounds, 0});
    primitiveOrder_.resize(count);
    tbb::parallel_for(all, [&](const tbb::blocked_range<std::uint32_t>& r) {
        for (std::uint32_t i = r.begin(); i < r.end(); ++i)
            primitiveOrder_[i] = primitives[i].index;
    });
}

}  // namespace lancer
