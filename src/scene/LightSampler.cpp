#include "scene/LightSampler.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/Hit.h"
#include "geometry/Shape.h"
#include "lights/AreaLight.h"
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

void LightSampler::addEmitters(const Shape& shape) {
    if (shape.areaLight()) return;  // the surface of a light of the scene file: sampled already
    for (std::uint32_t i = 0; i < shape.primitiveCount(); ++i) {
        const Material* material = shape.primitiveMaterial(i);
        if (!material || material->emission().isBlack()) continue;
        AreaLight::RadianceAt radianceAt;
        if (material->hasTexturedEmission())
            radianceAt = [material](const Hit& hit) { return material->emission(hit); };
        addEmitterLight(
            std::make_unique<AreaLight>(shape, i, material->emission(), std::move(radianceAt)),
            shape, i);
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
