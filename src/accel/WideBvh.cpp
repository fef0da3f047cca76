#include "accel/WideBvh.h"

#include <algorithm>
#include <array>

namespace lancer {

WideBvh::WideBvh(const Bvh& bvh, const LeafLayout& layOutLeaf) : bounds_(bvh.bounds()) {
    const std::span<const BvhNode> binary = bvh.nodes();
    if (binary.empty()) return;
    nodes_.emplace_back();
    collapse(binary, 0, 0, layOutLeaf);
    nodes_.shrink_to_fit();
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
