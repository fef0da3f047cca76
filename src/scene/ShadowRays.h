#pragma once

#include <cstdint>

#include "geometry/Hit.h"
#include "lights/Light.h"
#include "math/Color.h"

namespace lancer {

class Scene;

// Shadow rays from a surface point to a light sample: the one place that builds them (offset off
// the surface, stopping just short of a light with a position) and decides what blocks them.
class ShadowRays {
public:
    // Whether nothing at all lies between the point and the light sample (the path tracer's
    // test: light through glass reaches it by refracted paths instead).
    static bool unoccluded(const Scene& scene, const Hit& from, const LightSample& light,
                           std::uint64_t& rayCount);

    // The visibility V_l of the contract's shading: the product of the transmission of every
    // surface the shadow ray crosses on its way to the light (0 behind anything opaque, 1 behind
    // clear glass).
    static Color transmittance(const Scene& scene, const Hit& from, const LightSample& light,
                               std::uint64_t& rayCount);

private:
    static Ray towards(const Hit& from, const LightSample& light) {
        return light.atInfinity ? from.spawnRay(light.wi) : from.spawnRayTo(light.position);
    }
    static float reach(const LightSample& light) {
        return light.atInfinity ? kInfinity : 1 - kShadowEpsilon;
    }
};

}  // namespace lancer
