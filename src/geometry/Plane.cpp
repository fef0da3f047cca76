#include "geometry/Plane.h"

namespace lancer {

Plane::Plane(const Vec3& point, const Vec3& normal, const Material* material)
    : Shape(material), point_(point), normal_(normalize(normal)) {
    // uv are world coordinates: (x, z) for a plane facing y, (x, y) facing z, (y, z) facing x.
    const int normalAxis = maxDimension(normal_);
    uAxis_ = normalAxis == 0 ? 1 : 0;
    vAxis_ = normalAxis == 2 ? 1 : 2;
    // Moving by one along the u axis, the point must also move along the normal's main axis to
    // stay on the plane; likewise for v.
    dpdu_[uAxis_] = 1;
    dpdu_[normalAxis] = -normal_[uAxis_] / normal_[normalAxis];
    dpdv_[vAxis_] = 1;
    dpdv_[normalAxis] = -normal_[vAxis_] / normal_[normalAxis];
}

Bounds3 Plane::bounds() const {
    return {Vec3(-kInfinity), Vec3(kInfinity)};
}

bool Plane::intersect(const Ray& ray, float tMax, Hit& hit) const {
    // In double precision, for the same reason as the sphere: the sign of t must be exact for a
    // ray spawned just off the plane.
    const Vec3d n(normal_);
    const Vec3d d(ray.direction);
    const double denominator = dot(n, d);
    if (denominator == 0) return false;  // parallel: never meets the plane
    const Vec3d o(ray.origin);
    const Vec3d p0(point_);
    const double t = dot(n, p0 - o) / denominator;
    if (!(t > 0 && t < tMax)) return false;

    Vec3d onPlane = o + t * d;
    onPlane -= (dot(n, onPlane - p0) / dot(n, n)) * n;
    const Vec3 p(onPlane);

    hit.t = static_cast<float>(t);
    hit.p = p;
    hit.pError = gamma(2) * abs(p);
    hit.ng = normal_;
    hit.ns = normal_;
    hit.dpdu = dpdu_;
    hit.dpdv = dpdv_;
    hit.uv = {p[uAxis_], p[vAxis_]};
    hit.shape = this;
    hit.primitive = 0;
    hit.material = material();
    return true;
}

}  // namespace lancer
