#pragma once

#include <span>
#include <vector>

#include "accel/WideBvh.h"
#include "geometry/Shape.h"
#include "geometry/Triangle.h"
#include "geometry/TriangleMesh.h"
#include "geometry/TrianglePack.h"

namespace lancer {

// A triangle mesh as one shape, with its own BVH over its triangles (the bottom level of the
// scene's two-level structure): the binary tree the build gives, collapsed into an 8-wide one for
// the traversal, whose leaves hold their triangles' vertices in packs of four tested together.
// The triangles are reordered to follow the BVH's leaves. Shared by all instances of the same
// model.
class Mesh final : public Shape {
public:
    explicit Mesh(TriangleMesh triangles);

    // What a built mesh is made of, to keep it and make it again without the build (the model
    // cache): the triangles in the order of the leaves, the BVH's nodes and the leaves' packs.
    struct Parts {
        TriangleMesh triangles;
        Bounds3 bounds;
        std::vector<WideBvhNode> nodes;
        std::vector<TrianglePack> packs;
    };
    // Throws std::invalid_argument when the parts do not fit together: an index past its array
    // (a vertex, a material, a triangle of a pack, the packs of a leaf) or a malformed tree.
    explicit Mesh(Parts parts);

    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    bool occluded(const Ray& ray, float tMax) const override;
    Bounds3 bounds() const override { return bvh_.bounds(); }
    // A closed model, wound outwards, is a solid (checked by welding its vertices by position:
    // each call walks all its edges).
    bool isSolid() const override;
    void crossLine(const Ray& ray, LineCrossings& crossings) const override;
    void crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const override;
    bool emitsOnBothSides() const override { return false; }
    std::uint32_t primitiveCount() const override {
        return static_cast<std::uint32_t>(triangles_.triangleCount());
    }
    const Material* primitiveMaterial(std::uint32_t triangle) const override;
    float area(std::uint32_t triangle) const override;
    std::optional<ShapeSample> sample(std::uint32_t triangle, const Vec2& u) const override;
    // The triangles as they are.
    Tessellation tessellate(const TessellationRequest& request) const override;

    const TriangleMesh& triangles() const { return triangles_; }
    // The rest of the parts.
    std::span<const WideBvhNode> bvhNodes() const { return bvh_.nodes(); }
    std::span<const TrianglePack> packs() const { return packs_; }
    // Bytes held by the mesh's arrays and its BVH.
    std::size_t memoryBytes() const;

private:
    std::array<Vec3, 3> vertices(std::uint32_t triangle) const;
    // Asks the cache for a leaf's first pack.
    void prefetchPack(std::uint32_t pack) const;

    TriangleMesh triangles_;
    WideBvh bvh_;
    // The vertices again, for the traversal: each leaf's triangles in packs of their own, so that
    // a leaf of up to four is one 4-wide test, and read without going through the index buffer.
    std::vector<TrianglePack> packs_;
};

}  // namespace lancer
