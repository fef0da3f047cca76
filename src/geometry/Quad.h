#pragma once

#include "geometry/Shape.h"
#include "math/Vec2.h"

namespace lancer {

// A parallelogram: the points corner + u edge1 + v edge2 for u, v in [0, 1], with uv = (u, v).
// Its front side, the one edge1 x edge2 points to, is the side it emits light on (a quad light's
// visible surface).
class Quad final : public Shape {
public:
    Quad(const Vec3& corner, const Vec3& edge1, const Vec3& edge2, const Material* material);

    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    Bounds3 bounds() const override;
    bool emitsOnBothSides() const override { return false; }
    float area(std::uint32_t) const override { return area_; }
    std::optional<ShapeSample> sample(std::uint32_t primitive, const Vec2& u) const override;
    // Two facets, split along the diagonal from the corner.
    Tessellation tessellate(const TessellationRequest& request) const override;

    // The unit normal on the front side.
    const Vec3& normal() const { return normal_; }
    // The point at surface coordinates uv.
    Vec3 pointAt(const Vec2& uv) const { return corner_ + uv.x * edge1_ + uv.y * edge2_; }

private:
    Vec3 corner_, edge1_, edge2_;
    Vec3 normal_;
    float area_;
};

}  // namespace lancer
