#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "math/Vec2.h"
#include "math/Vec3.h"

namespace lancer {

class Material;

// Triangles sharing vertices, as loaded from a model file. Vertex attributes are indexed
// together: vertex i has positions[i], normals[i] (if any) and uvs[i] (if any).
struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // per vertex, or empty; a zero normal means "none" (flat shading)
    std::vector<Vec2> uvs;      // per vertex, or empty (uvs default to (0,0), (1,0), (0,1))
    std::vector<std::uint32_t> indices;        // 3 per triangle, counter-clockwise = front
    std::vector<std::uint32_t> faceMaterials;  // per triangle, an index into materials
    std::vector<std::shared_ptr<const Material>> materials;

    std::size_t triangleCount() const { return indices.size() / 3; }
};

}  // namespace lancer
