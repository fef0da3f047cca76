// A mesh made again from its parts (what the model cache keeps) is the mesh it was, and parts that
// do not fit together, as a damaged cache entry may hold, are refused before any ray meets them:
// indices past their arrays, trees that loop, go too deep or have boxes in unused slots.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "accel/Mesh.h"
#include "geometry/Hit.h"
#include "materials/BlinnPhongMaterial.h"
#include "math/Ray.h"

namespace lancer::test {
namespace {

// A bumpy grid of side x side quads, enough triangles for a tree of several wide nodes.
TriangleMesh grid(int side) {
    TriangleMesh mesh;
    for (int y = 0; y <= side; ++y)
        for (int x = 0; x <= side; ++x)
            mesh.positions.push_back(Vec3(static_cast<float>(x), static_cast<float>(y),
                                          std::sin(static_cast<float>(x * y))));
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const auto a = static_cast<std::uint32_t>(y * (side + 1) + x), b = a + 1,
                       c = a + static_cast<std::uint32_t>(side) + 2, d = c - 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
            mesh.faceMaterials.insert(mesh.faceMaterials.end(), {0, 0});
        }
    mesh.materials.push_back(std::make_shared<BlinnPhongMaterial>());
    return mesh;
}

Mesh::Parts partsOf(const Mesh& mesh) {
    return {mesh.triangles(), mesh.bounds(),
            std::vector<WideBvhNode>(mesh.bvhNodes().begin(), mesh.bvhNodes().end()),
            std::vector<TrianglePack>(mesh.packs().begin(), mesh.packs().end())};
}

class MeshPartsTest : public ::testing::Test {
protected:
    MeshPartsTest() : built_(grid(20)) {}

    // Whether the built mesh's parts, changed by `change`, are refused.
    bool refused(const std::function<void(Mesh::Parts&)>& change) const {
        Mesh::Parts parts = partsOf(built_);
        change(parts);
        try {
            Mesh mesh(std::move(parts));
        } catch (const std::invalid_argument&) {
            return true;
        }
        return false;
    }

    // The first interior child slot of node 0.
    int interiorSlot() const {
        const WideBvhNode& root = built_.bvhNodes()[0];
        for (int slot = 0; slot < WideBvhNode::kWidth; ++slot)
            if (root.primitiveCount[slot] == 0 && root.child[slot] != 0) return slot;
        ADD_FAILURE() << "the root has no interior child";
        return 0;
    }

    Mesh built_;
};

TEST_F(MeshPartsTest, TheMeshMadeAgainFromItsPartsHitsAlike) {
    ASSERT_GT(built_.bvhNodes().size(), 2u);
    const Mesh again(partsOf(built_));
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        const float x = 0.05f * static_cast<float>(i % 20) + 0.5f * static_cast<float>(i / 20);
        const Ray ray{Vec3(x, 0.37f * static_cast<float>(i % 23), 5),
                      normalize(Vec3(0.1f, 0.2f, -1))};
        const auto a = built_.cross(ray, kInfinity), b = again.cross(ray, kInfinity);
        ASSERT_EQ(a.has_value(), b.has_value());
        if (a) {
            ++hits;
            EXPECT_EQ(a->tShape, b->tShape);
            EXPECT_EQ(a->primitive, b->primitive);
        }
        EXPECT_EQ(built_.occluded(ray, 100), again.occluded(ray, 100));
    }
    EXPECT_GT(hits, 200);
}

TEST_F(MeshPartsTest, IndicesPastTheirArraysAreRefused) {
    EXPECT_FALSE(refused([](Mesh::Parts&) {}));
    EXPECT_TRUE(refused([](Mesh::Parts& p) {
        p.triangles.indices[7] = static_cast<std::uint32_t>(p.triangles.positions.size());
    }));
    EXPECT_TRUE(refused([](Mesh::Parts& p) { p.triangles.faceMaterials[3] = 1; }));
    EXPECT_TRUE(refused([](Mesh::Parts& p) { p.triangles.faceMaterials.pop_back(); }));
    EXPECT_TRUE(refused([](Mesh::Parts& p) { p.triangles.indices.pop_back(); }));
    EXPECT_TRUE(refused([](Mesh::Parts& p) { p.triangles.normals.resize(3); }));
    EXPECT_TRUE(refused([](Mesh::Parts& p) { p.triangles.uvs.resize(1); }));
    EXPECT_TRUE(refused([](Mesh::Parts& p) {
        p.packs[2].triangle[1] = static_cast<std::uint32_t>(p.triangles.triangleCount());
    }));
    EXPECT_TRUE(refused([](Mesh::Parts& p) { p.packs.pop_back(); }));  // a leaf's last pack
}

TEST_F(MeshPartsTest, TreesThatLoopOrHaveBoxesInUnusedSlotsAreRefused) {
    const int slot = interiorSlot();
    EXPECT_TRUE(refused([&](Mesh::Parts& p) { p.nodes[0].child[slot] = 0; }));  // a box, unused
    // An unused slot's box inverted by less than rounding, which a ray meets (found by fuzzing).
    EXPECT_TRUE(refused([](Mesh::Parts& p) {
        for (WideBvhNode& node : p.nodes)
            for (int unused = 0; unused < WideBvhNode::kWidth; ++unused)
                if (node.primitiveCount[unused] == 0 && node.child[unused] == 0) {
                    for (int axis = 0; axis < 3; ++axis) {
                        node.bounds[0][axis][unused] = 2e-38f;
                        node.bounds[1][axis][unused] = 1e-38f;
                    }
                    return;
                }
        FAIL() << "no unused slot in the tree";
    }));
    EXPECT_TRUE(refused([&](Mesh::Parts& p) {  // a node with two parents
        for (int other = 0; other < WideBvhNode::kWidth; ++other)
            if (other != slot && p.nodes[0].primitiveCount[other] == 0 &&
                p.nodes[0].child[other] != 0)
                p.nodes[0].child[other] = p.nodes[0].child[slot];
    }));
    EXPECT_TRUE(refused([&](Mesh::Parts& p) {
        const std::uint32_t child = p.nodes[0].child[slot];
        p.nodes[child] = p.nodes[0];  // its interior children now point back before it
    }));
    EXPECT_TRUE(refused([&](Mesh::Parts& p) {
        p.nodes[0].child[slot] = static_cast<std::uint32_t>(p.nodes.size());
    }));
    EXPECT_TRUE(
        refused([](Mesh::Parts& p) { p.bounds.min.x = std::numeric_limits<float>::quiet_NaN(); }));
    EXPECT_TRUE(refused([](Mesh::Parts& p) { p.bounds = Bounds3(); }));  // empty
}

TEST_F(MeshPartsTest, ATreeDeeperThanTheTraversalsStackIsRefused) {
    // A chain of nodes, each with one interior child and one leaf.
    const auto chain = [](int length) {
        return [length](Mesh::Parts& p) {
            WideBvhNode link{};
            for (int slot = 0; slot < WideBvhNode::kWidth; ++slot)
                for (int axis = 0; axis < 3; ++axis) {
                    link.bounds[0][axis][slot] = slot < 2 ? 0.0f : kInfinity;
                    link.bounds[1][axis][slot] = slot < 2 ? 1.0f : -kInfinity;
                }
            link.primitiveCount[1] = 1;  // the first pack's triangles
            p.nodes.assign(static_cast<std::size_t>(length), link);
            for (int i = 0; i + 1 < length; ++i)
                p.nodes[static_cast<std::size_t>(i)].child[0] = static_cast<std::uint32_t>(i + 1);
            p.nodes.back().primitiveCount[0] = 1;
        };
    };
    EXPECT_FALSE(refused(chain(Bvh::kMaxDepth)));
    EXPECT_TRUE(refused(chain(Bvh::kMaxDepth + 2)));
}

}  // namespace
}  // namespace lancer::test
