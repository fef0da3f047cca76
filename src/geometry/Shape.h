#pragma once

#include <cstdint>

#include "geometry/Hit.h"
#include "math/Bounds3.h"
#include "math/Ray.h"

namespace lancer {

class Light;
class Material;

// A surface a ray can hit. A shape may carry the material it is made of; shapes that carry
// several (meshes) leave it null and set Hit::material themselves.
class Shape {
public:
    explicit Shape(const Material* material) : material_(material) {}
    virtual ~Shape() = default;
    Shape(const Shape&) = delete;
    Shape& operator=(const Shape&) = delete;

    // Finds the nearest intersection with 0 < t < tMax. On success fills `hit` (t, p, pError,
    // ng, ns, dpdu, dpdv, uv, shape, material) and returns true; on failure leaves `hit` untouched.
    virtual bool intersect(const Ray& ray, float tMax, Hit& hit) const = 0;

    // Whether anything is hit with 0 < t < tMax: shadow rays, which need no hit record and can
    // stop at the first hit found.
    virtual bool occluded(const Ray& ray, float tMax) const {
        Hit hit;
        return intersect(ray, tMax, hit);
    }

    // The box the shape fits in. Only meaningful when isBounded().
    virtual Bounds3 bounds() const = 0;
    // False for shapes that extend to infinity (planes), which stay outside the BVH.
    virtual bool isBounded() const { return true; }

    // Whether a material's emission leaves both sides of the surface (spheres and planes) or
    // only the side the geometric normal points to (triangles).
    virtual bool emitsOnBothSides() const { return true; }

    const Material* material() const { return material_; }

    // The surface is made of primitives (a mesh's triangles; the shape itself for the others),
    // numbered as Hit::primitive numbers them, each of one material (null: none of its own).
    virtual std::uint32_t primitiveCount() const { return 1; }
    virtual const Material* primitiveMaterial(std::uint32_t) const { return material_; }

    // The light whose visible surface this shape is (an area light's quad or sphere, an emissive
    // surface sampled as a light), or null. Integrators use it to weigh a ray that hits the light
    // against sampling the light directly.
    const Light* areaLight() const { return areaLight_; }
    void setAreaLight(const Light* light) { areaLight_ = light; }

private:
    const Material* material_;
    const Light* areaLight_ = nullptr;
};

}  // namespace lancer
