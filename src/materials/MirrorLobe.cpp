#include "materials/MirrorLobe.h"

#include <cmath>

namespace lancer {

std::optional<BsdfSample> MirrorLobe::sample(const Vec3& wo, float, const Vec2&) const {
    if (wo.z == 0) return std::nullopt;
    BsdfSample s;
    s.wi = {-wo.x, -wo.y, wo.z};
    s.f = weight() / std::abs(wo.z);
    s.pdf = 1;
    s.isDelta = true;
    return s;
}

}  // namespace lancer
