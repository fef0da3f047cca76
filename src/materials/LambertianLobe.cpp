#include "materials/LambertianLobe.h"

#include <cmath>

#include "sampling/Sampling.h"

namespace lancer {

Color LambertianLobe::f(const Vec3& wo, const Vec3& wi) const {
    if (wo.z * wi.z <= 0) return Color(0);
    return weight() * (1 / kPi);
}

float LambertianLobe::pdf(const Vec3& wo, const Vec3& wi) const {
    if (wo.z * wi.z <= 0) return 0;
    return std::abs(wi.z) / kPi;
}

std::optional<BsdfSample> LambertianLobe::sample(const Vec3& wo, float, const Vec2& u) const {
    if (wo.z == 0) return std::nullopt;
    Vec3 wi = sampleCosineHemisphere(u);
    if (wo.z < 0) wi.z = -wi.z;
    BsdfSample s;
    s.wi = wi;
    s.f = f(wo, wi);
    s.pdf = pdf(wo, wi);
    if (s.pdf == 0) return std::nullopt;
    return s;
}

}  // namespace lancer
