#pragma once

#include <array>
#include <optional>

#include "geometry/Shape.h"

namespace lancer {

// A triangle v0 v1 v2. Its front side, the one (v1 - v0) x (v2 - v0) points to, is the side it
// emits light on. Optional per-vertex normals give smooth shading, optional uvs texture
// coordinates (by default (0,0), (1,0), (0,1)).
class Triangle final : public Shape {
public:
    Triangle(const std::array<Vec3, 3>& vertices, const Material* material,
             const std::optional<std::array<Vec3, 3>>& normals = std::nullopt,
             const std::optional<std::array<Vec2, 3>>& uvs = std::nullopt);

    bool intersect(const Ray& ray, float tMax, Hit& hit) const override;
    bool emitsOnBothSides() const override { return false; }

    // Twice the area is |(v1 - v0) x (v2 - v0)|; a triangle with zero area can never be hit.
    float area() const;

private:
    std::array<Vec3, 3> v_;
    std::optional<std::array<Vec3, 3>> n_;
    std::array<Vec2, 3> uv_;
    Vec3 geometricNormal_;
};

}  // namespace lancer
