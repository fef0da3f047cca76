#include "materials/DielectricLobe.h"

#include <cmath>

#include "materials/Optics.h"

namespace lancer {

SpecularSplit DielectricLobe::specularSplit(float cosThetaO, bool outside) const {
    const float eta = outside ? ior_ : 1 / ior_;
    const float F = fresnelDielectric(cosThetaO, eta);
    return {weight() * F, weight() * (1 - F), eta};
}

std::optional<BsdfSample> DielectricLobe::sample(const Vec3& wo, float, const Vec2& u) const {
    if (wo.z == 0) return std::nullopt;
    const bool outside = wo.z > 0;
    // eta: index beyond the boundary over index on wo's side.
    const float eta = outside ? ior_ : 1 / ior_;
    const float cosThetaO = std::abs(wo.z);
    const float F = fresnelDielectric(cosThetaO, eta);
    BsdfSample s;
    s.isDelta = true;
    if (u.x < F) {
        s.wi = {-wo.x, -wo.y, wo.z};
        s.f = weight() * (F / cosThetaO);
        s.pdf = F;
        return s;
    }
    const Vec3 n(0, 0, outside ? 1.0f : -1.0f);
    const std::optional<Vec3> refracted = refract(wo, n, eta);
    if (!refracted) return std::nullopt;  // F = 1 there, so u.x < F always: never reached
    s.wi = normalize(*refracted);
    s.etaSquared = eta * eta;
    s.f = weight() * ((1 - F) / (std::abs(s.wi.z) * s.etaSquared));
    s.pdf = 1 - F;
    return s;
}

}  // namespace lancer
