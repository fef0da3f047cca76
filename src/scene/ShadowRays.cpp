#include "scene/ShadowRays.h"

#include <optional>

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
    Color visibility(1);
    Hit surface = from;
    // Each crossing starts beyond the surface just crossed, so the walk always moves towards
    // the light and ends.
    for (;;) {
        ++rayCount;
        const Ray ray = towards(surface, light);
        const std::optional<SceneCrossing> crossing = scene.cross(ray, reach(light));
        if (!crossing) return visibility;
        // An opaque surface stops the light: no record needed to know it.
        const Material* material = crossing->shape->primitiveMaterial(crossing->crossing.primitive);
        if (material && !material->isTransmissive() && !material->hasCutOuts()) return Color(0);
        const Hit blocker = scene.record(ray, *crossing);
        if (!blocker.material->isCutAway(blocker)) {
            visibility *= blocker.material->transmission();
            if (visibility.isBlack()) return visibility;
        }
        surface = blocker;
    }
}

}  // namespace lancer
