#pragma once

#include "geometry/Shape.h"

namespace lancer {

// An infinite, two-sided plane through `point` with unit normal `normal`.
class Plane final : public Shape {
public:
    Plane(const Vec3& point, const Vec3& normal, const Material* material);

    bool intersect(const Ray& ray, float tMax, Hit& hit) const override;
    Bounds3 bounds() const override;
    bool isBounded() const override { return false; }

    const Vec3& point() const { return point_; }
    const Vec3& normal() const { return normal_; }

private:
    Vec3 point_;
    Vec3 normal_;
    int uAxis_, vAxis_;  // the world axes used as texture coordinates
    Vec3 dpdu_, dpdv_;   // steps along the plane that change u (or v) by one and keep v (or u)
};

}  // namespace lancer
