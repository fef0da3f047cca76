#pragma once

#include <optional>

#include "materials/BsdfSample.h"
#include "math/Vec2.h"

namespace lancer {

// One scattering lobe of a BSDF, in the local shading frame: z is the shading normal on the
// surface's outer (front) side, directions are unit vectors pointing away from the surface.
class BsdfLobe {
public:
    virtual ~BsdfLobe() = default;

    // A delta lobe (mirror, smooth glass) scatters into single directions: f() and pdf() are 0
    // and only sample() finds them.
    virtual bool isDelta() const = 0;
    virtual Color f(const Vec3& wo, const Vec3& wi) const = 0;
    virtual float pdf(const Vec3& wo, const Vec3& wi) const = 0;
    // A direction for wo from u in [0,1)^2, or none when the lobe has nothing to give.
    virtual std::optional<BsdfSample> sample(const Vec3& wo, const Vec2& u) const = 0;
};

}  // namespace lancer
