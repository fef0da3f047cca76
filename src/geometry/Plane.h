#pragma once

#include "geometry/Shape.h"

namespace lancer {

// An infinite, two-sided plane through `point` with unit normal `normal`.
class Plane final : public Shape {
public:
    Plane(const Vec3& point, const Vec3& normal, const Material* material);

    bool intersect(const Ray& ray, float tMax, Hit& hit) const override;

    const Vec3& point() const { return point_; }
    const Vec3& normal() const { return normal_; }

private:
    Vec3 point_;
    Vec3 normal_;
    int uAxis_, vAxis_;  // the world axes used as texture coordinates
};

}  // namespace lancer
