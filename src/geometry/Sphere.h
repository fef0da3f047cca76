#pragma once

#include "geometry/Shape.h"

namespace lancer {

class Sphere final : public Shape {
public:
    Sphere(const Vec3& center, float radius, const Material* material);

    bool intersect(const Ray& ray, float tMax, Hit& hit) const override;
    Bounds3 bounds() const override;

    const Vec3& center() const { return center_; }
    float radius() const { return radius_; }

private:
    Vec3 center_;
    float radius_;
};

}  // namespace lancer
