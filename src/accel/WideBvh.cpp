#include "accel/WideBvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace lancer {

WideBvh::WideBvh(const Bvh& bvh, const LeafLayout& layOutLeaf) : bounds_(bvh.bounds()) {
    const std::span<const BvhNode> binary = bvh.nodes();
    if (binary.empty()) return;
    nodes_.emplace_back();
    collapse(binary, 0, 0, layOutLeaf);
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

// Fills wide node `index` with the binary subtree under `root`, cut into at most kWidth children
// by opening the interior node of largest surface area (the most likely to be entered) until
// kWidth are reached or only leaves are left; then does the same for each interior child.
void WideBvh::collapse(std::span<const BvhNode> binary, std::uint32_t root, std::uint32_t index,
                       const LeafLayout& layOutLeaf) {
    constexpr int kWidth = WideBvhNode::kWidth;
    std::array<std::uint32_t, kWidth> slots{root};
    int slotCount = 1;
    const auto widestInterior = [&] {
        int widest = -1;
        float widestArea = -1;
        for (int i = 0; i < slotCount; ++i) {
            const BvhNode& node = binary[slots[i]];
            if (node.isLeaf()) continue;
            const float area = node.box().surfaceArea();
            if (area > widestArea) {
                widest = i;
                widestArea = area;
            }
        }
        return widest;
    };
    for (int opened; slotCount < kWidth && (opened = widestInterior()) >= 0;) {
        // Its two children take its place, in order, so that leaves keep the binary tree's order.
        const std::uint32_t node = slots[opened];
        std::copy_backward(slots.begin() + opened + 1, slots.begin() + slotCount,
                           slots.begin() + slotCount + 1);
        slots[opened] = node + 1;
        slots[opened + 1] = binary[node].offset;
        ++slotCount;
    }

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
        collapse(binary, interiorChildren[i], firstChild + static_cast<std::uint32_t>(i),
                 layOutLeaf);
}

}  // namespace lancer
