#pragma once

#include "geometry/Hit.h"
#include "geometry/Ray.h"

namespace lancer {

class Material;

// A surface a ray can hit. Each shape carries the material it is made of.
class Shape {
public:
    explicit Shape(const Material* material) : material_(material) {}
    virtual ~Shape() = default;
    Shape(const Shape&) = delete;
    Shape& operator=(const Shape&) = delete;

    // Finds the nearest intersection with 0 < t < tMax. On success fills `hit` (t, p, pError,
    // ng, ns, uv, shape) and returns true; on failure leaves `hit` untouched.
    virtual bool intersect(const Ray& ray, float tMax, Hit& hit) const = 0;

    // Whether the material's emission leaves both sides of the surface (spheres and planes) or
    // only the side the geometric normal points to (triangles).
    virtual bool emitsOnBothSides() const { return true; }

    const Material& material() const { return *material_; }

private:
    const Material* material_;
};

}  // namespace lancer
