#include "integrators/RadiosityIntegrator.h"

#include <bit>
#include <cmath>

#include "integrators/IntegratorRegistry.h"
#include "lights/Light.h"
#include "materials/Bsdf.h"
#include "materials/Material.h"
#include "radiosity/LightIrradiance.h"
#include "radiosity/RadiositySolver.h"
#include "sampling/Sampler.h"
#include "sampling/Sampling.h"
#include "sampling/StratifiedPoint.h"
#include "scene/Scene.h"
#include "scene/ShadowRays.h"

namespace lancer {

RadiosityIntegrator::RadiosityIntegrator(const Scene& scene, int maxDepth,
                                         std::shared_ptr<const RadiositySolution> solution,
                                         int finalGather, int directSamples)
    : WhittedIntegrator(scene, maxDepth, Bsdf::Weights::EnergyConserving),
      solution_(std::move(solution)),
      finalGather_(finalGather),
      directSamples_(directSamples),
      emitters_(scene) {}

std::unique_ptr<Integrator> RadiosityIntegrator::create(const Scene& scene,
                                                        const IntegratorSetup& setup) {
    RadiositySolver solver(scene);
    std::optional<RadiositySolution> solution =
        setup.radiositySolution ? setup.radiositySolution(solver) : solver.solve();
    if (!solution) return nullptr;
    return std::make_unique<RadiosityIntegrator>(
        scene, scene.settings().maxDepth,
        std::make_shared<const RadiositySolution>(std::move(*solution)),
        scene.settings().radiosity.finalGather, scene.settings().radiosity.directSamples);
}

Color RadiosityIntegrator::localShading(const Hit& hit, const Bsdf& bsdf, const Vec3& wo,
                                        bool front, Sampler& sampler,
                                        std::uint64_t& rayCount) const {
    const Vec3 n = bsdf.shadingNormal(front);
    Color L;
    const Color kd = bsdf.diffuseReflectance();
    if (!kd.isBlack()) {
        Color E;
        if (finalGather_ > 0)
            E = gatheredIrradiance(hit, n, front ? hit.ng : -hit.ng, sampler, rayCount);
        else if (directSamples_ > 0)
            E = solution_->irradiance(hit.p, hit.ng, wo, RadiositySolution::Part::Indirect)
                    .value_or(Color(0)) +
                directIrradiance(hit, n, directSamples_, sampler, rayCount);
        else
            E = solutionIrradiance(hit, n, wo, sampler, rayCount);
        L += kd * E / kPi;
    }
    if (bsdf.hasGlossyLobe()) L += highlights(hit, bsdf, n, wo, rayCount);
    if (bsdf.glossyLobeCount() > 0) L += glossyReflection(hit, bsdf, n, wo, sampler, rayCount);
    return L;
}

Color RadiosityIntegrator::solutionIrradiance(const Hit& hit, const Vec3& n, const Vec3& wo,
                                              Sampler& sampler, std::uint64_t& rayCount) const {
    if (const std::optional<Color> E = solution_->irradiance(hit.p, hit.ng, wo)) return *E;
    // Stratified light samples, placed by this sample's own numbers.
    constexpr int kLightSamples = 16;
    const Vec2 u = sampler.get2D();
    return LightIrradiance::at(
        scene(), hit.p, hit.ng, n, kLightSamples,
        hashValues(std::bit_cast<std::uint32_t>(u.x), std::bit_cast<std::uint32_t>(u.y)), rayCount);
}

namespace {

// The seed of a stratified pattern, shifted by `offset` (both from the sampler): every point of
// the pattern is then uniform over the square, and the pattern differs at every hit.
std::uint64_t patternSeed(const Vec2& offset) {
    return hashValues(std::bit_cast<std::uint32_t>(offset.x),
                      std::bit_cast<std::uint32_t>(offset.y));
}

}  // namespace

Color RadiosityIntegrator::gatheredIrradiance(const Hit& hit, const Vec3& n, const Vec3& ng,
                                              Sampler& sampler, std::uint64_t& rayCount) const {
    Vec3 a, b;
    coordinateSystem(n, a, b);
    const Vec2 offset = sampler.get2D();
    const std::uint64_t seed = patternSeed(offset);
    Color sum;
    for (int k = 0; k < finalGather_; ++k) {
        const Vec3 local =
            sampleCosineHemisphere(shifted(stratifiedPoint(k, finalGather_, seed), offset));
        const Vec3 wi = local.x * a + local.y * b + local.z * n;
        // A direction under the geometric surface (the shading normal leans) sees nothing.
        if (dot(wi, ng) <= 0) continue;
        sum += gatherRadiance(hit.spawnRay(wi), 0, sampler, rayCount);
    }
    // Cosine-distributed directions: E = pi x the mean radiance.
    return directIrradiance(hit, n, finalGather_, sampler, rayCount) +
           sum * (kPi / static_cast<float>(finalGather_));
}

Color RadiosityIntegrator::directIrradiance(const Hit& hit, const Vec3& n, int count,
                                            Sampler& sampler, std::uint64_t& rayCount) const {
    return sampledEmitters(hit, n, count, true, sampler, rayCount,
                           [](const Vec3&) { return Color(1); });
}

template <typename Response>
Color RadiosityIntegrator::sampledEmitters(const Hit& hit, const Vec3& n, int count,
                                           bool pointLightsToo, Sampler& sampler,
                                           std::uint64_t& rayCount,
                                           const Response& response) const {
    const Vec2 offset = sampler.get2D();
    const std::uint64_t seed = patternSeed(offset);
    Color sum;
    for (int k = 0; k < count; ++k) {
        // The light picked independently of the point's cell, so that each light's points are
        // still uniform over it.
        const auto choice =
            emitters_.choose(static_cast<float>(hashValues(seed, k, 1) >> 40) * 0x1p-24f);
        if (!choice) break;
        // Leaving a point light's picks out leaves the estimate of the others' light unbiased.
        if (!pointLightsToo && choice->light->isDelta()) continue;
        const LightSample ls =
            choice->light->sample(hit.p, shifted(stratifiedPoint(k, count, seed), offset));
        const float cosTheta = dot(n, ls.wi);
        if (!(cosTheta > 0) || ls.irradiance.isBlack() || !ls.irradiance.isFinite()) continue;
        const Color r = response(ls.wi);
        if (r.isBlack()) continue;
        sum += r * cosTheta * ls.irradiance *
               ShadowRays::transmittance(scene(), hit, ls, rayCount) / choice->probability;
    }
    return sum / static_cast<float>(count);
}

Color RadiosityIntegrator::glossyReflection(const Hit& hit, const Bsdf& bsdf, const Vec3& n,
                                            const Vec3& wo, Sampler& sampler,
                                            std::uint64_t& rayCount) const {
    Color L = sampledEmitters(hit, n, kHighlightSamples, false, sampler, rayCount,
                              [&](const Vec3& wi) { return bsdf.glossyF(wo, wi, false); });
    for (std::size_t lobe = 0; lobe < bsdf.glossyLobeCount(); ++lobe)
        if (const std::optional<SpecularRay> r = bsdf.glossyRay(lobe, wo, sampler.get2D()))
            L += r->weight * gatherRadiance(hit.spawnRay(r->direction), 0, sampler, rayCount);
    return L;
}

Color RadiosityIntegrator::gatherRadiance(const Ray& ray, int glossyBounces, Sampler& sampler,
                                          std::uint64_t& rayCount) const {
    ++rayCount;
    const std::optional<Hit> found = scene().intersect(ray, kInfinity);
    // The emitters, the environment among them, are sampled where the ray comes from; a plain
    // background lights nothing (it is not in the solution either).
    if (!found) return Color(0);
    const Hit& hit = *found;
    const Vec3 wo = -ray.direction;
    const bool front = hit.frontFace(ray);
    Color L;
    if (!emitters_.lightAt(hit) && hit.seesEmittingSide(ray)) L += hit.material->emission(hit);
    const Bsdf bsdf(*hit.material, hit, wo, Bsdf::Weights::EnergyConserving);
    const Color kd = bsdf.diffuseReflectance();
    const Vec3 n = bsdf.shadingNormal(front);
    if (!kd.isBlack()) L += kd * solutionIrradiance(hit, n, wo, sampler, rayCount) / kPi;
    // The solution carries no glossy reflection: a glossy surface's is estimated here as at an
    // eye ray's hit, by an emitter sample and a direction drawn from each lobe, so that what a
    // glossy floor reflects of the lamps and the room reaches the surfaces gathering it.
    if (bsdf.glossyLobeCount() > 0) {
        L += sampledEmitters(hit, n, 1, true, sampler, rayCount,
                             [&](const Vec3& wi) { return bsdf.glossyF(wo, wi, false); });
        if (glossyBounces < kGlossyBouncesGathered)
            for (std::size_t lobe = 0; lobe < bsdf.glossyLobeCount(); ++lobe)
                if (const std::optional<SpecularRay> r = bsdf.glossyRay(lobe, wo, sampler.get2D()))
                    L += r->weight * gatherRadiance(hit.spawnRay(r->direction), glossyBounces + 1,
                                                    sampler, rayCount);
    }
    return L;
}

Color RadiosityIntegrator::highlights(const Hit& hit, const Bsdf& bsdf, const Vec3& n,
                                      const Vec3& wo, std::uint64_t& rayCount) const {
    // Only point-like lights: glossyReflection and the rough lobes' traced rays find the rest.
    Color L;
    for (const auto& light : scene().lights()) {
        if (!light->isDelta()) continue;
        const LightSample ls = light->sample(hit.p, Vec2(0.5f, 0.5f));
        const float cosTheta = dot(n, ls.wi);
        if (!(cosTheta > 0) || ls.irradiance.isBlack() || !ls.irradiance.isFinite()) continue;
        const Color f = bsdf.glossyF(wo, ls.wi, true);
        if (f.isBlack()) continue;
        L += cosTheta * f * ls.irradiance * ShadowRays::transmittance(scene(), hit, ls, rayCount);
    }
    return L;
}

}  // namespace lancer
