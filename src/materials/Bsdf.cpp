#include "materials/Bsdf.h"

#include <algorithm>
#include <cmath>

#include "geometry/Hit.h"
#include "materials/Material.h"

namespace lancer {

namespace {

// The factor bringing kd + ks + kr + kt to at most 1 in every channel.
float energyScale(const Color& kd, const Color& ks, const Color& kr, const Color& kt) {
    const float largest = (kd + ks + kr + kt).maxComponent();
    return largest > 1 ? 1 / largest : 1;
}

}  // namespace

Bsdf::Bsdf(const Material& material, const Hit& hit)
    : frame_(Frame::fromZ(hit.ns)),
      ng_(hit.ng),
      lambertian_(Color(0)),
      blinnPhong_(Color(0), material.shininess),
      mirror_(Color(0)),
      dielectric_(Color(0), material.ior),
      lobes_{&lambertian_, &blinnPhong_, &mirror_, &dielectric_} {
    const Color kd = material.diffuse->evaluate(hit);
    const float scale =
        energyScale(kd, material.specular, material.reflection, material.transmission);
    const std::array<Color, kLobeCount> weights{kd * scale, material.specular * scale,
                                                material.reflection * scale,
                                                material.transmission * scale};
    lambertian_ = LambertianLobe(weights[0]);
    blinnPhong_ = BlinnPhongLobe(weights[1], material.shininess);
    mirror_ = MirrorLobe(weights[2]);
    dielectric_ = DielectricLobe(weights[3], material.ior);
    float total = 0;
    for (int i = 0; i < kLobeCount; ++i) {
        probabilities_[static_cast<std::size_t>(i)] =
            std::max(0.0f, weights[static_cast<std::size_t>(i)].average());
        total += probabilities_[static_cast<std::size_t>(i)];
    }
    for (float& p : probabilities_)
        p = total > 0 ? p / total : 0;
}

bool Bsdf::hasNonDeltaLobe() const {
    for (std::size_t i = 0; i < lobes_.size(); ++i)
        if (probabilities_[i] > 0 && !lobes_[i]->isDelta()) return true;
    return false;
}

Color Bsdf::f(const Vec3& wo, const Vec3& wi) const {
    if (!reflectsGeometrically(wo, wi)) return Color(0);
    const Vec3 woLocal = frame_.toLocal(wo), wiLocal = frame_.toLocal(wi);
    Color sum;
    for (std::size_t i = 0; i < lobes_.size(); ++i)
        if (probabilities_[i] > 0 && !lobes_[i]->isDelta()) sum += lobes_[i]->f(woLocal, wiLocal);
    return sum;
}

float Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const Vec3 woLocal = frame_.toLocal(wo), wiLocal = frame_.toLocal(wi);
    float sum = 0;
    for (std::size_t i = 0; i < lobes_.size(); ++i)
        if (probabilities_[i] > 0 && !lobes_[i]->isDelta())
            sum += probabilities_[i] * lobes_[i]->pdf(woLocal, wiLocal);
    return sum;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, float uLobe, const Vec2& u) const {
    // The lobe whose share of [0, 1) holds uLobe.
    std::size_t chosen = lobes_.size();
    float start = 0;
    for (std::size_t i = 0; i < lobes_.size(); ++i) {
        if (probabilities_[i] == 0) continue;
        chosen = i;
        if (uLobe < start + probabilities_[i]) break;
        start += probabilities_[i];
    }
    if (chosen == lobes_.size()) return std::nullopt;  // a black material
    const Vec3 woLocal = frame_.toLocal(wo);
    std::optional<BsdfSample> s = lobes_[chosen]->sample(woLocal, u);
    if (!s) return std::nullopt;
    s->wi = normalize(frame_.toWorld(s->wi));
    if (s->isDelta) {
        s->pdf *= probabilities_[chosen];
        return s;
    }
    if (!reflectsGeometrically(wo, s->wi)) return std::nullopt;
    s->f = f(wo, s->wi);
    s->pdf = pdf(wo, s->wi);
    if (!(s->pdf > 0)) return std::nullopt;
    return s;
}

}  // namespace lancer
