#pragma once

#include <array>
#include <cstdint>

#include "math/Color.h"
#include "math/Ray.h"
#include "radiosity/Element.h"
#include "radiosity/Patch.h"
#include "scene/LightSampler.h"

namespace lancer {

class RadiositySolution;
class Scene;

// The light that reaches a diffuse surface through one glossy reflection (the `specular`
// Blinn-Phong lobe): what a solution of diffuse transport alone leaves out (a glossy floor sends
// a lamp's light up to the ceiling). Estimated at a point by cosine-distributed rays; where one
// meets a glossy surface, that surface's reflection towards the point is estimated from one
// sample of the emitters (picked as the path tracer picks them) through the lobe's f, with a
// shadow ray, and one direction drawn from each glossy lobe, which finds the diffuse light of the
// surface it meets in a solution (kd / pi times its irradiance) and the emitters' light: the two
// techniques weighed by the power heuristic where both find an emitter, so that a sharp lobe's
// rare, very bright emitter samples do not show as blotches.
class GlossyTransport {
public:
    explicit GlossyTransport(const Scene& scene);

    // The irradiance on each side of the element at its surface point (none on a side `wanted`
    // leaves out), from `solution`'s diffuse light and the emitters, through one glossy
    // reflection, from `samples` rays. `seed` places them; rayCount grows by the rays traced.
    std::array<Color, 2> at(const Element& element, const std::array<bool, 2>& wanted,
                            const RadiositySolution& solution, int samples, std::uint64_t seed,
                            std::uint64_t& rayCount) const;

private:
    // What the first surface along the ray reflects back along it through its glossy lobes
    // (radiance), with the sample numbers that `seed` gives.
    Color glossyRadiance(const Ray& ray, const RadiositySolution& solution, std::uint64_t seed,
                         std::uint64_t& rayCount) const;

    const Scene& scene_;
    LightSampler emitters_;
    float offset_;  // how far rays start off the element's surface point
};

}  // namespace lancer
