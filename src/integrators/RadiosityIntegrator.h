#pragma once

#include <memory>

#include "integrators/WhittedIntegrator.h"
#include "radiosity/RadiositySolution.h"

namespace lancer {

// The second pass of radiosity: eye rays traced as in Whitted (emission seen directly, mirror
// reflection and refraction followed), but at a diffuse surface the light it reflects comes from
// the radiosity solution, interpolated smoothly over the element under the hit: the diffuse
// lobes' albedo / pi times the irradiance. Lights add only their highlights (the physical f of
// the lobes neither diffuse nor delta, such as the normalized Blinn-Phong lobe): their diffuse
// light is in the solution already, and there is no ambient term, so no light is counted twice.
// Where the solution has no element (a plane beyond the clipped part), the diffuse light is the
// lights' direct light alone.
class RadiosityIntegrator final : public WhittedIntegrator {
public:
    RadiosityIntegrator(const Scene& scene, int maxDepth,
                        std::shared_ptr<const RadiositySolution> solution);
    // With the solution the setup gives (by default, solved for the scene); null when stopped.
    static std::unique_ptr<Integrator> create(const Scene& scene, const IntegratorSetup& setup);

    const RadiositySolution& solution() const { return *solution_; }

protected:
    Color localShading(const Hit& hit, const Bsdf& bsdf, const Vec3& wo, bool front,
                       Sampler& sampler, std::uint64_t& rayCount) const override;

private:
    Color highlights(const Hit& hit, const Bsdf& bsdf, const Vec3& n, const Vec3& wo,
                     Sampler& sampler, std::uint64_t& rayCount) const;

    std::shared_ptr<const RadiositySolution> solution_;
};

}  // namespace lancer
