#pragma once

#include <cmath>
#include <optional>

#include "math/Vec3.h"

namespace lancer {

// Fraction of light reflected by a smooth dielectric boundary, for unpolarised light.
// cosThetaI: cosine between the incident direction and the normal on the incident side (>= 0);
// eta: index on the far side over index on the incident side. Returns 1 under total internal
// reflection.
inline float fresnelDielectric(float cosThetaI, float eta) {
    const float sin2ThetaI = std::max(0.0f, 1 - cosThetaI * cosThetaI);
    const float sin2ThetaT = sin2ThetaI / (eta * eta);
    if (sin2ThetaT >= 1) return 1;
    const float cosThetaT = std::sqrt(1 - sin2ThetaT);
    const float parallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
    const float perpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
    return (parallel * parallel + perpendicular * perpendicular) / 2;
}

// Snell's law: the direction transmitted through a boundary, for wi pointing away from the
// surface on the incident side, n the unit normal on that side, eta as in fresnelDielectric.
// No value under total internal reflection.
inline std::optional<Vec3> refract(const Vec3& wi, const Vec3& n, float eta) {
    const float cosThetaI = dot(wi, n);
    const float sin2ThetaT = std::max(0.0f, 1 - cosThetaI * cosThetaI) / (eta * eta);
    if (sin2ThetaT >= 1) return std::nullopt;
    const float cosThetaT = std::sqrt(1 - sin2ThetaT);
    return -wi / eta + (cosThetaI / eta - cosThetaT) * n;
}

}  // namespace lancer
