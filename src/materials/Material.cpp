#include "materials/Material.h"

#include <cmath>

#include "geometry/Hit.h"
#include "materials/Texture.h"

namespace lancer {

namespace {

// The cosine between a bent normal and the viewer: just in front of the horizon, so that the
// mirror direction of wo stays in front of the surface too (a normal on the horizon exactly would
// reflect wo straight through it).
constexpr float kBentNormalCosine = 0.01f;

}  // namespace

Vec3 Material::shadingNormal(const Hit& hit, const Vec3& wo) const {
    if (!shadingNormalMap_) return hit.ns;
    const Vec3 n = shadingNormalMap_->normal(hit);
    // The viewer's side of the surface: the shading happens with n there turned towards it.
    const float side = dot(wo, hit.ng) < 0 ? -1.0f : 1.0f;
    if (side * dot(n, wo) >= kBentNormalCosine) return n;
    const Vec3 acrossView = n - dot(n, wo) * wo;
    if (!(lengthSquared(acrossView) > 0)) return hit.ns;  // facing straight away: no way to bend
    return normalize(std::sqrt(1 - kBentNormalCosine * kBentNormalCosine) * normalize(acrossView) +
                     side * kBentNormalCosine * wo);
}

bool Material::readsFootprint() const {
    return texturesReadFootprint_ || (shadingNormalMap_ && shadingNormalMap_->readsFootprint()) ||
           (opacity_ && opacity_->readsFootprint());
}

bool Material::isCutAway(const Hit& hit) const {
    return opacity_ && opacity_->evaluate(hit).average() < 0.5f;
}

}  // namespace lancer
