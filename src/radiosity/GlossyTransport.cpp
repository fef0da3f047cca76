#include "radiosity/GlossyTransport.h"

#include "geometry/Hit.h"
#include "lights/Light.h"
#include "materials/Bsdf.h"
#include "materials/Material.h"
#include "radiosity/RadiositySolution.h"
#include "sampling/Sampling.h"
#include "sampling/StratifiedPoint.h"
#include "scene/Scene.h"
#include "scene/ShadowRays.h"
#include "util/ParallelFor.h"

namespace lancer {

namespace {

// A number in [0, 1) from a hash.
float unit(std::uint64_t hash) {
    return static_cast<float>(hash >> 40) * 0x1p-24f;
}

// The vertices' samples, per element sample.
constexpr int kVertexSamplesFactor = 4;

}  // namespace

GlossyTransport::GlossyTransport(const Scene& scene, int samples)
    : scene_(scene), emitters_(scene), samples_(samples) {
    const Bounds3 bounds = scene.bounds();
    offset_ = bounds.isEmpty() ? 1e-4f : 1e-5f * length(bounds.diagonal());
}

std::vector<std::array<Color, 2>> GlossyTransport::atElements(
    const RadiosityMesh& mesh, const std::vector<std::uint32_t>& elements,
    const RadiositySolution& solution, int round, const std::atomic<bool>* cancel,
    std::uint64_t& rayCount) const {
    std::vector<std::array<Color, 2>> E(elements.size());
    rayCount +=
        parallelForCounting(elements.size(), 16, cancel, [&](std::size_t i, std::uint64_t& rays) {
            E[i] = at(mesh.elements[elements[i]], solution, samples_,
                      hashValues(elements[i], round, 0x6c6fu), rays);
        });
    return E;
}

std::array<Color, 2> GlossyTransport::atVertex(const Element& site, std::size_t vertex,
                                               const RadiositySolution& solution,
                                               std::uint64_t& rayCount) const {
    return at(site, solution, kVertexSamplesFactor * samples_, hashValues(vertex, 0x76u, 0x6c6fu),
              rayCount);
}

std::array<Color, 2> GlossyTransport::at(const Element& element, const RadiositySolution& solution,
                                         int samples, std::uint64_t seed,
                                         std::uint64_t& rayCount) const {
    std::array<Color, 2> E;
    if (!(element.reflectance.maxComponent() > 0)) return E;
    for (Side side : kBothSides) {
        const Vec3 n = element.surfaceSideNormal(side);
        Vec3 a, b;
        coordinateSystem(n, a, b);
        const std::uint64_t sideSeed = hashValues(seed, sideIndex(side));
        Color sum;
        for (int k = 0; k < samples; ++k) {
            const Vec3 local = sampleCosineHemisphere(stratifiedPoint(k, samples, sideSeed));
            const Vec3 direction = local.x * a + local.y * b + local.z * n;
            ++rayCount;
            sum += glossyRadiance({element.surfacePoint + offset_ * n, direction}, solution,
                                  hashValues(sideSeed, k), rayCount);
        }
        // Cosine-distributed directions: E = pi x the mean radiance.
        E[sideIndex(side)] = sum * (kPi / static_cast<float>(samples));
    }
    return E;
}

Color GlossyTransport::glossyRadiance(const Ray& ray, const RadiositySolution& solution,
                                      std::uint64_t seed, std::uint64_t& rayCount) const {
    const std::optional<Hit> found = scene_.intersect(ray, kInfinity);
    if (!found || !found->material->reflectsGlossily()) return Color(0);
    return reflectedGlossily(*found, -ray.direction, solution, seed, 1, rayCount);
}

Color GlossyTransport::reflectedGlossily(const Hit& hit, const Vec3& wo,
                                         const RadiositySolution& solution, std::uint64_t seed,
                                         int reflections, std::uint64_t& rayCount) const {
    const Bsdf bsdf(*hit.material, hit, wo, Bsdf::Weights::EnergyConserving);
    if (bsdf.glossyLobeCount() == 0) return Color(0);
    const Vec3 n = bsdf.shadingNormal(dot(wo, hit.ng) > 0);  // the side wo leaves from
    Color L;
    // An emitter sample, weighed against the lobes' own samples, which find the same emitters
    // (multiple importance sampling: a sharp lobe's samples find a lamp that its f would make a
    // rare and very bright light sample).
    if (const auto choice = emitters_.choose(unit(hashValues(seed, 1)))) {
        const Light& light = *choice->light;
        const LightSample ls =
            light.sample(hit.p, Vec2(unit(hashValues(seed, 2)), unit(hashValues(seed, 3))));
        const float cosTheta = dot(n, ls.wi);
        if (cosTheta > 0 && !ls.irradiance.isBlack() && ls.irradiance.isFinite() &&
            (light.isDelta() || ls.pdf > 0)) {
            Color f;
            if (light.isDelta())
                f = bsdf.glossyF(wo, ls.wi, true);
            else
                for (std::size_t lobe = 0; lobe < bsdf.glossyLobeCount(); ++lobe) {
                    const Bsdf::LobeValue v = bsdf.glossyLobeValue(lobe, wo, ls.wi);
                    f += v.f * powerHeuristic(choice->probability * ls.pdf, v.pdf);
                }
            if (!f.isBlack())
                L += f * cosTheta * ls.irradiance *
                     ShadowRays::transmittance(scene_, hit, ls, rayCount) / choice->probability;
        }
    }
    for (std::size_t lobe = 0; lobe < bsdf.glossyLobeCount(); ++lobe) {
        const Vec2 u(unit(hashValues(seed, 4, lobe)), unit(hashValues(seed, 5, lobe)));
        const std::optional<SpecularRay> r = bsdf.glossyRay(lobe, wo, u);
        if (!r) continue;
        ++rayCount;
        const Ray next = hit.spawnRay(r->direction);
        const std::optional<Hit> seen = scene_.intersect(next, kInfinity);
        if (!seen) continue;
        Color there;
        if (seen->seesEmittingSide(next)) {
            float weight = 1;
            if (const Light* light = emitters_.lightAt(*seen))
                weight = powerHeuristic(
                    bsdf.glossyLobeValue(lobe, wo, r->direction).pdf,
                    emitters_.probability(light) * light->pdf(hit.p, r->direction, *seen));
            there += seen->material->emission(*seen) * weight;
        }
        const Bsdf seenBsdf(*seen->material, *seen, -next.direction,
                            Bsdf::Weights::EnergyConserving);
        const Color kd = seenBsdf.diffuseReflectance();
        if (!kd.isBlack())
            if (const std::optional<Color> E =
                    solution.irradiance(seen->p, seen->ng, -next.direction))
                there += kd * *E / kPi;
        // A glossy surface seen through a glossy lobe (the lamp's highlight on a glossy floor,
        // seen in a glossy sphere): the solution holds none of what it reflects glossily.
        if (reflections < kLongestGlossyChain && seen->material->reflectsGlossily())
            there += reflectedGlossily(*seen, -next.direction, solution, hashValues(seed, 6, lobe),
                                       reflections + 1, rayCount);
        L += r->weight * there;
    }
    return L;
}

}  // namespace lancer
