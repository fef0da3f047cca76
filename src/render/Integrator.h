#pragma once

#include <cstdint>

#include "math/Color.h"
#include "math/Ray.h"
#include "math/RayCone.h"

namespace lancer {

class Sampler;
class Scene;

// Computes the radiance arriving along a camera ray. An integrator is shared by all render
// threads: radiance() must not modify it.
class Integrator {
public:
    virtual ~Integrator() = default;

    // The radiance arriving along a camera ray of unit direction. footprint is the cone of a
    // sample's share of the pixel, for texture filtering. rayCount is incremented for every ray
    // traced (the camera ray included).
    virtual Color radiance(const Ray& ray, const RayCone& footprint, Sampler& sampler,
                           std::uint64_t& rayCount) const = 0;
};

}  // namespace lancer
