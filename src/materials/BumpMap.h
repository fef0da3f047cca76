#pragma once

#include <memory>

#include "materials/ShadingNormalMap.h"
#include "materials/Texture.h"

namespace lancer {

// A height map (its first channel, linear, scaled by `scale` scene units) that displaces the
// surface along the shading normal N: the normal of the displaced surface p + h(u, v) N, whose
// derivatives are dpdu + dh/du N and dpdv + dh/dv N (Blinn 1978; as pbrt's BumpMap, without the
// term of N's own change, small for small heights). The height's derivatives are central
// differences over half the pixel's uv footprint, or over a small fixed step without one.
class BumpMap final : public ShadingNormalMap {
public:
    BumpMap(std::shared_ptr<const Texture> heights, float scale);

    Vec3 normal(const Hit& hit) const override;
    // Its differences span the footprint.
    bool readsFootprint() const override { return true; }

private:
    float height(const Hit& hit, float u, float v) const;

    std::shared_ptr<const Texture> heights_;
    float scale_;
};

}  // namespace lancer
