#include "geometry/Sphere.h"

#include <cmath>

namespace lancer {

Sphere::Sphere(const Vec3& center, float radius, const Material* material)
    : Shape(material), center_(center), radius_(radius) {}

Bounds3 Sphere::bounds() const {
    return {center_ - Vec3(radius_), center_ + Vec3(radius_)};
}

bool Sphere::intersect(const Ray& ray, float tMax, Hit& hit) const {
    // Solved in double precision: the roots, and so the side of the surface a spawned ray starts
    // on, are then exact to far below the float error bound used to offset spawned rays.
    const Vec3d o = Vec3d(ray.origin) - Vec3d(center_);
    const Vec3d d(ray.direction);
    const double r = radius_;
    const double a = dot(d, d);
    if (a == 0) return false;
    const double halfB = dot(o, d);
    const double c = dot(o, o) - r * r;
    // b^2 - 4ac rewritten with the closest point of the line to the centre (Ray Tracing Gems,
    // ch. 7), which keeps its precision for small spheres far from the ray origin.
    const Vec3d toLine = o - (halfB / a) * d;
    const double discriminant = a * (r * r - dot(toLine, toLine));
    if (discriminant < 0) return false;
    const double q = -(halfB + std::copysign(std::sqrt(discriminant), halfB));
    double t0 = q / a;
    double t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 >= tMax || t1 <= 0) return false;
    const double t = t0 > 0 ? t0 : t1;
    if (t >= tMax) return false;

    // Project the point back onto the surface; what remains is the rounding to float.
    Vec3d local = o + t * d;
    local *= r / length(local);
    const Vec3 p = Vec3(Vec3d(center_) + local);
    const Vec3 n = Vec3(local / r);

    hit.t = static_cast<float>(t);
    hit.p = p;
    hit.pError = gamma(2) * abs(p);
    hit.ng = n;
    hit.ns = n;
    // u: longitude from +x towards -z (counter-clockwise seen from +y), v: latitude, south to
    // north.
    float phi = std::atan2(-n.z, n.x);
    if (phi < 0) phi += 2 * kPi;
    hit.uv = {phi / (2 * kPi), 0.5f + std::asin(clamp(n.y, -1.0f, 1.0f)) / kPi};
    hit.shape = this;
    hit.primitive = 0;
    hit.material = material();
    return true;
}

}  // namespace lancer
