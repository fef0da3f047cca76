#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/Shape.h"
#include "lights/Light.h"
#include "materials/Material.h"
#include "scene/Camera.h"
#include "scene/RenderSettings.h"

namespace lancer {

// Everything a render needs: settings, camera, materials, shapes and lights. It owns them all;
// shapes point to their materials, so a Scene is moved, never copied.
class Scene {
public:
    Scene() = default;
    Scene(Scene&&) = default;
    Scene& operator=(Scene&&) = default;

    RenderSettings& settings() { return settings_; }
    const RenderSettings& settings() const { return settings_; }

    const Camera& camera() const { return camera_; }
    void setCamera(const Camera& camera) { camera_ = camera; }

    const Color& background() const { return background_; }
    void setBackground(const Color& c) { background_ = c; }
    const Color& ambient() const { return ambient_; }
    void setAmbient(const Color& c) { ambient_ = c; }

    const Material* addMaterial(std::unique_ptr<Material> material);
    void addShape(std::unique_ptr<Shape> shape);
    void addLight(std::unique_ptr<Light> light);

    const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }

    // The nearest hit with 0 < t < tMax, if any.
    bool intersect(const Ray& ray, float tMax, Hit& hit) const;

    // The visibility V_l of a light sample from a surface point: the product of the transmission
    // of every surface the shadow ray crosses on its way (0 behind anything opaque).
    Color transmittance(const Hit& from, const LightSample& light, std::uint64_t& rayCount) const;

private:
    RenderSettings settings_;
    Camera camera_;
    Color background_{0};
    Color ambient_{0};
    std::vector<std::unique_ptr<Material>> materials_;
    std::vector<std::unique_ptr<Shape>> shapes_;
    std::vector<std::unique_ptr<Light>> lights_;
};

}  // namespace lancer
