#pragma once

#include <memory>

#include "geometry/Shape.h"
#include "math/Transform.h"

namespace lancer {

// A shape placed in the world by a transform: rays are carried into the shape's own space, hits
// carried back. Several instances can share one shape (a mesh loaded once, drawn many times),
// each with its own transform and, optionally, its own material replacing the shape's.
class Instance final : public Shape {
public:
    Instance(std::shared_ptr<const Shape> shape, const Transform& objectToWorld,
             const Material* materialOverride = nullptr);

    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    bool occluded(const Ray& ray, float tMax) const override;
    Bounds3 bounds() const override;
    bool isBounded() const override { return shape_->isBounded(); }
    bool isSolid() const override { return shape_->isSolid(); }
    void crossLine(const Ray& ray, LineCrossings& crossings) const override;
    void crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const override;
    bool emitsOnBothSides() const override { return shape_->emitsOnBothSides(); }
    std::uint32_t primitiveCount() const override { return shape_->primitiveCount(); }
    // The instance's own material, when it has one, replaces the shape's.
    const Material* primitiveMaterial(std::uint32_t primitive) const override;
    // The shape's samples carried into the world, their density divided by how much the
    // transform stretches the surface there: exact for flat primitives and for similarities,
    // the stretch at one point for the area of a curved primitive under a non-uniform scale.
    float area(std::uint32_t primitive) const override;
    std::optional<ShapeSample> sample(std::uint32_t primitive, const Vec2& u) const override;
    float areaPdf(std::uint32_t primitive, const Hit& onSurface) const override;
    // The shape's facets in the world, asked as fine as the world-space size needs.
    Tessellation tessellate(const TessellationRequest& request) const override;

private:
    // The ray in the shape's space, and the shift of its parameter t (see intersect).
    Ray toObject(const Ray& ray, float& shift) const;
    // The factor by which the transform multiplies areas of the surface whose unit normal (in
    // the shape's space) is n.
    float areaStretch(const Vec3& n) const;
    // The longest that a unit vector of the shape's space becomes in the world (about).
    float largestStretch() const;

    std::shared_ptr<const Shape> shape_;
    Transform objectToWorld_;
    Transform worldToObject_;
    float determinant_;  // of the linear part of objectToWorld
    bool flipsOrientation_;
    // An object placed without a transform (most models) passes rays and records through as
    // they are: the identity needs no rounding error bound, and no normal renormalised.
    bool identity_;
};

}  // namespace lancer
