#pragma once

#include <cmath>
#include <optional>

#include "math/Vec3.h"

namespace lancer {

// cos^2 of the transmitted angle, 1 - sin^2(theta_i) / eta^2, written as
// (eta^2 - 1 + cos^2(theta_i)) / eta^2: at grazing incidence 1 - cos^2 rounds to exactly 1, which
// would turn an index-matched boundary (eta = 1) into a total internal reflector. Not positive
// under total internal reflection.
inline float cos2Transmitted(float cosThetaI, float eta) {
    return (eta * eta - 1 + cosThetaI * cosThetaI) / (eta * eta);
}

// Fraction of light reflected by a smooth dielectric boundary, for unpolarised light.
// cosThetaI: cosine between the incident direction and the normal on the incident side (>= 0);
// eta: index on the far side over index on the incident side. Returns 1 under total internal
// reflection.
inline float fresnelDielectric(float cosThetaI, float eta) {
    const float cos2ThetaT = cos2Transmitted(cosThetaI, eta);
    if (cos2ThetaT <= 0) return 1;
    const float cosThetaT = std::sqrt(cos2ThetaT);
    const float parallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
    const float perpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
    return (parallel * parallel + perpendicular * perpendicular) / 2;
}

// Snell's law: the direction transmitted through a boundary, for wi pointing away from the
// surface on the incident side, n the unit normal on that side, eta as in fresnelDielectric.
// No value under total internal reflection.
inline std::optional<Vec3> refract(const Vec3& wi, const Vec3& n, float eta) {
    const float cosThetaI = dot(wi, n);
    const float cos2ThetaT = cos2Transmitted(cosThetaI, eta);
    if (cos2ThetaT <= 0) return std::nullopt;
    const float cosThetaT = std::sqrt(cos2ThetaT);
    return -wi / eta + (cosThetaI / eta - cosThetaT) * n;
}

}  // namespace lancer
