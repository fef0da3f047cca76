#pragma once

#include <memory>

#include "materials/Bsdf.h"
#include "math/Color.h"
#include "render/Integrator.h"

namespace lancer {

class Scene;
struct IntegratorSetup;
struct Hit;

// Whitted ray tracing with the scene format's shading equation, from the BSDF's lobes: emission,
// ambient, the lobes' local responses to the lights with shadow rays, and the delta lobes'
// recursive reflection and refraction (weights split by the Fresnel term for transmissive
// materials) up to maxDepth bounces, and the rough lobes' traced rays. Subclasses may replace the
// local shading (ambient and direct lighting) and keep the rest (radiosity does), and weigh the
// lobes as the path tracer does instead of as given (radiosity's physical model is path's).
class WhittedIntegrator : public Integrator {
public:
    WhittedIntegrator(const Scene& scene, int maxDepth,
                      Bsdf::Weights weights = Bsdf::Weights::AsGiven);
    static std::unique_ptr<Integrator> create(const Scene& scene, const IntegratorSetup& setup);

    Color radiance(const Ray& ray, const RayCone& footprint, Sampler& sampler,
                   std::uint64_t& rayCount) const override;

protected:
    // The light a surface reflects towards wo besides emission, reflection and refraction:
    // ambient and the lobes' local responses to the lights. wo is on the front side of the
    // geometric surface or not.
    virtual Color localShading(const Hit& hit, const Bsdf& bsdf, const Vec3& wo, bool front,
                               Sampler& sampler, std::uint64_t& rayCount) const;

    const Scene& scene() const { return scene_; }

private:
    // A ray of the path from the camera, with what texture filtering needs to know of the path
    // (the distance travelled before this ray and the pixel's footprint along the path) and the
    // fraction of the ray's radiance that reaches the pixel (the product of the weights of the
    // rays before it).
    struct PathRay {
        Ray ray;
        float distance;
        RayCone footprint;
        Color weight;
    };

    Color trace(const PathRay& path, int depth, Sampler& sampler, std::uint64_t& rayCount) const;
    Color directLighting(const Hit& hit, const Bsdf& bsdf, const Vec3& wo, bool front,
                         Sampler& sampler, std::uint64_t& rayCount) const;

    const Scene& scene_;
    int maxDepth_;
    float adcBailout_;  // RenderSettings::adcBailout
    Bsdf::Weights weights_;
};

}  // namespace lancer
