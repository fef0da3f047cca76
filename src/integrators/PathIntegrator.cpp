#include "integrators/PathIntegrator.h"

#include <algorithm>
#include <cmath>

#include "lights/EnvironmentLight.h"
#include "materials/Bsdf.h"
#include "materials/Material.h"
#include "sampling/Sampler.h"
#include "sampling/Sampling.h"
#include "scene/Scene.h"
#include "scene/ShadowRays.h"

namespace lancer {

PathIntegrator::PathIntegrator(const Scene& scene, int maxDepth)
    : scene_(scene), maxDepth_(maxDepth), lights_(scene) {}

std::unique_ptr<Integrator> PathIntegrator::create(const Scene& scene, const IntegratorSetup&) {
    return std::make_unique<PathIntegrator>(scene, scene.settings().maxDepth);
}

Color PathIntegrator::sampleOneLight(const Hit& hit, const Bsdf& bsdf, const Vec3& wo,
                                     const LightSampler::Choice& choice, const Vec2& uLight,
                                     std::uint64_t& rayCount) const {
    const Light& light = *choice.light;
    const LightSample ls = light.sampleBesideBsdf(hit.p, uLight);
    const bool delta = light.isDelta();
    if (ls.irradiance.isBlack() || (!delta && !(ls.pdf > 0))) return Color(0);
    const Color f = bsdf.f(wo, ls.wi);
    if (f.isBlack()) return Color(0);
    // Shadow rays stop at the first surface: light through glass arrives by refracted paths.
    if (!ShadowRays::unoccluded(scene_, hit, ls, rayCount)) return Color(0);
    const float weight =
        delta ? 1 : powerHeuristic(choice.probability * ls.pdf, bsdf.pdf(wo, ls.wi));
    const float cosine = std::abs(dot(ls.wi, bsdf.shadingNormal()));
    return f * ls.irradiance * (cosine * weight / choice.probability);
}

Color PathIntegrator::radiance(const Ray& cameraRay, const RayCone&, Sampler& sampler,
                               std::uint64_t& rayCount) const {
    Color L, throughput(1);
    // etaScale: the product of the eta^2 of the refractions so far, which Russian roulette
    // takes out of the throughput (it measures the energy carried, not the radiance scale).
    float etaScale = 1;
    bool afterDelta = false;  // the last bounce was a delta lobe's
    float lastBsdfPdf = 0;    // the density of the last bounce's direction
    Vec3 lastVertex;
    Ray ray = cameraRay;
    for (int bounces = 0;; ++bounces) {
        ++rayCount;
        const std::optional<Hit> found = scene_.intersect(ray, kInfinity);
        if (!found) {
            const EnvironmentLight* environment = scene_.environment();
            if (!environment) {
                L += throughput * scene_.background();
                break;
            }
            const EnvironmentLight::Arrival seen = environment->arrivalBesideBsdf(ray.direction);
            float weight = 1;
            // A BSDF ray escaping to an environment that light sampling could also have found.
            if (bounces > 0 && !afterDelta)
                weight = powerHeuristic(lastBsdfPdf, lights_.probability(environment) * seen.pdf);
            L += throughput * seen.radiance * weight;
            break;
        }
        const Hit& hit = *found;
        const Material& material = *hit.material;
        const Vec3 wo = -normalize(ray.direction);
        if (!material.emission().isBlack() && hit.seesEmittingSide(ray)) {
            float weight = 1;
            // A BSDF ray hitting a light that light sampling could also have found.
            if (bounces > 0 && !afterDelta) {
                if (const Light* light = lights_.lightAt(hit)) {
                    const float lightPdf =
                        lights_.probability(light) * light->pdfBesideBsdf(lastVertex, -wo, hit);
                    weight = powerHeuristic(lastBsdfPdf, lightPdf);
                }
            }
            L += throughput * material.emission(hit) * weight;
        }
        if (bounces >= maxDepth_) break;

        const Bsdf bsdf(material, hit, wo);
        const bool samplesLight = bsdf.hasNonDeltaLobe();
        // The same requests at every bounce, so that each keeps its dimensions and a pixel's
        // samples stay stratified bounce by bounce; those this bounce does not read are passed
        // over, not drawn (the others get the same numbers either way).
        const auto value = [&](bool read) {
            if (read) return sampler.get1D();
            sampler.skip();
            return 0.0f;
        };
        const auto point = [&](bool read) {
            if (read) return sampler.get2D();
            sampler.skip();
            return Vec2();
        };
        const float uLightChoice = value(samplesLight && lights_.choiceReadsU());
        const std::optional<LightSampler::Choice> light =
            samplesLight ? lights_.choose(uLightChoice) : std::nullopt;
        // A delta light's sample does not read its point.
        const Vec2 uLight = point(light && !light->light->isDelta());
        const float uLobe = value(bsdf.readsLobeChoice());
        const Vec2 uBsdf = sampler.get2D();
        if (light) L += throughput * sampleOneLight(hit, bsdf, wo, *light, uLight, rayCount);

        const auto s = bsdf.sample(wo, uLobe, uBsdf);
        if (!s || s->f.isBlack() || !(s->pdf > 0)) break;
        throughput *= s->f * (std::abs(dot(s->wi, bsdf.shadingNormal())) / s->pdf);
        etaScale *= s->etaSquared;
        afterDelta = s->isDelta;
        lastBsdfPdf = s->pdf;
        lastVertex = hit.p;
        ray = hit.spawnRay(s->wi);

        const float survival = bounces + 1 >= kRouletteDepth
                                   ? std::min(1.0f, (throughput * etaScale).maxComponent())
                                   : 1.0f;
        const float uRoulette = value(survival < 1);
        if (survival < 1) {
            const float q = std::max(0.05f, 1 - survival);
            if (uRoulette < q) break;
            throughput /= 1 - q;
        }
    }
    return L;
}

}  // namespace lancer
