#include "geometry/Mesh.h"

#include "geometry/Triangle.h"
#include "materials/Material.h"

namespace lancer {

namespace {

std::vector<Bounds3> triangleBounds(const TriangleMesh& mesh) {
    std::vector<Bounds3> bounds(mesh.triangleCount());
    for (std::size_t i = 0; i < bounds.size(); ++i) {
        const std::uint32_t* v = &mesh.indices[3 * i];
        bounds[i] =
            merge(Bounds3(mesh.positions[v[0]], mesh.positions[v[1]]), mesh.positions[v[2]]);
    }
    return bounds;
}

// Puts the triangles in the order of the BVH's leaves.
void reorderTriangles(TriangleMesh& mesh, std::span<const std::uint32_t> order) {
    std::vector<std::uint32_t> indices(mesh.indices.size());
    std::vector<std::uint32_t> faceMaterials(mesh.faceMaterials.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        for (std::size_t j = 0; j < 3; ++j)
            indices[3 * k + j] = mesh.indices[3 * std::size_t{order[k]} + j];
        faceMaterials[k] = mesh.faceMaterials[order[k]];
    }
    mesh.indices = std::move(indices);
    mesh.faceMaterials = std::move(faceMaterials);
}

}  // namespace

Mesh::Mesh(TriangleMesh triangles)
    : Shape(nullptr), triangles_(std::move(triangles)), bvh_(triangleBounds(triangles_)) {
    reorderTriangles(triangles_, bvh_.primitiveOrder());
}

std::optional<TriangleIntersection> Mesh::intersectTriangle(std::uint32_t k, const Ray& ray,
                                                            float tMax) const {
    const std::uint32_t* v = &triangles_.indices[3 * std::size_t{k}];
    return Triangle::intersect(triangles_.positions[v[0]], triangles_.positions[v[1]],
                               triangles_.positions[v[2]], ray, tMax);
}

bool Mesh::intersect(const Ray& ray, float tMax, Hit& hit) const {
    // Only barycentrics and t during traversal; the hit record is filled once, for the nearest.
    TriangleIntersection nearest{};
    std::uint32_t nearestIndex = 0;
    const bool found = bvh_.intersect(ray, tMax, [&](std::uint32_t k, const Ray& r, float& tFar) {
        const auto at = intersectTriangle(k, r, tFar);
        if (!at) return false;
        nearest = *at;
        nearestIndex = k;
        tFar = at->t;
        return true;
    });
    if (!found) return false;
    Triangle::fillHit(triangles_, nearestIndex, nearest, hit);
    hit.shape = this;
    return true;
}

bool Mesh::occluded(const Ray& ray, float tMax) const {
    return bvh_.occluded(ray, tMax, [&](std::uint32_t k, const Ray& r, float tFar) {
        return intersectTriangle(k, r, tFar).has_value();
    });
}

bool Mesh::hasTransmissiveMaterial() const {
    for (const auto& material : triangles_.materials)
        if (material->isTransmissive()) return true;
    return false;
}

std::size_t Mesh::memoryBytes() const {
    const TriangleMesh& m = triangles_;
    return m.positions.size() * sizeof(Vec3) + m.normals.size() * sizeof(Vec3) +
           m.uvs.size() * sizeof(Vec2) + m.indices.size() * sizeof(std::uint32_t) +
           m.faceMaterials.size() * sizeof(std::uint32_t) + bvh_.memoryBytes();
}

}  // namespace lancer
