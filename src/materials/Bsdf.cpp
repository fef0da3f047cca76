#include "materials/Bsdf.h"

#include <algorithm>
#include <cmath>

#include "geometry/Hit.h"
#include "materials/Material.h"
#include "materials/Optics.h"
#include "math/Float.h"

namespace lancer {

Bsdf::Bsdf(const Material& material, const Hit& hit, const Vec3& wo, Weights weights)
    : frame_(Frame::fromZ(material.shadingNormal(hit, wo))), ng_(hit.ng) {
    material.addLobes(hit, *this);
    weighLobes(weights);
}

void Bsdf::weighLobes(Weights weights) {
    if (weights == Weights::AsGiven) return;  // Whitted: nothing is sampled
    Color sum;
    for (std::size_t i = 0; i < lobeCount_; ++i)
        sum += lobes_[i]->weight();
    const float largest = sum.maxComponent();
    if (largest > 1) {
        for (std::size_t i = 0; i < lobeCount_; ++i)
            lobes_[i]->scaleWeight(1 / largest);
        diffuseWeight_ *= 1 / largest;
    }
    float total = 0;
    for (std::size_t i = 0; i < lobeCount_; ++i) {
        probabilities_[i] = std::max(0.0f, lobes_[i]->weight().average());
        total += probabilities_[i];
    }
    for (float& p : probabilities_)
        p = total > 0 ? p / total : 0;
}

bool Bsdf::readsLobeChoice() const {
    const BsdfLobe* only = nullptr;
    for (std::size_t i = 0; i < lobeCount_; ++i) {
        if (probabilities_[i] == 0) continue;  // never chosen
        if (only) return true;
        only = lobes_[i];
    }
    return only && only->readsChoice();
}

bool Bsdf::hasNonDeltaLobe() const {
    return lobeCount_ > deltaCount_;
}

Color Bsdf::f(const Vec3& wo, const Vec3& wi) const {
    const Vec3 woLocal = frame_.toLocal(wo), wiLocal = frame_.toLocal(wi);
    if (!sidesAgree(woLocal, wiLocal, reflectsGeometrically(wo, wi))) return Color(0);
    Color sum;
    for (std::size_t i = 0; i < lobeCount_; ++i)
        if (!lobes_[i]->isDelta()) sum += lobes_[i]->f(woLocal, wiLocal);
    return sum;
}

float Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const Vec3 woLocal = frame_.toLocal(wo), wiLocal = frame_.toLocal(wi);
    float sum = 0;
    for (std::size_t i = 0; i < lobeCount_; ++i)
        if (!lobes_[i]->isDelta()) sum += probabilities_[i] * lobes_[i]->pdf(woLocal, wiLocal);
    return sum;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, float uLobe, const Vec2& u) const {
    // The lobe whose share of [0, 1) holds uLobe.
    std::size_t chosen = lobeCount_;
    float start = 0, chosenStart = 0;
    for (std::size_t i = 0; i < lobeCount_; ++i) {
        if (probabilities_[i] == 0) continue;
        chosen = i;
        chosenStart = start;
        if (uLobe < start + probabilities_[i]) break;
        start += probabilities_[i];
    }
    if (chosen == lobeCount_) return std::nullopt;  // a black material
    // Where uLobe falls in the chosen lobe's share, a fresh number for the lobe's own choice.
    const float uChoice =
        std::clamp((uLobe - chosenStart) / probabilities_[chosen], 0.0f, kOneMinusEpsilon);
    const Vec3 woLocal = frame_.toLocal(wo);
    std::optional<BsdfSample> s = lobes_[chosen]->sample(woLocal, uChoice, u);
    if (!s) return std::nullopt;
    const Vec3 wiLocal = s->wi;
    s->wi = normalize(frame_.toWorld(s->wi));
    if (s->isDelta) {
        s->pdf *= probabilities_[chosen];
        return s;
    }
    if (!sidesAgree(woLocal, wiLocal, reflectsGeometrically(wo, s->wi))) return std::nullopt;
    // The one-sample mixture's f and pdf are the lobe's own when it is the only lobe.
    if (lobeCount_ > 1) {
        s->f = f(wo, s->wi);
        s->pdf = pdf(wo, s->wi);
    }
    if (!(s->pdf > 0)) return std::nullopt;
    return s;
}

Color Bsdf::localResponse(const Vec3& wo, const Vec3& wi, bool front, bool deltaLight) const {
    const Vec3 n = shadingNormal(front);
    const float cosThetaL = dot(n, wi);
    if (cosThetaL <= 0) return Color(0);
    // kd cos(theta_L) for the diffuse lobes, then the glossy ones, which need the half vector.
    Color sum = diffuseWeight_ * cosThetaL;
    if (deltaLight && roughCount_ > 0) sum += roughF(wo, wi) * cosThetaL;
    if (glossyCount_ == 0) return sum;
    const float cosThetaH = dot(n, normalize(wi + wo));
    for (std::size_t i = 0; i < glossyCount_; ++i)
        sum += glossyLobes_[i]->localResponse(cosThetaL, cosThetaH);
    return sum;
}

Color Bsdf::roughF(const Vec3& wo, const Vec3& wi) const {
    const Vec3 woLocal = frame_.toLocal(wo), wiLocal = frame_.toLocal(wi);
    Color sum;
    for (std::size_t i = 0; i < roughCount_; ++i)
        sum += roughLobes_[i]->f(woLocal, wiLocal);
    return sum;
}

std::size_t Bsdf::tracedRays(std::size_t index, const Vec3& wo, const Vec2& u,
                             std::array<SpecularRay, 2>& rays) const {
    const Vec3 woLocal = frame_.toLocal(wo);
    const std::size_t drawn = roughLobes_[index]->tracedRays(woLocal, u, rays);
    std::size_t count = 0;
    for (std::size_t i = 0; i < drawn; ++i) {
        const Vec3 wi = normalize(frame_.toWorld(rays[i].direction));
        if (sidesAgree(woLocal, rays[i].direction, reflectsGeometrically(wo, wi)))
            rays[count++] = {wi, rays[i].weight};
    }
    return count;
}

std::optional<SpecularRay> Bsdf::glossyRay(std::size_t index, const Vec3& wo, const Vec2& u) const {
    const Vec3 woLocal = frame_.toLocal(wo);
    const std::optional<BsdfSample> s = glossyLobes_[index]->sample(woLocal, 0, u);
    if (!s) return std::nullopt;
    const Vec3 wi = normalize(frame_.toWorld(s->wi));
    if (!sidesAgree(woLocal, s->wi, reflectsGeometrically(wo, wi))) return std::nullopt;
    return SpecularRay{wi, s->f * (std::abs(s->wi.z) / s->pdf)};
}

std::size_t Bsdf::specularRays(const Vec3& wo, bool front,
                               std::array<SpecularRay, kMaxSpecularRays>& rays) const {
    if (deltaCount_ == 0) return 0;
    const Vec3 n = shadingNormal(front);
    const float cosThetaO = std::min(1.0f, std::abs(dot(wo, n)));
    // Refractions from rays[1] on, behind the reflection's place.
    Color reflected;
    std::size_t count = 1;
    for (std::size_t i = 0; i < deltaCount_; ++i) {
        const SpecularSplit split = deltaLobes_[i]->specularSplit(cosThetaO, front);
        reflected += split.reflected;
        if (split.refracted.isBlack()) continue;
        if (const std::optional<Vec3> refracted = refract(wo, n, split.eta))
            rays[count++] = {normalize(*refracted), split.refracted};
    }
    if (!reflected.isBlack()) {
        rays[0] = {reflect(wo, n), reflected};
        return count;
    }
    std::copy(rays.begin() + 1, rays.begin() + static_cast<std::ptrdiff_t>(count), rays.begin());
    return count - 1;
}

Bsdf::LobeValue Bsdf::glossyLobeValue(std::size_t index, const Vec3& wo, const Vec3& wi) const {
    const Vec3 woLocal = frame_.toLocal(wo), wiLocal = frame_.toLocal(wi);
    return {glossyLobes_[index]->f(woLocal, wiLocal), glossyLobes_[index]->pdf(woLocal, wiLocal)};
}

Color Bsdf::glossyF(const Vec3& wo, const Vec3& wi, bool deltaLight) const {
    const Vec3 woLocal = frame_.toLocal(wo), wiLocal = frame_.toLocal(wi);
    Color sum;
    for (std::size_t i = 0; i < glossyCount_; ++i)
        sum += glossyLobes_[i]->f(woLocal, wiLocal);
    if (deltaLight && roughCount_ > 0) sum += roughF(wo, wi);
    return sum;
}

}  // namespace lancer
