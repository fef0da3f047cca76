#pragma once

#include <array>
#include <cstdint>

#include "math/Color.h"
#include "math/Vec3.h"
#include "radiosity/Element.h"
#include "radiosity/Patch.h"

namespace lancer {

class Scene;

// Form factors from a receiving element to a shooting patch, by the exact point-to-polygon
// formula (Lambert's contour integral) for the unoccluded part and rays cast through the scene's
// BVH for visibility (the approach of Wallace, Elmquist and Haines 1989, with the analytic
// formula where they summed discs): F = F_exact * (the share of rays from the element to points
// spread over the patch that get through, each weighed by their disc form factor). Rays through
// transmissive surfaces keep their transmission, as Whitted shadow rays do; mirrors and other
// surfaces block.
class FormFactor {
public:
    explicit FormFactor(const Scene& scene);

    // The form factor from a differential area at p with unit normal n to the triangle, without
    // occlusion: only the part of the triangle in front of p's tangent plane counts.
    static double pointToTriangle(const Vec3d& p, const Vec3d& n,
                                  const std::array<Vec3, 3>& triangle);

    // The same, for a point p on the side `triangleSide` of the triangle's plane (of unit
    // normal triangleNormal) only: 0 on the other side.
    static double pointToSideOfTriangle(const Vec3d& p, const Vec3d& n,
                                        const std::array<Vec3, 3>& triangle,
                                        const Vec3& triangleNormal, Side triangleSide);

    // Either of the above where the triangle is near p, and where it is far (beyond
    // kFarField times its longest edge, whose square is given) the kernel
    // cos(theta_p) cos(theta_t) / (pi d^2) integrated over the triangle by the three-point rule,
    // without the exact formula's arctangents: within 0.5% at that distance, where the kernel at
    // the centroid times the area was 2-3% high (about (r / d)^2 for a disc of radius r seen
    // head-on), and a closed room's form factors added up to 1% more than 1.
    static constexpr double kFarField = 2;
    static double pointToSideOfTriangleApprox(const Vec3d& p, const Vec3d& n,
                                              const std::array<Vec3, 3>& triangle,
                                              const Vec3& triangleNormal, Side triangleSide,
                                              double area, double longestEdgeSquared);

    // F from the side `receiverSide` of the element to the side `shooterSide` of a triangle of the
    // patch (one of its elements, or the patch's own corners), visibility included (per colour
    // channel, through transmissive surfaces) from `rays` rays to points of the triangle that
    // derive from `seed`. rayCount grows by the rays traced.
    Color elementToTriangle(const Element& receiver, Side receiverSide,
                            const std::array<Vec3, 3>& triangle, const Patch& shooter,
                            Side shooterSide, int rays, std::uint64_t seed,
                            std::uint64_t& rayCount) const;

    // The share (per colour channel) of `rays` rays that get through from points of the
    // receiver's side `receiverSide` to points of the side `shooterSide` of a triangle of the
    // patch `shooter`: from points spread uniformly over the receiver (from its surface point,
    // when it is curved: its own surface would block the chords' points) to stratified points of
    // the triangle, each ray weighed by the form factor of the piece of the triangle it stands for,
    // cos cos / (pi d^2 + area / rays). Rays to points behind the receiver are not counted; 0
    // when none is left.
    Color areaVisibility(const Element& receiver, const std::array<Vec3, 3>& receiverCorners,
                         bool receiverCurved, Side receiverSide,
                         const std::array<Vec3, 3>& triangle, const Patch& shooter,
                         Side shooterSide, int rays, std::uint64_t seed,
                         std::uint64_t& rayCount) const;

private:
    // The visibility of both: from `receiver`'s surface point, or from points spread over its
    // corners' triangle when they are given.
    Color visibility(const Element& receiver, const std::array<Vec3, 3>* receiverCorners,
                     const Vec3& n, const std::array<Vec3, 3>& triangle, const Patch& shooter,
                     Side shooterSide, int rays, std::uint64_t seed, std::uint64_t& rayCount) const;

    const Scene& scene_;
};

}  // namespace lancer
