#include "integrators/WhittedIntegrator.h"

#include <array>
#include <bit>
#include <cmath>

#include "materials/Bsdf.h"
#include "materials/Material.h"
#include "sampling/Sampler.h"
#include "sampling/Sampling.h"
#include "sampling/StratifiedPoint.h"
#include "scene/Scene.h"
#include "scene/ShadowRays.h"

namespace lancer {

WhittedIntegrator::WhittedIntegrator(const Scene& scene, int maxDepth, Bsdf::Weights weights)
    : scene_(scene),
      maxDepth_(maxDepth),
      adcBailout_(scene.settings().adcBailout),
      weights_(weights) {}

std::unique_ptr<Integrator> WhittedIntegrator::create(const Scene& scene, const IntegratorSetup&) {
    return std::make_unique<WhittedIntegrator>(scene, scene.settings().maxDepth);
}

Color WhittedIntegrator::radiance(const Ray& ray, const RayCone& footprint, Sampler& sampler,
                                  std::uint64_t& rayCount) const {
    return trace({ray, 0, footprint, Color(1)}, 0, sampler, rayCount);
}

namespace {

// The pixel's footprint on the surface: a disc of the given width across the ray, projected
// along the ray onto the tangent plane (ray-cone texture filtering, ignoring curvature).
void setFootprint(Hit& hit, const Vec3& direction, float width) {
    const float cosTheta = dot(hit.ng, direction);
    if (cosTheta == 0) return;
    Vec3 a, b;
    coordinateSystem(direction, a, b);
    const auto ontoSurface = [&](const Vec3& v) {
        return width * (v - direction * (dot(hit.ng, v) / cosTheta));
    };
    hit.setUvFootprint(ontoSurface(a), ontoSurface(b));
}

}  // namespace

Color WhittedIntegrator::trace(const PathRay& path, int depth, Sampler& sampler,
                               std::uint64_t& rayCount) const {
    const Ray& ray = path.ray;
    ++rayCount;
    std::optional<Hit> found = scene_.intersect(ray, kInfinity);
    if (!found) return scene_.background(ray.direction);
    Hit& hit = *found;
    // Directions are unit vectors, so t is a distance.
    const float distance = path.distance + hit.t;
    const Material& material = *hit.material;
    if (material.readsFootprint())
        setFootprint(hit, ray.direction, path.footprint.widthAt(distance));
    const Vec3 wo = -normalize(ray.direction);
    // Shade the side the ray arrived on.
    const bool front = hit.frontFace(ray);
    const Bsdf bsdf(material, hit, wo, weights_);

    Color L;
    if (hit.seesEmittingSide(ray)) L += material.emission(hit);
    L += localShading(hit, bsdf, wo, front, sampler, rayCount);

    if (depth >= maxDepth_) return L;

    const auto traceFurther = [&](const SpecularRay& r) {
        const Color weight = path.weight * r.weight;
        // Adaptive depth control: a ray that could not change the pixel by the bailout is left.
        if (weight.maxComponent() < adcBailout_) return Color(0);
        return r.weight * trace({hit.spawnRay(r.direction), distance, path.footprint, weight},
                                depth + 1, sampler, rayCount);
    };
    std::array<SpecularRay, Bsdf::kMaxSpecularRays> rays;
    const std::size_t count = bsdf.specularRays(wo, front, rays);
    for (std::size_t i = 0; i < count; ++i)
        L += traceFurther(rays[i]);
    // Distribution ray tracing: one microfacet normal per rough lobe and pixel sample.
    for (std::size_t lobe = 0; lobe < bsdf.roughLobeCount(); ++lobe) {
        std::array<SpecularRay, 2> traced;
        const std::size_t tracedCount = bsdf.tracedRays(lobe, wo, sampler.get2D(), traced);
        for (std::size_t i = 0; i < tracedCount; ++i)
            L += traceFurther(traced[i]);
    }
    return L;
}

Color WhittedIntegrator::localShading(const Hit& hit, const Bsdf& bsdf, const Vec3& wo, bool front,
                                      Sampler& sampler, std::uint64_t& rayCount) const {
    return hit.material->ambientReflectance(hit) * scene_.ambient() +
           directLighting(hit, bsdf, wo, front, sampler, rayCount);
}

Color WhittedIntegrator::directLighting(const Hit& hit, const Bsdf& bsdf, const Vec3& wo,
                                        bool front, Sampler& sampler,
                                        std::uint64_t& rayCount) const {
    // V_l E_l (kd max(0, n.L) + ks max(0, n.h)^n [n.L > 0]) for one sample of a light.
    const auto shade = [&](const LightSample& ls, bool deltaLight) {
        const Color brdfCos = bsdf.localResponse(wo, ls.wi, front, deltaLight);
        if (brdfCos.isBlack() || ls.irradiance.isBlack()) return Color(0);
        return ShadowRays::transmittance(scene_, hit, ls, rayCount) * ls.irradiance * brdfCos;
    };
    Color L;
    for (const auto& light : scene_.lights()) {
        if (light->isDelta()) {
            L += shade(light->sample(hit.p, Vec2(0.5f, 0.5f)), true);
            continue;
        }
        // An area light: the average over its shadow samples, stratified over the light, the
        // pattern shifted by a fresh offset from the sampler at every hit (with wrap-around, so
        // that every point is uniform over the light and the average unbiased) and jittered by
        // a hash of that offset.
        const int count = light->shadowSamples();
        const Vec2 offset = sampler.get2D();
        const std::uint64_t jitterSeed = hashValues(std::bit_cast<std::uint32_t>(offset.x),
                                                    std::bit_cast<std::uint32_t>(offset.y));
        Color sum;
        for (int k = 0; k < count; ++k)
            sum +=
                shade(light->sample(hit.p, shifted(stratifiedPoint(k, count, jitterSeed), offset)),
                      false);
        L += sum / static_cast<float>(count);
    }
    return L;
}

}  // namespace lancer
