#include "geometry/Instance.h"

namespace lancer {

Instance::Instance(std::shared_ptr<const Shape> shape, const Transform& objectToWorld,
                   const Material* materialOverride)
    : Shape(materialOverride),
      shape_(std::move(shape)),
      objectToWorld_(objectToWorld),
      worldToObject_(objectToWorld.inverse()) {}

const Material* Instance::primitiveMaterial(std::uint32_t primitive) const {
    return material() ? material() : shape_->primitiveMaterial(primitive);
}

Bounds3 Instance::bounds() const {
    return objectToWorld_.applyBounds(shape_->bounds());
}

Ray Instance::toObject(const Ray& ray, float& shift) const {
    // The transformed origin carries rounding error; moving it forward to the edge of that error
    // along the ray keeps it from starting behind the surface it left (pbrt 6.8.6). The ray's
    // parameter is unchanged by an affine map, up to this shift.
    Vec3 originError;
    Vec3 origin = worldToObject_.applyPoint(ray.origin, Vec3(0), originError);
    const Vec3 direction = worldToObject_.applyVector(ray.direction);
    shift = 0;
    if (const float lengthSq = lengthSquared(direction); lengthSq > 0) {
        shift = dot(abs(direction), originError) / lengthSq;
        origin += direction * shift;
    }
    return {origin, direction};
}

bool Instance::occluded(const Ray& ray, float tMax) const {
    float shift;
    const Ray local = toObject(ray, shift);
    return shape_->occluded(local, tMax - shift);
}

bool Instance::intersect(const Ray& ray, float tMax, Hit& hit) const {
    float shift;
    const Ray local = toObject(ray, shift);
    if (!shape_->intersect(local, tMax - shift, hit)) return false;

    hit.t += shift;
    Vec3 pError;
    hit.p = objectToWorld_.applyPoint(hit.p, hit.pError, pError);
    hit.pError = pError;
    hit.ng = normalize(objectToWorld_.applyNormal(hit.ng));
    hit.ns = normalize(objectToWorld_.applyNormal(hit.ns));
    hit.dpdu = objectToWorld_.applyVector(hit.dpdu);
    hit.dpdv = objectToWorld_.applyVector(hit.dpdv);
    if (material()) hit.material = material();
    hit.shape = this;
    return true;
}

}  // namespace lancer
