#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "math/Color.h"
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

// The complex index of refraction eta + i k of a conductor, per channel, relative to the medium
// the light arrives from.
struct ConductorIor {
    Color eta;
    Color k;
};

// Fraction of unpolarised light reflected by a smooth conductor of index eta + i k, at the cosine
// cosThetaI (>= 0) from the normal: the exact average of the s and p reflectances (as pbrt-v3's
// FrConductor and Mitsuba's fresnel_conductor), written with a^2 + b^2 = |eta^2 - sin^2| so that
// nothing is complex. ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2) at normal incidence, 1 at grazing.
inline float fresnelConductor(float cosThetaI, float eta, float k) {
    const float cos2 = cosThetaI * cosThetaI, sin2 = 1 - cos2;
    const float t0 = eta * eta - k * k - sin2;
    const float a2PlusB2 = std::sqrt(t0 * t0 + 4 * eta * eta * k * k);
    const float a = std::sqrt(std::max(0.0f, (a2PlusB2 + t0) / 2));
    const float t1 = a2PlusB2 + cos2, t2 = 2 * cosThetaI * a;
    if (!(t1 + t2 > 0)) return 1;  // grazing on an index-matched conductor: the limit
    const float perpendicular = (t1 - t2) / (t1 + t2);
    const float t3 = a2PlusB2 * cos2 + sin2 * sin2, t4 = t2 * sin2;
    const float parallel = perpendicular * (t3 - t4) / (t3 + t4);
    return (perpendicular + parallel) / 2;
}

inline Color fresnelConductor(float cosThetaI, const ConductorIor& ior) {
    return {fresnelConductor(cosThetaI, ior.eta.r, ior.k.r),
            fresnelConductor(cosThetaI, ior.eta.g, ior.k.g),
            fresnelConductor(cosThetaI, ior.eta.b, ior.k.b)};
}

// A conductor that reflects `normalReflectance` (each channel in [0, 1]) at normal incidence, for
// materials given by their colour (glTF's metals): eta = 1 and k = 2 sqrt(F0 / (1 - F0)), which
// solves ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2) = F0. Of the one-parameter choices it follows
// Schlick's curve, which glTF's metals are defined by, closer than k = 0 does for metals' F0 of
// 0.5 and more (the mean |difference| weighted by cos theta: 0.006 against 0.038 at F0 = 0.5,
// 0.016 against 0.026 at 0.9; k = 0 dips far below it towards grazing). F0 is held below 1,
// which no finite index reaches: k at most 200.
inline ConductorIor conductorReflecting(const Color& normalReflectance) {
    const auto k = [](float f0) {
        const float clamped = std::clamp(f0, 0.0f, 0.9999f);
        return 2 * std::sqrt(clamped / (1 - clamped));
    };
    return {Color(1),
            Color(k(normalReflectance.r), k(normalReflectance.g), k(normalReflectance.b))};
}

}  // namespace lancer
