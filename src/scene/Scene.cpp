#include "scene/Scene.h"

namespace lancer {

const Material* Scene::addMaterial(std::unique_ptr<Material> material) {
    materials_.push_back(std::move(material));
    return materials_.back().get();
}

void Scene::addShape(std::unique_ptr<Shape> shape) {
    for (std::uint32_t i = 0; i < shape->primitiveCount() && !hasTransmissiveMaterial_; ++i) {
        const Material* material = shape->primitiveMaterial(i);
        hasTransmissiveMaterial_ = material && material->isTransmissive();
    }
    (shape->isBounded() ? boundedShapes_ : unboundedShapes_).push_back(std::move(shape));
}

void Scene::buildAccelerationStructure() {
    std::vector<Bounds3> bounds;
    bounds.reserve(boundedShapes_.size());
    for (const auto& shape : boundedShapes_)
        bounds.push_back(shape->bounds());
    bvh_ = Bvh(bounds);
    std::vector<std::unique_ptr<Shape>> ordered;
    ordered.reserve(boundedShapes_.size());
    for (std::uint32_t index : bvh_.primitiveOrder())
        ordered.push_back(std::move(boundedShapes_[index]));
    boundedShapes_ = std::move(ordered);
}

void Scene::addLight(std::unique_ptr<Light> light) {
    lights_.push_back(std::move(light));
}

std::optional<Hit> Scene::intersect(const Ray& ray, float tMax) const {
    std::optional<Hit> nearest;
    bvh_.intersect(ray, tMax, [&](std::uint32_t k, const Ray& r, float& tFar) {
        std::optional<Hit> hit = boundedShapes_[k]->intersect(r, tFar);
        if (!hit) return false;
        tFar = hit->t;
        nearest = std::move(hit);
        return true;
    });
    for (const auto& shape : unboundedShapes_) {
        if (std::optional<Hit> hit = shape->intersect(ray, tMax)) {
            tMax = hit->t;
            nearest = std::move(hit);
        }
    }
    return nearest;
}

bool Scene::occluded(const Ray& ray, float tMax) const {
    for (const auto& shape : unboundedShapes_)
        if (shape->occluded(ray, tMax)) return true;
    return bvh_.occluded(ray, tMax, [&](std::uint32_t k, const Ray& r, float tFar) {
        return boundedShapes_[k]->occluded(r, tFar);
    });
}

Color Scene::transmittance(const Hit& from, const LightSample& light,
                           std::uint64_t& rayCount) const {
    if (!hasTransmissiveMaterial_) {
        // Everything is opaque: the first blocker decides, and any blocker will do.
        const Ray ray =
            light.atInfinity ? from.spawnRay(light.wi) : from.spawnRayTo(light.position);
        ++rayCount;
        return occluded(ray, light.atInfinity ? kInfinity : 1 - kShadowEpsilon) ? Color(0)
                                                                                : Color(1);
    }
    Color visibility(1);
    Hit surface = from;
    // Each crossing starts beyond the surface just crossed, so the walk always moves towards
    // the light and ends.
    for (;;) {
        const Ray ray =
            light.atInfinity ? surface.spawnRay(light.wi) : surface.spawnRayTo(light.position);
        const float tMax = light.atInfinity ? kInfinity : 1 - kShadowEpsilon;
        ++rayCount;
        const std::optional<Hit> blocker = intersect(ray, tMax);
        if (!blocker) return visibility;
        visibility *= blocker->material->transmission();
        if (visibility.isBlack()) return visibility;
        surface = *blocker;
    }
}

}  // namespace lancer
