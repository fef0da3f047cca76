#pragma once

#include "accel/Bvh.h"
#include "geometry/Shape.h"
#include "geometry/Triangle.h"
#include "geometry/TriangleMesh.h"

namespace lancer {

// A triangle mesh as one shape, with its own BVH over its triangles (the bottom level of the
// scene's two-level structure). The triangles are reordered to follow the BVH's leaves, so that
// a leaf's triangles are contiguous in memory. Shared by all instances of the same model.
class Mesh final : public Shape {
public:
    explicit Mesh(TriangleMesh triangles);

    bool intersect(const Ray& ray, float tMax, Hit& hit) const override;
    bool occluded(const Ray& ray, float tMax) const override;
    Bounds3 bounds() const override { return bvh_.bounds(); }
    bool emitsOnBothSides() const override { return false; }
    bool hasTransmissiveMaterial() const override;

    const TriangleMesh& triangles() const { return triangles_; }
    // Bytes held by the mesh's arrays and its BVH.
    std::size_t memoryBytes() const;

private:
    // Triangle k's intersection with the ray, if any.
    std::optional<TriangleIntersection> intersectTriangle(std::uint32_t k, const Ray& ray,
                                                          float tMax) const;

    TriangleMesh triangles_;
    Bvh bvh_;
};

}  // namespace lancer
