#include "accel/WideBvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace lancer {

// How the collapse holds one binary subtree in at most j slots of wide nodes (j = 1 to kWidth).
struct WideBvh::SlotPlan {
    // leftSlots[j - 1]: how many of j slots go to the left child's subtree (the rest to the
    // right's), or 0 to hold the subtree in one slot: a leaf, or a wide node of its own.
    // An interior subtree given all kWidth slots always opens (that saves its own node), so
    // leftSlots[kWidth - 1] is also how a wide node made of it shares its slots.
    std::array<std::uint8_t, WideBvhNode::kWidth> leftSlots;
};

namespace {

constexpr int kWidth = WideBvhNode::kWidth;
using SlotAreas = std::array<float, kWidth>;

}  // namespace

WideBvh::WideBvh(const Bvh& bvh, const LeafLayout& layOutLeaf) : bounds_(bvh.bounds()) {
    const std::span<const BvhNode> binary = bvh.nodes();
    if (binary.empty()) return;
    std::vector<SlotPlan> plans(binary.size());
    planSlots(binary, 0, plans);
    nodes_.emplace_back();
    collapse(binary, 0, 0, plans, layOutLeaf);
    nodes_.shrink_to_fit();
}

WideBvh::WideBvh(const Bounds3& bounds, std::vector<WideBvhNode> nodes, const LeafCheck& leafFits)
    : bounds_(bounds), nodes_(std::move(nodes)) {
    // The scene's tree is built over these bounds: they must be a box.
    for (int axis = 0; axis < 3; ++axis)
        if (!(std::isfinite(bounds.min[axis]) && std::isfinite(bounds.max[axis]) &&
              bounds.min[axis] <= bounds.max[axis]))
            throw std::invalid_argument("the tree's bounds are not a box");
    // Children come after their node, so one pass in order knows each node's depth first; each
    // node but the root is the child of one slot (a tree, which a ray walks at most once).
    std::vector<std::uint8_t> depth(nodes_.size(), 0);
    std::vector<bool> isChild(nodes_.size(), false);
    for (std::size_t index = 0; index < nodes_.size(); ++index) {
        const WideBvhNode& node = nodes_[index];
        for (int slot = 0; slot < WideBvhNode::kWidth; ++slot) {
            const std::uint32_t child = node.child[slot];
            if (node.primitiveCount[slot] != 0) {
                if (!leafFits(child, node.primitiveCount[slot]))
                    throw std::invalid_argument("a leaf of the tree is past the primitives");
            } else if (child == 0) {  // the root is no one's child: an unused slot
                // The empty box the build leaves, which no finite ray meets (a box merely
                // inverted may be met through rounding, and its child 0 is the root).
                for (int axis = 0; axis < 3; ++axis)
                    if (node.bounds[0][axis][slot] != kInfinity ||
                        node.bounds[1][axis][slot] != -kInfinity)
                        throw std::invalid_argument("an unused slot of the tree has a box");
            } else {
                if (child <= index || child >= nodes_.size())
                    throw std::invalid_argument("a node of the tree is not after its parent");
                if (isChild[child])
                    throw std::invalid_argument("a node of the tree has two parents");
                isChild[child] = true;
                if (depth[index] + 1 > Bvh::kMaxDepth)
                    throw std::invalid_argument("the tree is too deep");
                depth[child] = static_cast<std::uint8_t>(depth[index] + 1);
            }
        }
    }
}

// The collapse minimises the surface area heuristic's cost of the wide nodes: the sum of their
// areas, each node's being in proportion to the chance that a ray visits it (the leaves are the
// binary tree's, whatever the plan, and cost the same). Opening the widest binary node first,
// greedily, left most nodes with two or three children (a subtree too small to share a full node
// gets a node of its own); the optimal plan is found by dynamic programming over slot counts, as
// Ylitie, Karras and Laine collapse a binary tree (2017, "Efficient incoherent ray traversal on
// GPUs through compressed wide BVHs"). Returns the least area for each slot count, having planned
// the subtree under `node` (children first; the recursion is at most Bvh::kMaxDepth deep).
SlotAreas WideBvh::planSlots(std::span<const BvhNode> binary, std::uint32_t node,
                             std::span<SlotPlan> plans) {
    SlotPlan& plan = plans[node];
    plan = {};
    if (binary[node].isLeaf()) return SlotAreas{};
    const SlotAreas left = planSlots(binary, node + 1, plans);
    const SlotAreas right = planSlots(binary, binary[node].offset, plans);
    // shared[j - 1]: the least area with j slots shared between the two children's subtrees.
    SlotAreas shared;
    std::array<std::uint8_t, kWidth> sharedLeft{};
    shared[0] = kInfinity;
    for (int j = 2; j <= kWidth; ++j) {
        // Areas beyond the float range (boxes of 1e20 and more) are all infinite: then any
        // share will do, but it must be a share.
        shared[j - 1] = kInfinity;
        sharedLeft[j - 1] = 1;
        for (int k = 1; k < j; ++k) {
            if (const float area = left[k - 1] + right[j - k - 1]; area < shared[j - 1]) {
                shared[j - 1] = area;
                sharedLeft[j - 1] = static_cast<std::uint8_t>(k);
            }
        }
    }
    // In one slot the subtree is a wide node of its own, its kWidth slots shared between the
    // children; with more slots it may open into its children's, which saves that node.
    const float asNode = binary[node].box().surfaceArea() + shared[kWidth - 1];
    SlotAreas areas;
    for (int j = 1; j <= kWidth; ++j) {
        // (Opens too where an area is NaN, so that all kWidth slots always open.)
        const bool opens = !(asNode < shared[j - 1]);
        areas[j - 1] = opens ? shared[j - 1] : asNode;
        plan.leftSlots[j - 1] = opens ? sharedLeft[j - 1] : 0;
    }
    return areas;
}

// Appends the slots that hold the subtree under `node` in at most `slotCount`, as planned.
void WideBvh::appendSlots(std::span<const BvhNode> binary, std::uint32_t node, int slotCount,
                          std::span<const SlotPlan> plans, std::span<std::uint32_t> slots,
                          int& used) {
    const int left = plans[node].leftSlots[slotCount - 1];
    if (left == 0) {
        slots[used++] = node;
        return;
    }
    appendSlots(binary, node + 1, left, plans, slots, used);
    appendSlots(binary, binary[node].offset, slotCount - left, plans, slots, used);
}

// Fills wide node `index` with the binary subtree under `root`, in the slots the plan gives it
// (leaves in the binary tree's order); then does the same for each interior child.
void WideBvh::collapse(std::span<const BvhNode> binary, std::uint32_t root, std::uint32_t index,
                       std::span<const SlotPlan> plans, const LeafLayout& layOutLeaf) {
    std::array<std::uint32_t, kWidth> slots{};
    int slotCount = 0;
    appendSlots(binary, root, kWidth, plans, slots, slotCount);  // a lone leaf takes one slot

    WideBvhNode node{};
    std::array<std::uint32_t, kWidth> interiorChildren{};  // binary roots of the wide children
    int interiorCount = 0;
    auto next = static_cast<std::uint32_t>(nodes_.size());
    for (int slot = 0; slot < kWidth; ++slot) {
        const Bounds3 box = slot < slotCount ? binary[slots[slot]].box() : Bounds3();
        for (int axis = 0; axis < 3; ++axis) {
            node.bounds[0][axis][slot] = box.min[axis];
            node.bounds[1][axis][slot] = box.max[axis];
        }
        if (slot >= slotCount) continue;
        const BvhNode& child = binary[slots[slot]];
        if (child.isLeaf()) {
            node.child[slot] = layOutLeaf(child.offset, child.primitiveCount);
            node.primitiveCount[slot] = child.primitiveCount;
        } else {
            node.child[slot] = next++;
            interiorChildren[interiorCount++] = slots[slot];
        }
    }
    // The interior children are stored side by side, after everything built so far.
    const std::uint32_t firstChild = static_cast<std::uint32_t>(nodes_.size());
    nodes_[index] = node;
    nodes_.resize(next);
    for (int i = 0; i < interiorCount; ++i)
        collapse(binary, interiorChildren[i], firstChild + static_cast<std::uint32_t>(i), plans,
                 layOutLeaf);
}

}  // namespace lancer
