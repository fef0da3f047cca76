#pragma once

#include <array>
#include <optional>

#include "materials/BlinnPhongLobe.h"
#include "materials/BsdfSample.h"
#include "materials/DielectricLobe.h"
#include "materials/LambertianLobe.h"
#include "materials/MirrorLobe.h"
#include "math/Frame.h"

namespace lancer {

class Material;
struct Hit;

// How a material scatters light at one hit point, for the path tracer: a Lambertian lobe of
// albedo kd, a normalized Blinn-Phong lobe from ks and shininess, a mirror kr and a smooth
// dielectric kt / ior. Energy conservation: when kd + ks + kr + kt exceeds 1 in some channel,
// all four weights are divided by the largest channel sum, so that no light is created. One lobe
// is sampled, chosen in proportion to its (scaled) weight averaged over the channels.
//
// Directions are in world space, unit length and point away from the surface. The lobes live in
// the frame of the shading normal (turned to the front side); light that would cross the
// geometric surface the wrong way (a reflection lobe reaching below the true surface because of
// a smooth-shading normal) is cut.
class Bsdf {
public:
    Bsdf(const Material& material, const Hit& hit);

    // The sum of the non-delta lobes (delta lobes give 0).
    Color f(const Vec3& wo, const Vec3& wi) const;
    // The density with which sample() returns wi through a non-delta lobe.
    float pdf(const Vec3& wo, const Vec3& wi) const;
    // A direction from one lobe chosen by uLobe, sampled with u. For a non-delta lobe, f and pdf
    // are those of the whole BSDF (the one-sample mixture); for a delta lobe, its own weight
    // and its selection probability.
    std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const;

    // Whether some lobe can be evaluated for a given pair of directions (light sampling is then
    // worthwhile).
    bool hasNonDeltaLobe() const;
    // The shading normal on the front side.
    const Vec3& shadingNormal() const { return frame_.n; }

private:
    // Whether wo and wi lie on the sides of the geometric surface that a reflection needs.
    bool reflectsGeometrically(const Vec3& wo, const Vec3& wi) const {
        return dot(wo, ng_) * dot(wi, ng_) > 0;
    }

    static constexpr int kLobeCount = 4;

    Frame frame_;
    Vec3 ng_;
    LambertianLobe lambertian_;
    BlinnPhongLobe blinnPhong_;
    MirrorLobe mirror_;
    DielectricLobe dielectric_;
    std::array<const BsdfLobe*, kLobeCount> lobes_;
    std::array<float, kLobeCount> probabilities_{};  // of choosing each lobe; 0 for absent ones
};

}  // namespace lancer
