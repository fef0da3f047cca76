#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "lights/Light.h"
#include "math/Distribution1D.h"

namespace lancer {

class Scene;
class Shape;
struct Hit;

// The lights a path tracer samples: the scene's own (point, directional, spot, quad, sphere, the
// environment) and an AreaLight for each emissive primitive of the shapes in the BVH (a triangle
// of a model, per instance, a sphere, a quad...), on the sides its shape emits from. Infinite
// planes that emit are found only by rays that hit them. A light is picked in proportion to its
// power (the average of its channels), the scene's radius bounding the power of lights at infinity.
class LightSampler {
public:
    explicit LightSampler(const Scene& scene);

    struct Choice {
        const Light* light;
        float probability;
    };
    // The light whose share of [0, 1) holds u; none when the scene has no light.
    std::optional<Choice> choose(float u) const;
    // Whether choose() depends on u (not for one light or none).
    bool choiceReadsU() const { return lights_.size() > 1; }
    // The probability of choosing `light` (0 for a light that is not sampled).
    float probability(const Light* light) const;
    // The light whose surface a hit lies on, or null.
    const Light* lightAt(const Hit& hit) const;

    std::size_t size() const { return lights_.size(); }

private:
    // The lights of a scene shape's emissive primitives.
    void addEmitters(const Shape& shape);
    void addEmitterLight(std::unique_ptr<Light> light, const Shape& shape, std::uint32_t primitive);
    void addLight(const Light* light);

    std::vector<std::unique_ptr<Light>> emitterLights_;  // the lights made for emissive surfaces
    std::vector<const Light*> lights_;
    std::unordered_map<const Light*, std::size_t> indexOf_;
    struct PrimitiveHash {
        std::size_t operator()(const std::pair<const Shape*, std::uint32_t>& key) const {
            return std::hash<const Shape*>()(key.first) ^
                   (std::size_t{key.second} * 0x9e3779b97f4a7c15ULL);
        }
    };
    // The light of each emissive primitive: (the scene's shape, the primitive's index).
    std::unordered_map<std::pair<const Shape*, std::uint32_t>, const Light*, PrimitiveHash>
        lightOfPrimitive_;
    std::optional<Distribution1D> byPower_;
};

}  // namespace lancer
