#pragma once

#include <cstdint>

#include "math/Color.h"
#include "math/Vec3.h"

namespace lancer {

class Scene;

// The irradiance the scene's lights deliver to a surface point, shadows included: what radiosity
// starts from, and what the radiosity integrator falls back on where no element is.
class LightIrradiance {
public:
    // At p (with error bound on the surface of geometric normal ng), on the side n faces: one
    // sample of a delta light, `samples` stratified samples of the others (more if the light asks
    // for more).
    static Color at(const Scene& scene, const Vec3& p, const Vec3& ng, const Vec3& n, int samples,
                    std::uint64_t seed, std::uint64_t& rayCount);
};

}  // namespace lancer
