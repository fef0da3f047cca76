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

    bool intersect(const Ray& ray, float tMax, Hit& hit) const override;
    bool occluded(const Ray& ray, float tMax) const override;
    Bounds3 bounds() const override;
    bool isBounded() const override { return shape_->isBounded(); }
    bool emitsOnBothSides() const override { return shape_->emitsOnBothSides(); }
    std::uint32_t primitiveCount() const override { return shape_->primitiveCount(); }
    // The instance's own material, when it has one, replaces the shape's.
    const Material* primitiveMaterial(std::uint32_t primitive) const override;

    const Shape& placedShape() const { return *shape_; }
    const Transform& objectToWorld() const { return objectToWorld_; }

private:
    // The ray in the shape's space, and the shift of its parameter t (see intersect).
    Ray toObject(const Ray& ray, float& shift) const;

    std::shared_ptr<const Shape> shape_;
    Transform objectToWorld_;
    Transform worldToObject_;
};

}  // namespace lancer
