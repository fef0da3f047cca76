#include "materials/Bsdf.h"

#include <algorithm>
#include <cmath>

#include "geometry/Hit.h"
#include "materials/BlinnPhongLobe.h"
#include "materials/DielectricLobe.h"
#include "materials/LambertianLobe.h"
#include "materials/Material.h"
#include "materials/MirrorLobe.h"

namespace lancer {

Bsdf::Bsdf(const Material& material, const Hit& hit) : frame_(Frame::fromZ(hit.ns)), ng_(hit.ng) {
    add<LambertianLobe>(material.diffuse->evaluate(hit));
    add<BlinnPhongLobe>(material.specular, material.shininess);
    add<MirrorLobe>(material.reflection);
    add<DielectricLobe>(material.transmission, material.ior);
    weighLobes();
}

void Bsdf::weighLobes() {
    Color sum;
    for (std::size_t i = 0; i < lobeCount_; ++i)
        sum += lobes_[i]->weight();
    const float largest = sum.maxComponent();
    if (largest > 1)
        for (std::size_t i = 0; i < lobeCount_; ++i)
            lobes_[i]->scaleWeight(1 / largest);
    float total = 0;
    for (std::size_t i = 0; i < lobeCount_; ++i) {
        probabilities_[i] = std::max(0.0f, lobes_[i]->weight().average());
        total += probabilities_[i];
    }
    for (float& p : probabilities_)
        p = total > 0 ? p / total : 0;
}

bool Bsdf::hasNonDeltaLobe() const {
    for (std::size_t i = 0; i < lobeCount_; ++i)
        if (probabilities_[i] > 0 && !lobes_[i]->isDelta()) return true;
    return false;
}

Color Bsdf::f(const Vec3& wo, const Vec3& wi) const {
    if (!reflectsGeometrically(wo, wi)) return Color(0);
    const Vec3 woLocal = frame_.toLocal(wo), wiLocal = frame_.toLocal(wi);
    Color sum;
    for (std::size_t i = 0; i < lobeCount_; ++i)
        if (probabilities_[i] > 0 && !lobes_[i]->isDelta()) sum += lobes_[i]->f(woLocal, wiLocal);
    return sum;
}

float Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const Vec3 woLocal = frame_.toLocal(wo), wiLocal = frame_.toLocal(wi);
    float sum = 0;
    for (std::size_t i = 0; i < lobeCount_; ++i)
        if (probabilities_[i] > 0 && !lobes_[i]->isDelta())
            sum += probabilities_[i] * lobes_[i]->pdf(woLocal, wiLocal);
    return sum;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, float uLobe, const Vec2& u) const {
    // The lobe whose share of [0, 1) holds uLobe.
    std::size_t chosen = lobeCount_;
    float start = 0;
    for (std::size_t i = 0; i < lobeCount_; ++i) {
        if (probabilities_[i] == 0) continue;
        chosen = i;
        if (uLobe < start + probabilities_[i]) break;
        start += probabilities_[i];
    }
    if (chosen == lobeCount_) return std::nullopt;  // a black material
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
