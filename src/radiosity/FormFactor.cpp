#include "radiosity/FormFactor.h"

#include <algorithm>
#include <cmath>

#include "lights/Light.h"
#include "radiosity/SurfaceProbe.h"
#include "radiosity/TriangleQuadrature.h"
#include "sampling/StratifiedPoint.h"
#include "scene/Scene.h"
#include "scene/ShadowRays.h"

namespace lancer {

namespace {

// A point of the triangle from one of the unit square, uniform over the triangle when the
// square's point is (the square's cells keep their areas).
Vec3 uniformPointOn(const std::array<Vec3, 3>& t, const Vec2& uv) {
    const float su = std::sqrt(uv.x);
    return (1 - su) * t[0] + su * (1 - uv.y) * t[1] + su * uv.y * t[2];
}

}  // namespace

FormFactor::FormFactor(const Scene& scene) : scene_(scene) {}

double FormFactor::pointToTriangle(const Vec3d& p, const Vec3d& n,
                                   const std::array<Vec3, 3>& triangle) {
    // The part of the triangle in front of p's tangent plane: the triangle, or a triangle or
    // quadrilateral cut from it (Sutherland-Hodgman against one plane, without allocating: this
    // runs for every element and shooter).
    std::array<Vec3d, 4> visible;
    std::size_t count = 0;
    std::array<double, 3> height;
    for (std::size_t k = 0; k < 3; ++k)
        height[k] = dot(n, Vec3d(triangle[k]) - p);
    if (height[0] <= 0 && height[1] <= 0 && height[2] <= 0) return 0;
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t next = (k + 1) % 3;
        if (height[k] >= 0) visible[count++] = Vec3d(triangle[k]);
        if ((height[k] >= 0) != (height[next] >= 0))
            visible[count++] =
                Vec3d(triangle[k]) + (height[k] / (height[k] - height[next])) *
                                         (Vec3d(triangle[next]) - Vec3d(triangle[k]));
    }
    // F = 1 / (2 pi) sum_k angle(R_k, R_k+1) n . normalize(R_k x R_k+1), R_k = v_k - p.
    double sum = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3d a = visible[k] - p, b = visible[(k + 1) % count] - p;
        const Vec3d c = cross(a, b);
        const double sine = length(c);
        if (!(sine > 0)) continue;  // an edge seen end-on subtends nothing
        sum += std::atan2(sine, dot(a, b)) * dot(n, c) / sine;
    }
    return std::abs(sum) / (2 * std::numbers::pi);
}

namespace {

// p's height over the triangle's plane when p is on the side `side` of it, farther from it than
// the rounding of float positions; 0 otherwise. A point within that of the plane (an element's
// corner or gather point on a coplanar neighbour) sees the triangle edge-on, whatever the
// rounding says, and its form factor is 0. Without the margin, the contour integral from a point
// a rounding error in front of a coplanar triangle whose outline it is in came out as 1 (the
// triangle filling the hemisphere): bright dots at the vertices of cornell-original's tall block.
double heightOnSide(const Vec3d& p, const std::array<Vec3, 3>& triangle, const Vec3& triangleNormal,
                    Side side) {
    const double height = dot(Vec3d(triangleNormal), p - Vec3d(triangle[0]));
    const double scale = std::max(maxComponent(abs(p)), maxComponent(abs(Vec3d(triangle[0]))));
    const double margin = 1e-5 * scale;  // about 100 float roundings of the coordinates
    const bool onSide = side == Side::Front ? height > margin : height < -margin;
    return onSide ? height : 0;
}

}  // namespace

double FormFactor::pointToSideOfTriangle(const Vec3d& p, const Vec3d& n,
                                         const std::array<Vec3, 3>& triangle,
                                         const Vec3& triangleNormal, Side triangleSide) {
    if (heightOnSide(p, triangle, triangleNormal, triangleSide) == 0) return 0;
    return pointToTriangle(p, n, triangle);
}

double FormFactor::pointToSideOfTriangleApprox(const Vec3d& p, const Vec3d& n,
                                               const std::array<Vec3, 3>& triangle,
                                               const Vec3& triangleNormal, Side triangleSide,
                                               double area, double longestEdgeSquared) {
    const Vec3d centroid = (Vec3d(triangle[0]) + Vec3d(triangle[1]) + Vec3d(triangle[2])) / 3.0;
    const Vec3d towards = centroid - p;
    const double d2 = dot(towards, towards);
    if (!(d2 > kFarField * kFarField * longestEdgeSquared))
        return pointToSideOfTriangle(p, n, triangle, triangleNormal, triangleSide);
    const double height = heightOnSide(p, triangle, triangleNormal, triangleSide);
    if (height == 0) return 0;
    // The kernel cos(theta_p) cos(theta_t) / (pi d^2) integrated over the triangle by the
    // three-point rule (exact for quadratics): at the centroid alone it is 2-3% high at this
    // distance, which made the form factors of a closed room add up to more than 1.
    const std::array<Vec3d, 3> points = triangleQuadraturePoints<double>(
        {Vec3d(triangle[0]), Vec3d(triangle[1]), Vec3d(triangle[2])});
    double sum = 0;
    for (const Vec3d& point : points) {
        const Vec3d q = point - p;
        const double cosP = dot(n, q), q2 = dot(q, q);
        // cos(theta_t) d = |height| to the plane, cos(theta_p) d = n . q.
        if (cosP > 0) sum += cosP / (q2 * q2);
    }
    return area * std::abs(height) * sum / (3 * std::numbers::pi);
}

Color FormFactor::elementToTriangle(const Element& receiver, Side receiverSide,
                                    const std::array<Vec3, 3>& triangle, const Patch& shooter,
                                    Side shooterSide, int rays, std::uint64_t seed,
                                    std::uint64_t& rayCount) const {
    const Vec3 n = receiverSide == Side::Front ? receiver.normal : -receiver.normal;
    const double unoccluded = pointToSideOfTriangle(Vec3d(receiver.centroid), Vec3d(n), triangle,
                                                    shooter.normal, shooterSide);
    if (!(unoccluded > 0)) return Color(0);
    return static_cast<float>(unoccluded) *
           visibility(receiver, nullptr, n, triangle, shooter, shooterSide, rays, seed, rayCount);
}

Color FormFactor::areaVisibility(const Element& receiver,
                                 const std::array<Vec3, 3>& receiverCorners, bool receiverCurved,
                                 Side receiverSide, const std::array<Vec3, 3>& triangle,
                                 const Patch& shooter, Side shooterSide, int rays,
                                 std::uint64_t seed, std::uint64_t& rayCount) const {
    const Vec3 n = receiverSide == Side::Front ? receiver.normal : -receiver.normal;
    return visibility(receiver, receiverCurved ? nullptr : &receiverCorners, n, triangle, shooter,
                      shooterSide, rays, seed, rayCount);
}

Color FormFactor::visibility(const Element& receiver, const std::array<Vec3, 3>* receiverCorners,
                             const Vec3& n, const std::array<Vec3, 3>& triangle,
                             const Patch& shooter, Side shooterSide, int rays, std::uint64_t seed,
                             std::uint64_t& rayCount) const {
    Hit from;
    from.p = receiver.surfacePoint;
    from.ng = receiver.surfaceNormal;
    Vec3 start = receiver.centroid;  // on the flat element, for the test of what is behind
    Color visible;
    float weights = 0;
    const float pieceArea = 0.5f *
                            length(cross(triangle[1] - triangle[0], triangle[2] - triangle[0])) /
                            static_cast<float>(rays);
    for (int k = 0; k < rays; ++k) {
        if (receiverCorners) {
            // Independent of the target's cell: pairing cell k with cell k would be biased.
            start = uniformPointOn(*receiverCorners, stratifiedPoint(0, 1, hashValues(seed, k, 1)));
            from.p = start;
        }
        from.pError = gamma(16) * abs(from.p);
        Vec3 target = uniformPointOn(triangle, stratifiedPoint(k, rays, seed));
        if (!(dot(n, target - start) > 0)) continue;  // behind the receiver
        // Off the source's surface towards the receiver: rounding must not let the ray meet that
        // surface just before the target. A target rounded behind a flat source's plane by an ulp
        // was met there at t = 0.9996 by rays grazing it from the next wall across a corner: a
        // quarter of the links between the elements along a room's edges lost a ray.
        const Vec3 towardsReceiver = shooterSide == Side::Front ? shooter.normal : -shooter.normal;
        if (shooter.curved)
            target = SurfaceProbe::onSurface(shooter, target) +
                     (1e-4f * std::sqrt(shooter.area)) * towardsReceiver;
        else
            target =
                offsetRayOrigin(target, gamma(16) * abs(target), towardsReceiver, towardsReceiver);
        LightSample towards;
        towards.position = target;
        const Vec3 d = target - from.p;
        towards.wi = normalize(d);
        // Each ray weighs as much as the form factor of the piece of the source it stands for
        // (Wallace et al.'s disc of area A / rays): the objects standing in a room hide mostly
        // what is seen near the horizon, where the kernel is small, and a plain share of blocked
        // rays took as much off for that as for the source's nearest part.
        // (The cosines' magnitudes: from a curved receiver's surface point, a ray to a point
        // in front of its flat element can leave a little behind the element's normal.)
        const float weight = std::abs(dot(n, towards.wi) * dot(shooter.normal, towards.wi)) /
                             (kPi * lengthSquared(d) + pieceArea);
        visible += weight * ShadowRays::transmittance(scene_, from, towards, rayCount);
        weights += weight;
    }
    if (!(weights > 0)) return Color(0);
    // Divided, not multiplied by the reciprocal: every ray through must give exactly 1, or the
    // link would count as partly occluded.
    return {visible.r / weights, visible.g / weights, visible.b / weights};
}

}  // namespace lancer
