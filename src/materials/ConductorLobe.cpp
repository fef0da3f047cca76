#include "materials/ConductorLobe.h"

#include <cmath>

namespace lancer {

std::optional<BsdfSample> ConductorLobe::sample(const Vec3& wo, float, const Vec2&) const {
    if (wo.z == 0) return std::nullopt;
    const float cosThetaO = std::abs(wo.z);
    BsdfSample s;
    s.wi = {-wo.x, -wo.y, wo.z};
    s.f = weight() * fresnelConductor(cosThetaO, ior_) / cosThetaO;
    s.pdf = 1;
    s.isDelta = true;
    return s;
}

}  // namespace lancer
