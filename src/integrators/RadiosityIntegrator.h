#pragma once

#include <memory>
#include <optional>

#include "integrators/LightSampler.h"
#include "integrators/WhittedIntegrator.h"
#include "radiosity/RadiositySolution.h"

namespace lancer {

// The second pass of radiosity: eye rays traced as in Whitted (emission seen directly, mirror
// reflection and refraction followed), but at a diffuse surface the light it reflects comes from
// the radiosity solution, interpolated smoothly over the element under the hit: the diffuse
// lobes' albedo / pi times the irradiance. The glossy lobes (the normalized Blinn-Phong lobe)
// reflect what one direction per pixel sample drawn from each finds, traced as the rough lobes'
// are: the solution on the surfaces it meets, emitters, area lights, mirrors, the environment.
// Point-like lights, which no ray meets, add their highlights through the lobes' f. The lights'
// diffuse light is in the solution already, and there is no ambient term, so no light is
// counted twice. Where the solution has no element (a plane beyond the clipped part), the
// diffuse light is the lights' direct light alone.
// With a final gather of N rays (the classic two-pass method), the irradiance at an eye ray's
// diffuse hit is not interpolated but computed there: N samples of the emitters (lights and
// emissive surfaces, as the path tracer picks them) with shadow rays, plus what N
// cosine-distributed rays find the surfaces they hit reflect, from the solution at those hits.
class RadiosityIntegrator final : public WhittedIntegrator {
public:
    RadiosityIntegrator(const Scene& scene, int maxDepth,
                        std::shared_ptr<const RadiositySolution> solution, int finalGather = 0);
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
    // The irradiance on the side n faces (towards wo) from the solution, or from the lights alone
    // where it has no element.
    Color solutionIrradiance(const Hit& hit, const Vec3& n, const Vec3& wo, Sampler& sampler,
                             std::uint64_t& rayCount) const;
    // The final gather's irradiance on the side n faces of the surface whose geometric normal on
    // that side is ng.
    Color gatheredIrradiance(const Hit& hit, const Vec3& n, const Vec3& ng, Sampler& sampler,
                             std::uint64_t& rayCount) const;
    // The emitters' part of it.
    Color emittersIrradiance(const Hit& hit, const Vec3& n, Sampler& sampler,
                             std::uint64_t& rayCount) const;
    // The light the first surface along `ray` sends back: its diffuse reflection from the
    // solution, what its glossy lobes reflect (followed up to kGlossyBouncesGathered times), and
    // its emission, but that of an emitter emittersIrradiance samples when the ray is a gather
    // ray (glossyBounces 0).
    Color gatherRadiance(const Ray& ray, int glossyBounces, Sampler& sampler,
                         std::uint64_t& rayCount) const;

    static constexpr int kGlossyBouncesGathered = 2;

    std::shared_ptr<const RadiositySolution> solution_;
    int finalGather_;
    std::optional<LightSampler> emitters_;  // with a final gather only
};

}  // namespace lancer
