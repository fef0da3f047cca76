#pragma once

#include <algorithm>
#include <cmath>

#include "math/Float.h"
#include "math/Vec2.h"
#include "math/Vec3.h"

namespace lancer {

// The isotropic GGX (Trowbridge-Reitz) distribution of microfacet normals of roughness alpha > 0,
// in the local shading frame (z the macro normal), with Smith's masking function, as Walter et
// al. 2007 and Heitz 2014/2018 write them (and Mitsuba's MicrofacetDistribution with ggx):
//
//     D(m) = alpha^2 / (pi cos^4 theta_m (alpha^2 + tan^2 theta_m)^2)
//     Lambda(w) = (sqrt(1 + alpha^2 tan^2 theta_w) - 1) / 2,  G1(w, m) = 1 / (1 + Lambda(w))
//
// G1 is 0 where w sees the back of the microfacet m (w.m and w.z of different signs).
class GgxDistribution {
public:
    explicit GgxDistribution(float alpha) : alpha_(alpha) {}

    float alpha() const { return alpha_; }

    // D(m) for m on the upper side (0 below).
    float density(const Vec3& m) const {
        if (m.z <= 0) return 0;
        const float a2 = alpha_ * alpha_;
        // (x^2 + y^2) / alpha^2 + z^2 = cos^2 theta_m (tan^2 theta_m + alpha^2) / alpha^2.
        const float t = (m.x * m.x + m.y * m.y) / a2 + m.z * m.z;
        return 1 / (kPi * a2 * t * t);
    }

    float smithG1(const Vec3& w, const Vec3& m) const {
        if (dot(w, m) * w.z <= 0) return 0;
        const float cos2 = w.z * w.z;
        const float tan2 = std::max(0.0f, 1 - cos2) / cos2;
        return 2 / (1 + std::sqrt(1 + alpha_ * alpha_ * tan2));
    }

    // Smith's separable masking-shadowing: G1(wo, m) G1(wi, m).
    float smithG(const Vec3& wo, const Vec3& wi, const Vec3& m) const {
        return smithG1(wo, m) * smithG1(wi, m);
    }

    // The density of the normals visible from wo (wo.z > 0), D_wo(m) = G1(wo, m) max(0, wo.m)
    // D(m) / wo.z, which sampleVisible draws from.
    float visibleDensity(const Vec3& wo, const Vec3& m) const {
        const float woDotM = dot(wo, m);
        if (woDotM <= 0) return 0;
        return smithG1(wo, m) * woDotM * density(m) / wo.z;
    }

    // A normal from the visible normals of wo (wo.z > 0), from u in [0,1)^2: Heitz 2018, "Sampling
    // the GGX Distribution of Visible Normals" (the view stretched to the hemisphere configuration
    // of alpha 1, a point on the projected half disk, the normal unstretched).
    Vec3 sampleVisible(const Vec3& wo, const Vec2& u) const {
        const Vec3 vh = normalize(Vec3(alpha_ * wo.x, alpha_ * wo.y, wo.z));
        const float lengthSq = vh.x * vh.x + vh.y * vh.y;
        const Vec3 t1 = lengthSq > 0 ? Vec3(-vh.y, vh.x, 0) / std::sqrt(lengthSq) : Vec3(1, 0, 0);
        const Vec3 t2 = cross(vh, t1);
        const float r = std::sqrt(u.x), phi = 2 * kPi * u.y;
        const float p1 = r * std::cos(phi);
        const float s = (1 + vh.z) / 2;
        const float p2 = (1 - s) * std::sqrt(std::max(0.0f, 1 - p1 * p1)) + s * r * std::sin(phi);
        const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1 - p1 * p1 - p2 * p2)) * vh;
        return normalize(Vec3(alpha_ * nh.x, alpha_ * nh.y, std::max(1e-6f, nh.z)));
    }

private:
    float alpha_;
};

}  // namespace lancer
