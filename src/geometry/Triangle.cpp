#include "geometry/Triangle.h"

#include <cmath>

namespace lancer {

Triangle::Triangle(const std::array<Vec3, 3>& vertices, const Material* material,
                   const std::optional<std::array<Vec3, 3>>& normals,
                   const std::optional<std::array<Vec2, 3>>& uvs)
    : Shape(material),
      v_(vertices),
      n_(normals),
      uv_(uvs.value_or(std::array<Vec2, 3>{Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}})) {
    const Vec3 n = cross(v_[1] - v_[0], v_[2] - v_[0]);
    geometricNormal_ = lengthSquared(n) > 0 ? normalize(n) : Vec3(0, 0, 0);
}

float Triangle::area() const {
    return 0.5f * length(cross(v_[1] - v_[0], v_[2] - v_[0]));
}

namespace {

// The 2D edge function a.x * b.y - a.y * b.x, recomputed in double when float rounds it to exactly
// zero: that is what makes the test watertight on shared edges (Woop et al. 2013).
float edgeFunction(const Vec3& a, const Vec3& b) {
    const float e = a.x * b.y - a.y * b.x;
    if (e != 0) return e;
    return static_cast<float>(double(a.x) * double(b.y) - double(a.y) * double(b.x));
}

}  // namespace

// Watertight ray/triangle intersection (Woop, Benthin and Wald 2013, in pbrt's formulation): the
// triangle is moved into a frame where the ray starts at the origin and runs along +z, so that
// the test reduces to the signs of three 2D edge functions, which agree exactly along a shared
// edge. The t > 0 test is made conservative with a bound on the error of the computed t.
bool Triangle::intersect(const Ray& ray, float tMax, Hit& hit) const {
    // Translate to the ray origin, permute so that the ray's largest component is z, then shear.
    Vec3 p0 = v_[0] - ray.origin, p1 = v_[1] - ray.origin, p2 = v_[2] - ray.origin;
    const int kz = maxDimension(ray.direction);
    const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    const Vec3 d = permute(ray.direction, kx, ky, kz);
    if (d.z == 0) return false;
    p0 = permute(p0, kx, ky, kz);
    p1 = permute(p1, kx, ky, kz);
    p2 = permute(p2, kx, ky, kz);
    const float shearX = -d.x / d.z, shearY = -d.y / d.z, shearZ = 1.0f / d.z;
    for (Vec3* p : {&p0, &p1, &p2}) {
        p->x += shearX * p->z;
        p->y += shearY * p->z;
    }

    const float e0 = edgeFunction(p1, p2);
    const float e1 = edgeFunction(p2, p0);
    const float e2 = edgeFunction(p0, p1);
    if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
    const float det = e0 + e1 + e2;
    if (det == 0) return false;  // degenerate triangle, or a ray in its plane

    // t, still scaled by det; compared against the range without dividing.
    p0.z *= shearZ;
    p1.z *= shearZ;
    p2.z *= shearZ;
    const float tScaled = e0 * p0.z + e1 * p1.z + e2 * p2.z;
    if (det < 0 && (tScaled >= 0 || tScaled < tMax * det)) return false;
    if (det > 0 && (tScaled <= 0 || tScaled > tMax * det)) return false;

    const float invDet = 1.0f / det;
    const float b0 = e0 * invDet, b1 = e1 * invDet, b2 = e2 * invDet;
    const float t = tScaled * invDet;
    if (!(t < tMax)) return false;

    // Reject t that is not certainly positive given the rounding errors above (pbrt 6.8.4).
    const float maxZ = maxComponent(abs(Vec3(p0.z, p1.z, p2.z)));
    const float maxX = maxComponent(abs(Vec3(p0.x, p1.x, p2.x)));
    const float maxY = maxComponent(abs(Vec3(p0.y, p1.y, p2.y)));
    const float deltaZ = gamma(3) * maxZ;
    const float deltaX = gamma(5) * (maxX + maxZ);
    const float deltaY = gamma(5) * (maxY + maxZ);
    const float deltaE = 2 * (gamma(2) * maxX * maxY + deltaY * maxX + deltaX * maxY);
    const float maxE = maxComponent(abs(Vec3(e0, e1, e2)));
    const float deltaT =
        3 * (gamma(3) * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) * std::abs(invDet);
    if (t <= deltaT) return false;

    hit.t = t;
    hit.p = b0 * v_[0] + b1 * v_[1] + b2 * v_[2];
    hit.pError = gamma(7) * (abs(b0 * v_[0]) + abs(b1 * v_[1]) + abs(b2 * v_[2]));
    hit.ng = geometricNormal_;
    hit.ns = geometricNormal_;
    if (n_) {
        const Vec3 ns = b0 * (*n_)[0] + b1 * (*n_)[1] + b2 * (*n_)[2];
        if (lengthSquared(ns) > 0)
            hit.ns = dot(ns, geometricNormal_) < 0 ? -normalize(ns) : normalize(ns);
    }
    hit.uv = b0 * uv_[0] + b1 * uv_[1] + b2 * uv_[2];
    hit.shape = this;
    return true;
}

}  // namespace lancer
