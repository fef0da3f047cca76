#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/Hit.h"
#include "geometry/TrianglePack.h"
#include "math/Bounds3.h"
#include "math/Color.h"
#include "math/Float.h"
#include "math/Ray.h"
#include "scene/Camera.h"
#include "scene/RenderSettings.h"
#include "scene/SceneCrossing.h"

namespace lancer {

class WideBvh;
class TriangleIntersector;
class EnvironmentLight;
class Light;
class Material;
class Shape;

// Everything a render needs: settings, camera, materials, shapes and lights. It owns them all;
// shapes point to their materials, so a Scene is moved, never copied.
class Scene {
public:
    // What the scene holds, for --stats.
    struct Statistics {
        std::size_t uniqueTriangles = 0;     // stored: each model counted once
        std::size_t instancedTriangles = 0;  // drawn: each model counted once per instance
        std::size_t meshBytes = 0;           // the models' vertex, index and BVH arrays
        double loadSeconds = 0;              // reading files and building BVHs
        double buildSeconds = 0;             // of which building BVHs (models' and the scene's)
        std::size_t cachedModels = 0;        // models taken from the model cache, not built
    };

    Scene();
    ~Scene();
    Scene(Scene&&) noexcept;
    Scene& operator=(Scene&&) noexcept;

    RenderSettings& settings() { return settings_; }
    const RenderSettings& settings() const { return settings_; }

    const Camera& camera() const { return *camera_; }
    void setCamera(std::unique_ptr<const Camera> camera) { camera_ = std::move(camera); }

    // The colour of rays that leave the scene when it has no environment.
    const Color& background() const { return background_; }
    void setBackground(const Color& c) { background_ = c; }
    // The radiance a ray leaving the scene along `direction` sees: the environment's, or the
    // background colour.
    Color background(const Vec3& direction) const;
    // The environment is one of the lights too (it is sampled and lights every integrator).
    void setEnvironment(std::unique_ptr<EnvironmentLight> environment);
    const EnvironmentLight* environment() const { return environment_; }
    const Color& ambient() const { return ambient_; }
    void setAmbient(const Color& c) { ambient_ = c; }

    const Material* addMaterial(std::unique_ptr<Material> material);
    void addShape(std::unique_ptr<Shape> shape);
    void addLight(std::unique_ptr<Light> light);
    // Builds the BVH over the bounded shapes; call once all shapes are added, before rendering.
    void buildAccelerationStructure();

    const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }
    // The infinite shapes (planes), outside the BVH: radiosity meshes them too.
    const std::vector<std::unique_ptr<Shape>>& unboundedShapes() const { return unboundedShapes_; }

    // The files the scene was read from: the scene file, its includes, models and their material
    // files, textures and maps; a resumed render checks that none of them has changed.
    void addSourceFile(const std::filesystem::path& path) { sourceFiles_.push_back(path); }
    const std::vector<std::filesystem::path>& sourceFiles() const { return sourceFiles_; }

    Statistics& statistics() { return statistics_; }
    const Statistics& statistics() const { return statistics_; }
    std::size_t boundedShapeCount() const { return boundedShapes_.size(); }
    std::size_t unboundedShapeCount() const { return unboundedShapes_.size(); }
    std::size_t accelerationStructureBytes() const;
    // The shapes in the BVH (all but infinite planes), and the box they fit in.
    const std::vector<std::unique_ptr<Shape>>& boundedShapes() const { return boundedShapes_; }
    Bounds3 bounds() const;

    // The nearest hit with 0 < t < tMax, if any: every candidate crosses, the nearest is recorded.
    // Points of surfaces cut away by their material's opacity are passed through (cross and
    // record below see every surface).
    std::optional<Hit> intersect(const Ray& ray, float tMax) const;
    // The same in two phases: the nearest crossing, then its record (for callers that may need
    // no record, such as shadow rays stopped by an opaque surface).
    std::optional<SceneCrossing> cross(const Ray& ray, float tMax) const;
    Hit record(const Ray& ray, const SceneCrossing& crossing) const;
    // Whether anything is hit with 0 < t < tMax (cut-away points let the ray through).
    bool occluded(const Ray& ray, float tMax) const;
    // For shadow rays through transparent surfaces, in one search: every crossing with
    // 0 < t < tMax, in increasing t, into `crossings` (records are the caller's); false, and the
    // crossings left unfinished, as soon as one is of a surface no light passes (an opaque
    // material without cut-outs).
    bool crossSegment(const Ray& ray, float tMax, std::vector<SceneCrossing>& crossings) const;

    // Whether some surface lets light through (shadow rays must then look past the first
    // surface they meet).
    bool hasTransmissiveMaterial() const { return hasTransmissiveMaterial_; }
    // Whether some surface has alpha cut-outs (intersect then looks past the points cut away).
    bool hasCutOuts() const { return hasCutOuts_; }
    // Whether some surface reflects glossily (Material::reflectsGlossily).
    bool hasGlossyMaterial() const { return hasGlossyMaterial_; }
    // Whether some surface emits light (an area light, an emitting material).
    bool hasEmittingSurface() const { return hasEmittingSurface_; }

private:
    // cross and occluded through the BVH, the lone triangles tested by the scene (kLoneTriangles)
    // or, as every other shape, by themselves: a scene of none keeps the leaner traversal.
    template <bool kLoneTriangles>
    std::optional<SceneCrossing> crossWith(const Ray& ray, float tMax) const;
    template <bool kLoneTriangles>
    bool occludedWith(const Ray& ray, float tMax) const;
    // The crossing of the lone triangle in loneTriangles_[pack]: what Triangle::cross finds, with
    // the ray's set-up made once for all. Out of line, so that the other shapes' path through the
    // traversal stays as lean.
    LANCER_NEVER_INLINE std::optional<SurfaceCrossing> crossLoneTriangle(
        std::uint32_t pack, float tMax, const TriangleIntersector& intersector) const;

    RenderSettings settings_;
    std::unique_ptr<const Camera> camera_;
    Color background_{0};
    const EnvironmentLight* environment_ = nullptr;  // one of lights_, or none
    Color ambient_{0};
    std::vector<std::unique_ptr<Material>> materials_;
    std::vector<std::unique_ptr<Shape>> boundedShapes_;  // in the BVH's leaf order once built
    std::vector<std::unique_ptr<Shape>> unboundedShapes_;
    std::unique_ptr<WideBvh> bvh_;  // over the bounded shapes
    // For each bounded shape, the pack holding it (in lane 0) when it is a lone triangle
    // (Shape::loneTriangle) and the scene has two or more, else kNotALoneTriangle.
    static constexpr std::uint32_t kNotALoneTriangle = ~0u;
    std::vector<std::uint32_t> loneTrianglePack_;
    std::vector<TrianglePack> loneTriangles_;
    bool hasTransmissiveMaterial_ = false;
    bool hasEmittingSurface_ = false;
    bool hasCutOuts_ = false;
    bool hasGlossyMaterial_ = false;
    Statistics statistics_;
    std::vector<std::filesystem::path> sourceFiles_;
    std::vector<std::unique_ptr<Light>> lights_;
};

}  // namespace lancer
