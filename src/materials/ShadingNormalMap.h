#pragma once

#include "math/Vec3.h"

namespace lancer {

struct Hit;

// A map that perturbs the shading normal over a surface (a normal map or a bump map), held by a
// material and applied when the BSDF's frame is made, so that every integrator sees it.
class ShadingNormalMap {
public:
    virtual ~ShadingNormalMap() = default;
    // The perturbed unit normal at the hit, on the side of hit.ns (which it replaces).
    virtual Vec3 normal(const Hit& hit) const = 0;
    // Whether normal reads the hit's uv footprint (dudx...), which is then worth computing.
    virtual bool readsFootprint() const = 0;
};

}  // namespace lancer
