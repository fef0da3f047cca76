#pragma once

#include <memory>
#include <optional>

#include "scene/LightSampler.h"
#include "integrators/WhittedIntegrator.h"
#include "radiosity/RadiositySolution.h"

namespace lancer {

// The second pass of radiosity: eye rays traced as in Whitted (emission seen directly, mirror
// reflection and refraction followed), but at a diffuse surface the light it reflects comes from
// the radiosity solution, interpolated smoothly over the element under the hit: the diffuse
// lobes' albedo / pi times the irradiance. The glossy lobes (the normalized Blinn-Phong lobe)
// reflect the emitters (area lights, emissive surfaces, the environment) by light samples, and
// everything else along one direction per pixel sample drawn from each lobe, gathered as the
// final gather's rays are: the solution on the surfaces it meets, what further glossy surfaces
// reflect, the emitters no sample reaches. Point-like lights add the glossy and rough lobes'
// highlights through their f. The lights' diffuse light is in the solution already, and there is
// no ambient term, so no light is counted twice. Where the solution has no element (a plane
// beyond the clipped part), the diffuse light is the lights' direct light alone.
// With a final gather of N rays (the classic two-pass method), the irradiance at an eye ray's
// diffuse hit is not interpolated but computed there: N samples of the emitters (lights and
// emissive surfaces, as the path tracer picks them) with shadow rays, plus what N
// cosine-distributed rays find the surfaces they hit reflect, from the solution at those hits.
// With N direct samples (and no final gather), the irradiance at an eye ray's diffuse hit is the
// solution's indirect part, interpolated, plus the emitters' direct light computed there from N
// samples with shadow rays: shadows as sharp as the ray tracer's, where the solution's elements
// would spread them over their corners.
class RadiosityIntegrator final : public WhittedIntegrator {
public:
    RadiosityIntegrator(const Scene& scene, int maxDepth,
                        std::shared_ptr<const RadiositySolution> solution, int finalGather = 0,
                        int directSamples = 0);
    // With the solution the setup gives (by default, solved for the scene); null when stopped.
    static std::unique_ptr<Integrator> create(const Scene& scene, const IntegratorSetup& setup);

    const RadiositySolution& solution() const { return *solution_; }

protected:
    Color localShading(const Hit& hit, const Bsdf& bsdf, const Vec3& wo, bool front,
                       Sampler& sampler, std::uint64_t& rayCount) const override;

private:
    // The glossy and rough lobes' highlights of the point-like lights.
    Color highlights(const Hit& hit, const Bsdf& bsdf, const Vec3& n, const Vec3& wo,
                     std::uint64_t& rayCount) const;
    // What the glossy lobes reflect of everything but the point-like lights.
    Color glossyReflection(const Hit& hit, const Bsdf& bsdf, const Vec3& n, const Vec3& wo,
                           Sampler& sampler, std::uint64_t& rayCount) const;
    // The irradiance on the side n faces (towards wo) from the solution, or from the lights alone
    // where it has no element.
    Color solutionIrradiance(const Hit& hit, const Vec3& n, const Vec3& wo, Sampler& sampler,
                             std::uint64_t& rayCount) const;
    // The irradiance from `count` samples of the emitters (lights too) with shadow rays.
    Color directIrradiance(const Hit& hit, const Vec3& n, int count, Sampler& sampler,
                           std::uint64_t& rayCount) const;
    // The final gather's irradiance on the side n faces of the surface whose geometric normal on
    // that side is ng.
    Color gatheredIrradiance(const Hit& hit, const Vec3& n, const Vec3& ng, Sampler& sampler,
                             std::uint64_t& rayCount) const;
    // The mean over `count` samples of the emitters (picked as the path tracer picks them,
    // point-like lights too or not) of response(wi) cos irradiance / probability, with shadow
    // rays: the irradiance for a response of 1.
    template <typename Response>
    Color sampledEmitters(const Hit& hit, const Vec3& n, int count, bool pointLightsToo,
                          Sampler& sampler, std::uint64_t& rayCount,
                          const Response& response) const;
    // The light the first surface along `ray` sends back but the sampled emitters' (which the
    // point the ray leaves samples): its diffuse reflection from the solution, its glossy
    // reflection (an emitter sample and, up to kGlossyBouncesGathered glossy reflections deep, one
    // direction drawn from each lobe, gathered again), the emission of an emitter no sample
    // reaches (an emissive infinite plane).
    Color gatherRadiance(const Ray& ray, int glossyBounces, Sampler& sampler,
                         std::uint64_t& rayCount) const;

    static constexpr int kGlossyBouncesGathered = 2;
    // Emitter samples per pixel sample for a glossy surface's highlights (as many as Whitted's
    // area lights take by default).
    static constexpr int kHighlightSamples = 16;

    std::shared_ptr<const RadiositySolution> solution_;
    int finalGather_;
    int directSamples_;
    LightSampler emitters_;
};

}  // namespace lancer
