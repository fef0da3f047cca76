#include "scene/Scene.h"

namespace lancer {

const Material* Scene::addMaterial(std::unique_ptr<Material> material) {
    materials_.push_back(std::move(material));
    return materials_.back().get();
}

void Scene::addShape(std::unique_ptr<Shape> shape) {
    shapes_.push_back(std::move(shape));
}

void Scene::addLight(std::unique_ptr<Light> light) {
    lights_.push_back(std::move(light));
}

bool Scene::intersect(const Ray& ray, float tMax, Hit& hit) const {
    bool found = false;
    for (const auto& shape : shapes_) {
        if (shape->intersect(ray, tMax, hit)) {
            tMax = hit.t;
            found = true;
        }
    }
    return found;
}

Color Scene::transmittance(const Hit& from, const LightSample& light,
                           std::uint64_t& rayCount) const {
    Color visibility(1);
    Hit surface = from;
    // Each crossing starts beyond the surface just crossed, so the walk always moves towards
    // the light and ends.
    for (;;) {
        const Ray ray =
            light.atInfinity ? surface.spawnRay(light.wi) : surface.spawnRayTo(light.position);
        const float tMax = light.atInfinity ? kInfinity : 1 - kShadowEpsilon;
        ++rayCount;
        Hit blocker;
        if (!intersect(ray, tMax, blocker)) return visibility;
        visibility *= blocker.shape->material().transmission;
        if (visibility.isBlack()) return visibility;
        surface = blocker;
    }
}

}  // namespace lancer
