#include "scene/ShadowRays.h"

#include <vector>

#include "geometry/Shape.h"
#include "materials/Material.h"
#include "scene/Scene.h"

namespace lancer {

bool ShadowRays::unoccluded(const Scene& scene, const Hit& from, const LightSample& light,
                            std::uint64_t& rayCount) {
    ++rayCount;
    return !scene.occluded(towards(from, light), reach(light));
}

Color ShadowRays::transmittance(const Scene& scene, const Hit& from, const LightSample& light,
                                std::uint64_t& rayCount) {
    // Everything is opaque: the first blocker decides, and any blocker will do.
    if (!scene.hasTransmissiveMaterial())
        return unoccluded(scene, from, light, rayCount) ? Color(1) : Color(0);
    ++rayCount;
    const Ray ray = towards(from, light);
    thread_local std::vector<SceneCrossing> crossings;
    if (!scene.crossSegment(ray, reach(light), crossings)) return Color(0);
    // Multiplied in the order the light meets them, so that the rounding does not depend on
    // the order the search found them in.
    Color visibility(1);
    for (const SceneCrossing& crossing : crossings) {
        const Material* material = crossing.shape->primitiveMaterial(crossing.crossing.primitive);
        // Only a cut-out needs the record, to know whether the point is cut away.
        if (!material || material->hasCutOuts()) {
            const Hit surface = scene.record(ray, crossing);
            material = surface.material;
            if (material->isCutAway(surface)) continue;
        }
        visibility *= material->transmission();
        if (visibility.isBlack()) return visibility;
    }
    return visibility;
}

}  // namespace lancer
