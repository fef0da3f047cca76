#pragma once

#include <memory>

#include "materials/ShadingNormalMap.h"
#include "materials/Texture.h"

namespace lancer {

// A tangent-space normal map (OpenGL convention: red along +u, green along +v, blue out of the
// surface), whose texels c are read as linear data: n_ts = 2 c - 1. The tangent frame is the
// scene format's: N the shading normal, T = normalize(dpdu - N (N.dpdu)), B = cross(N, T) turned
// to dpdv's side; the mapped normal is normalize(n_ts.x T + n_ts.y B + n_ts.z N).
class NormalMap final : public ShadingNormalMap {
public:
    explicit NormalMap(std::shared_ptr<const Texture> texels);

    Vec3 normal(const Hit& hit) const override;
    bool readsFootprint() const override;

private:
    std::shared_ptr<const Texture> texels_;
};

}  // namespace lancer
