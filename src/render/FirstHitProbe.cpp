#include "render/FirstHitProbe.h"

#include <algorithm>
#include <array>
#include <optional>

#include "geometry/Hit.h"
#include "materials/Bsdf.h"
#include "scene/Scene.h"

namespace lancer {

FirstHitProbe::FirstHitProbe(const Scene& scene)
    : scene_(scene), maxDepth_(scene.settings().maxDepth) {}

AovSample FirstHitProbe::probe(const Ray& cameraRay, std::uint64_t& rayCount) const {
    AovSample sample;
    Ray ray = cameraRay;
    for (int depth = 0;; ++depth) {
        ++rayCount;
        const std::optional<Hit> found = scene_.intersect(ray, kInfinity);
        if (!found) return sample;
        const Hit& hit = *found;
        const bool front = hit.frontFace(ray);
        const Vec3 wo = -normalize(ray.direction);
        const Bsdf bsdf(*hit.material, hit, wo, Bsdf::Weights::AsGiven);
        if (depth == 0) {
            sample.normal = bsdf.shadingNormal(front);
            // The camera's rays have unit directions, so t is a distance.
            sample.depth = hit.t;
        }
        std::array<SpecularRay, Bsdf::kMaxSpecularRays> rays;
        const std::size_t count =
            depth < maxDepth_ ? bsdf.specularRays(wo, front, rays) : 0;
        // A surface with a diffuse colour is what the albedo describes, even if it also
        // reflects (its mirror image is detail a denoiser should keep from the image itself);
        // one without a diffuse colour or a way on (black, or the depth reached) has albedo 0.
        if (!bsdf.diffuseReflectance().isBlack() || count == 0) {
            sample.albedo = bsdf.diffuseReflectance();
            return sample;
        }
        // Glass splits the ray: the branch that carries the most light is the one seen.
        const SpecularRay& next =
            *std::max_element(rays.begin(), rays.begin() + static_cast<std::ptrdiff_t>(count),
                              [](const SpecularRay& a, const SpecularRay& b) {
                                  return a.weight.average() < b.weight.average();
                              });
        ray = hit.spawnRay(next.direction);
    }
}

}  // namespace lancer
