#include "integrators/RadiosityIntegrator.h"

#include <bit>
#include <cmath>

#include "integrators/IntegratorRegistry.h"
#include "lights/Light.h"
#include "materials/Bsdf.h"
#include "radiosity/LightIrradiance.h"
#include "radiosity/RadiositySolver.h"
#include "sampling/Sampler.h"
#include "sampling/Sampling.h"
#include "scene/Scene.h"
#include "scene/ShadowRays.h"

namespace lancer {

RadiosityIntegrator::RadiosityIntegrator(const Scene& scene, int maxDepth,
                                         std::shared_ptr<const RadiositySolution> solution)
    : WhittedIntegrator(scene, maxDepth), solution_(std::move(solution)) {}

std::unique_ptr<Integrator> RadiosityIntegrator::create(const Scene& scene,
                                                        const IntegratorSetup& setup) {
    RadiositySolver solver(scene);
    std::optional<RadiositySolution> solution =
        setup.radiositySolution ? setup.radiositySolution(solver) : solver.solve();
    if (!solution) return nullptr;
    return std::make_unique<RadiosityIntegrator>(
        scene, scene.settings().maxDepth,
        std::make_shared<const RadiositySolution>(std::move(*solution)));
}

Color RadiosityIntegrator::localShading(const Hit& hit, const Bsdf& bsdf, const Vec3& wo,
                                        bool front, Sampler& sampler,
                                        std::uint64_t& rayCount) const {
    const Vec3 n = bsdf.shadingNormal(front);
    Color L;
    const Color kd = bsdf.diffuseReflectance();
    if (!kd.isBlack()) {
        std::optional<Color> E = solution_->irradiance(hit.p, hit.ng, wo);
        if (!E) {
            // Stratified light samples, placed by this sample's own numbers.
            constexpr int kLightSamples = 16;
            const Vec2 u = sampler.get2D();
            E = LightIrradiance::at(
                scene(), hit.p, hit.ng, n, kLightSamples,
                hashValues(std::bit_cast<std::uint32_t>(u.x), std::bit_cast<std::uint32_t>(u.y)),
                rayCount);
        }
        L += kd * *E / kPi;
    }
    if (bsdf.hasGlossyLobe()) L += highlights(hit, bsdf, n, wo, sampler, rayCount);
    return L;
}

Color RadiosityIntegrator::highlights(const Hit& hit, const Bsdf& bsdf, const Vec3& n,
                                      const Vec3& wo, Sampler& sampler,
                                      std::uint64_t& rayCount) const {
    Color L;
    for (const auto& light : scene().lights()) {
        const int count = light->isDelta() ? 1 : light->shadowSamples();
        Color sum;
        for (int k = 0; k < count; ++k) {
            const Vec2 u = light->isDelta() ? Vec2(0.5f, 0.5f) : sampler.get2D();
            const LightSample ls = light->sample(hit.p, u);
            const float cosTheta = dot(n, ls.wi);
            if (!(cosTheta > 0) || ls.irradiance.isBlack() || !ls.irradiance.isFinite()) continue;
            const Color f = bsdf.glossyF(wo, ls.wi, light->isDelta());
            if (f.isBlack()) continue;
            sum += cosTheta * f * ls.irradiance *
                   ShadowRays::transmittance(scene(), hit, ls, rayCount);
        }
        L += sum / static_cast<float>(count);
    }
    return L;
}

}  // namespace lancer
