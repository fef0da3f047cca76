#include "render/WhittedIntegrator.h"

#include <cmath>

#include "materials/Material.h"
#include "materials/Optics.h"
#include "render/Sampler.h"
#include "scene/Scene.h"

namespace lancer {

WhittedIntegrator::WhittedIntegrator(const Scene& scene, int maxDepth)
    : scene_(scene), maxDepth_(maxDepth) {}

Color WhittedIntegrator::radiance(const Ray& ray, float pixelSpread, Sampler& sampler,
                                  std::uint64_t& rayCount) const {
    return trace({ray, 0, pixelSpread}, 0, sampler, rayCount);
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
    Hit hit;
    if (!scene_.intersect(ray, kInfinity, hit)) return scene_.background();
    // Directions are unit vectors, so t is a distance.
    const float distance = path.distance + hit.t;
    setFootprint(hit, ray.direction, distance * path.spread);

    const Material& material = *hit.material;
    const Vec3 wo = -normalize(ray.direction);
    const bool front = hit.frontFace(ray);
    // Shade the side the ray arrived on.
    const Vec3 n = front ? hit.ns : -hit.ns;

    Color L;
    if (front || hit.shape->emitsOnBothSides()) L += material.emission;
    L += material.ambient->evaluate(hit) * scene_.ambient();
    L += directLighting(hit, n, wo, sampler, rayCount);

    if (depth >= maxDepth_) return L;

    Color reflectionWeight = material.reflection;
    Color refractionWeight;
    std::optional<Vec3> refracted;
    if (material.isTransmissive()) {
        // eta: index beyond the surface over index on the ray's side.
        const float eta = front ? material.ior : 1 / material.ior;
        const float F = fresnelDielectric(std::min(1.0f, std::abs(dot(wo, n))), eta);
        reflectionWeight += material.transmission * F;
        refractionWeight = material.transmission * (1 - F);
        if (!refractionWeight.isBlack()) refracted = refract(wo, n, eta);
    }
    if (!reflectionWeight.isBlack())
        L += reflectionWeight * trace({hit.spawnRay(reflect(wo, n)), distance, path.spread},
                                      depth + 1, sampler, rayCount);
    if (refracted)
        L += refractionWeight * trace({hit.spawnRay(normalize(*refracted)), distance, path.spread},
                                      depth + 1, sampler, rayCount);
    return L;
}

Color WhittedIntegrator::directLighting(const Hit& hit, const Vec3& n, const Vec3& wo,
                                        Sampler& sampler, std::uint64_t& rayCount) const {
    const Material& material = *hit.material;
    const Color kd = material.diffuse->evaluate(hit);
    Color L;
    for (const auto& light : scene_.lights()) {
        const Vec2 u = light->isDelta() ? Vec2(0.5f, 0.5f) : sampler.get2D();
        const LightSample ls = light->sample(hit.p, u);
        const float cosTheta = dot(n, ls.wi);
        if (cosTheta <= 0) continue;  // both terms vanish when the light is behind the surface
        const Vec3 h = normalize(ls.wi + wo);
        const Color brdfCos =
            kd * cosTheta +
            material.specular * std::pow(std::max(0.0f, dot(n, h)), material.shininess);
        if (brdfCos.isBlack() || ls.irradiance.isBlack()) continue;
        const Color visibility = scene_.transmittance(hit, ls, rayCount);
        L += visibility * ls.irradiance * brdfCos;
    }
    return L;
}

}  // namespace lancer
