#include "integrators/LightSampler.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "accel/Mesh.h"
#include "geometry/Hit.h"
#include "geometry/Instance.h"
#include "geometry/Sphere.h"
#include "geometry/Triangle.h"
#include "lights/SphereLight.h"
#include "lights/TriangleLight.h"
#include "materials/Material.h"
#include "scene/Scene.h"

namespace lancer {

namespace {

constexpr float kLargestFloat = std::numeric_limits<float>::max();

}  // namespace

LightSampler::LightSampler(const Scene& scene) {
    for (const auto& light : scene.lights())
        addLight(light.get());
    for (const auto& shape : scene.boundedShapes())
        addEmitters(*shape);
    if (lights_.empty()) return;
    const Bounds3 bounds = scene.bounds();
    const float sceneRadius = bounds.isEmpty() ? 1 : 0.5f * length(bounds.diagonal());
    std::vector<float> weights;
    weights.reserve(lights_.size());
    for (const Light* light : lights_) {
        // An emitter so strong that its power overflows still gets the largest share.
        const float power = light->power(sceneRadius).average();
        weights.push_back(std::isnan(power) ? 0 : std::clamp(power, 0.0f, kLargestFloat));
    }
    byPower_.emplace(std::move(weights));
}

void LightSampler::addLight(const Light* light) {
    indexOf_[light] = lights_.size();
    lights_.push_back(light);
}

void LightSampler::addEmitterLight(std::unique_ptr<Light> light, const Shape& placed,
                                   std::uint32_t primitive) {
    lightOfPrimitive_[{&placed, primitive}] = light.get();
    addLight(light.get());
    emitterLights_.push_back(std::move(light));
}

void LightSampler::addEmitters(const Shape& placed) {
    if (placed.areaLight()) return;  // the surface of a light of the scene file: sampled already
    // The geometry, and what places it in the world, when `placed` is an instance.
    const Shape* shape = &placed;
    const Transform* toWorld = nullptr;
    const Material* materialOverride = nullptr;
    if (const auto* instance = dynamic_cast<const Instance*>(&placed)) {
        shape = &instance->placedShape();
        toWorld = &instance->objectToWorld();
        materialOverride = instance->material();
    }
    const auto addTriangle = [&](std::array<Vec3, 3> vertices, std::uint32_t index,
                                 const Material* material) {
        if (materialOverride) material = materialOverride;
        if (!material || material->emission().isBlack()) return;
        Vec3 front = cross(vertices[1] - vertices[0], vertices[2] - vertices[0]);
        if (toWorld) {
            // The front side follows the normal as transformed (a mirroring transform turns the
            // winding around, not the side that emits).
            front = toWorld->applyNormal(front);
            for (Vec3& v : vertices)
                v = toWorld->applyPoint(v);
        }
        addEmitterLight(std::make_unique<TriangleLight>(vertices, front, material->emission()),
                        placed, index);
    };
    if (const auto* mesh = dynamic_cast<const Mesh*>(shape)) {
        const TriangleMesh& triangles = mesh->triangles();
        if (triangles.materials.empty() && !materialOverride) return;
        for (std::uint32_t i = 0; i < triangles.triangleCount(); ++i) {
            const std::uint32_t* v = &triangles.indices[3 * std::size_t{i}];
            const Material* material = triangles.materials.empty()
                                           ? nullptr
                                           : triangles.materials[triangles.faceMaterials[i]].get();
            addTriangle(
                {triangles.positions[v[0]], triangles.positions[v[1]], triangles.positions[v[2]]},
                i, material);
        }
    } else if (const auto* triangle = dynamic_cast<const Triangle*>(shape)) {
        addTriangle(triangle->vertices(), triangle->index(), triangle->material());
    } else if (const auto* sphere = dynamic_cast<const Sphere*>(shape); sphere && !toWorld) {
        const Material* material = sphere->material();
        if (material && !material->emission().isBlack())
            addEmitterLight(std::make_unique<SphereLight>(*sphere, material->emission()), placed,
                            0);
    }
}

std::optional<LightSampler::Choice> LightSampler::choose(float u) const {
    if (!byPower_) return std::nullopt;
    float probability = 0;
    const std::size_t index = byPower_->sampleDiscrete(u, &probability);
    if (!(probability > 0)) return std::nullopt;
    return Choice{lights_[index], probability};
}

float LightSampler::probability(const Light* light) const {
    const auto it = indexOf_.find(light);
    return it == indexOf_.end() ? 0 : byPower_->pmf(it->second);
}

const Light* LightSampler::lightAt(const Hit& hit) const {
    if (!hit.shape) return nullptr;
    if (const Light* light = hit.shape->areaLight()) return light;
    const auto it = lightOfPrimitive_.find({hit.shape, hit.primitive});
    return it == lightOfPrimitive_.end() ? nullptr : it->second;
}

}  // namespace lancer
