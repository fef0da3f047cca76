#pragma once

#include <memory>

#include "render/Integrator.h"
#include "scene/LightSampler.h"

namespace lancer {

class Bsdf;
class Scene;
struct Hit;
struct IntegratorSetup;

// Unidirectional path tracing (pbrt's PathIntegrator): at every vertex one light, chosen in
// proportion to power, is sampled (next-event estimation) and one direction is drawn from the
// BSDF; emitters that the BSDF's rays hit are weighted against light sampling by multiple
// importance sampling (power heuristic), delta lights and delta lobes by neither. Paths scatter
// at most maxDepth times (0: emitted light only, 1: direct lighting); after kRouletteDepth
// bounces Russian roulette ends paths in proportion to their throughput, without bias.
class PathIntegrator final : public Integrator {
public:
    PathIntegrator(const Scene& scene, int maxDepth);
    static std::unique_ptr<Integrator> create(const Scene& scene, const IntegratorSetup& setup);

    Color radiance(const Ray& ray, const RayCone& footprint, Sampler& sampler,
                   std::uint64_t& rayCount) const override;

    static constexpr int kRouletteDepth = 3;

private:
    // Light from the chosen light sampled at the vertex, weighted against BSDF sampling.
    Color sampleOneLight(const Hit& hit, const Bsdf& bsdf, const Vec3& wo,
                         const LightSampler::Choice& choice, const Vec2& uLight,
                         std::uint64_t& rayCount) const;

    const Scene& scene_;
    int maxDepth_;
    LightSampler lights_;
};

}  // namespace lancer
