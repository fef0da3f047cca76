#include "BvhTestSupport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <utility>

namespace lancer::test {

std::string describe(const Ray& ray) {
    std::ostringstream text;
    text << std::setprecision(9) << "from (" << ray.origin.x << ", " << ray.origin.y << ", "
         << ray.origin.z << ") along (" << ray.direction.x << ", " << ray.direction.y << ", "
         << ray.direction.z << ")";
    return text.str();
}

std::string describe(const ClosestHit& hit) {
    if (hit.primitive < 0) return "none";
    std::ostringstream text;
    text << "t = " << std::hexfloat << hit.t << " on primitive " << hit.primitive;
    return text.str();
}

TriangleSoup bumpySphere(int levels) {
    const float g = (1 + std::sqrt(5.0f)) / 2;
    std::vector<Vec3> positions = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                   {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                   {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (Vec3& p : positions)
        p = normalize(p);
    std::vector<std::array<std::uint32_t, 3>> faces = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto [it, inserted] =
                midpoints.try_emplace(key, static_cast<std::uint32_t>(positions.size()));
            if (inserted) positions.push_back(normalize(positions[a] + positions[b]));
            return it->second;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        finer.reserve(4 * faces.size());
        for (const auto& [a, b, c] : faces) {
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({b, bc, ab});
            finer.push_back({c, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    for (Vec3& p : positions)
        p *= 1 + 0.2f * std::sin(5 * p.x) * std::sin(7 * p.y) * std::sin(3 * p.z + 1);
    TriangleSoup soup;
    for (const auto& [a, b, c] : faces)
        soup.add(positions[a], positions[b], positions[c]);
    return soup;
}

// On each axis one vertex is at -extent and another at +extent.
TriangleSoup sameCentroidSoup(std::uint32_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> size(0.1f, 1), within(-1, 1);
    TriangleSoup soup;
    for (std::uint32_t i = 0; i < n; ++i) {
        const float a = size(rng), b = size(rng), c = size(rng);
        soup.add({-a, -b, c * within(rng)}, {a, b * within(rng), -c}, {a * within(rng), b, c});
    }
    return soup;
}

namespace {

// The bits of a 10-bit integer spread to every third bit, for Morton codes.
std::uint32_t spreadBits(std::uint32_t x) {
    x = (x | (x << 16)) & 0x030000ff;
    x = (x | (x << 8)) & 0x0300f00f;
    x = (x | (x << 4)) & 0x030c30c3;
    x = (x | (x << 2)) & 0x09249249;
    return x;
}

constexpr std::uint32_t kGroupSize = 16;

}  // namespace

BruteForce::BruteForce(std::span<const Bounds3> primitiveBounds) {
    Bounds3 centroids;
    for (const Bounds3& b : primitiveBounds)
        centroids = merge(centroids, b.centroid());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed;  // Morton code, index
    keyed.reserve(primitiveBounds.size());
    for (std::uint32_t i = 0; i < primitiveBounds.size(); ++i) {
        const Vec3 cell = 1023.0f * centroids.offset(primitiveBounds[i].centroid());
        keyed.emplace_back(spreadBits(static_cast<std::uint32_t>(cell.x)) |
                               (spreadBits(static_cast<std::uint32_t>(cell.y)) << 1) |
                               (spreadBits(static_cast<std::uint32_t>(cell.z)) << 2),
                           i);
    }
    std::sort(keyed.begin(), keyed.end());
    for (const auto& [key, index] : keyed)
        members_.push_back(index);

    const auto sphereAround = [](const Bounds3& box, std::uint32_t begin, std::uint32_t end) {
        const Vec3d lo(box.min), hi(box.max);
        return Sphere{begin, end, 0.5 * (lo + hi), 0.5 * length(hi - lo)};
    };
    std::vector<Bounds3> groupBoxes;
    const auto count = static_cast<std::uint32_t>(members_.size());
    for (std::uint32_t begin = 0; begin < count; begin += kGroupSize) {
        const std::uint32_t end = std::min(begin + kGroupSize, count);
        Bounds3 box;
        for (std::uint32_t g = begin; g < end; ++g)
            box = merge(box, primitiveBounds[members_[g]]);
        groups_.push_back(sphereAround(box, begin, end));
        groupBoxes.push_back(box);
    }
    const auto groupCount = static_cast<std::uint32_t>(groups_.size());
    for (std::uint32_t begin = 0; begin < groupCount; begin += kGroupSize) {
        const std::uint32_t end = std::min(begin + kGroupSize, groupCount);
        Bounds3 box;
        for (std::uint32_t c = begin; c < end; ++c)
            box = merge(box, groupBoxes[c]);
        clusters_.push_back(sphereAround(box, begin, end));
    }
}

namespace {

bool inside(const Bounds3& inner, const Bounds3& outer) {
    return outer.contains(inner.min) && outer.contains(inner.max);
}

}  // namespace

TreeStats checkTree(const Bvh& bvh, std::span<const Bounds3> primitiveBounds) {
    TreeStats stats;
    const std::span<const BvhNode> nodes = bvh.nodes();
    const std::span<const std::uint32_t> order = bvh.primitiveOrder();
    EXPECT_EQ(order.size(), primitiveBounds.size());
    if (nodes.empty()) {
        EXPECT_TRUE(primitiveBounds.empty());
        return stats;
    }
    EXPECT_EQ(nodes[0].box().min, bvh.bounds().min);
    EXPECT_EQ(nodes[0].box().max, bvh.bounds().max);

    struct Visit {
        std::uint32_t node;
        int depth;
    };
    std::vector<Visit> stack = {{0, 0}};
    std::uint32_t nextPrimitive = 0;
    std::size_t visited = 0;
    while (!stack.empty()) {
        const auto [index, depth] = stack.back();
        stack.pop_back();
        ++visited;
        const BvhNode& node = nodes[index];
        if (node.isLeaf()) {
            ++stats.leafCount;
            stats.maxDepth = std::max(stats.maxDepth, depth);
            stats.maxLeafSize = std::max<std::uint32_t>(stats.maxLeafSize, node.primitiveCount);
            EXPECT_EQ(node.offset, nextPrimitive) << "leaves out of order at node " << index;
            nextPrimitive = node.offset + node.primitiveCount;
            for (std::uint32_t k = node.offset; k < nextPrimitive && k < order.size(); ++k)
                EXPECT_TRUE(inside(primitiveBounds[order[k]], node.box()))
                    << "primitive " << order[k] << " outside leaf " << index;
            continue;
        }
        if (node.offset <= index + 1 || node.offset >= nodes.size()) {
            ADD_FAILURE() << "node " << index << " has second child " << node.offset;
            return stats;
        }
        EXPECT_LT(node.axis, 3);
        for (const std::uint32_t child : {index + 1, node.offset})
            EXPECT_TRUE(inside(nodes[child].box(), node.box()))
                << "child " << child << " of " << index;
        // Second child pushed first: the first child's subtree is walked first, as it is stored.
        stack.push_back({node.offset, depth + 1});
        stack.push_back({index + 1, depth + 1});
    }
    EXPECT_EQ(nextPrimitive, order.size());
    EXPECT_EQ(visited, nodes.size());
    return stats;
}

}  // namespace lancer::test
