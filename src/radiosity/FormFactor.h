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
// formula instead of their disc approximation): F = F_exact * (fraction of rays from the element
// to points spread over the patch that get through). Rays through transmissive surfaces keep
// their transmission, as Whitted shadow rays do; mirrors and other surfaces block.
class FormFactor {
public:
    explicit FormFactor(const Scene& scene);

    // The form factor from a differential area at p with unit normal n to the triangle, without
    // occlusion: only the part of the triangle in front of p's tangent plane counts.
    static double pointToTriangle(const Vec3d& p, const Vec3d& n,
                                  const std::array<Vec3, 3>& triangle);

    // F from the side `receiverSide` of the element to the side `shooterSide` of a triangle of the
    // patch (one of its elements, or the patch's own corners), visibility included (per colour
    // channel, through transmissive surfaces) from `rays` rays to points of the triangle that
    // derive from `seed`. rayCount grows by the rays traced.
    Color elementToTriangle(const Element& receiver, Side receiverSide,
                            const std::array<Vec3, 3>& triangle, const Patch& shooter,
                            Side shooterSide, int rays, std::uint64_t seed,
                            std::uint64_t& rayCount) const;

private:
    const Scene& scene_;
};

}  // namespace lancer
