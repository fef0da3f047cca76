#include "scene/Scene.h"

#include <algorithm>
#include <type_traits>
#include <variant>

#include "accel/Bvh.h"
#include "accel/WideBvh.h"
#include "geometry/Shape.h"
#include "geometry/Triangle.h"
#include "geometry/TriangleIntersector.h"
#include "lights/EnvironmentLight.h"
#include "lights/Light.h"
#include "materials/Material.h"

namespace lancer {

Scene::Scene() : bvh_(std::make_unique<WideBvh>()) {}
Scene::~Scene() = default;
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

std::size_t Scene::accelerationStructureBytes() const {
    return bvh_->memoryBytes();
}

Bounds3 Scene::bounds() const {
    return bvh_->bounds();
}

const Material* Scene::addMaterial(std::unique_ptr<Material> material) {
    materials_.push_back(std::move(material));
    return materials_.back().get();
}

void Scene::addShape(std::unique_ptr<Shape> shape) {
    for (std::uint32_t i = 0;
         i < shape->primitiveCount() &&
         !(hasTransmissiveMaterial_ && hasCutOuts_ && hasGlossyMaterial_ && hasEmittingSurface_);
         ++i) {
        if (const Material* material = shape->primitiveMaterial(i)) {
            hasTransmissiveMaterial_ = hasTransmissiveMaterial_ || material->isTransmissive();
            hasCutOuts_ = hasCutOuts_ || material->hasCutOuts();
            hasGlossyMaterial_ = hasGlossyMaterial_ || material->reflectsGlossily();
            hasEmittingSurface_ = hasEmittingSurface_ || !material->emission().isBlack();
        }
    }
    (shape->isBounded() ? boundedShapes_ : unboundedShapes_).push_back(std::move(shape));
}

void Scene::buildAccelerationStructure() {
    std::vector<Bounds3> bounds;
    bounds.reserve(boundedShapes_.size());
    for (const auto& shape : boundedShapes_)
        bounds.push_back(shape->bounds());
    // One shape per leaf: testing a shape (a csg, a mesh with its own hierarchy) costs far more
    // than testing its box, which the heuristic cannot know. Collapsed 8-wide, a scene of a few
    // objects is one node, whose boxes a ray meets in one SIMD test.
    const Bvh binary(bounds, 1);
    std::vector<std::unique_ptr<Shape>> ordered;
    ordered.reserve(boundedShapes_.size());
    for (std::uint32_t index : binary.primitiveOrder())
        ordered.push_back(std::move(boundedShapes_[index]));
    boundedShapes_ = std::move(ordered);
    // A leaf is known by its first shape in that order.
    bvh_ =
        std::make_unique<WideBvh>(binary, [](std::uint32_t first, std::uint32_t) { return first; });

    loneTrianglePack_.assign(boundedShapes_.size(), kNotALoneTriangle);
    loneTriangles_.clear();
    for (std::size_t k = 0; k < boundedShapes_.size(); ++k) {
        if (const std::optional<std::array<Vec3, 3>> corners = boundedShapes_[k]->loneTriangle()) {
            loneTrianglePack_[k] = static_cast<std::uint32_t>(loneTriangles_.size());
            TrianglePack& pack = loneTriangles_.emplace_back();  // zeros in the other lanes
            pack.set(0, (*corners)[0], (*corners)[1], (*corners)[2]);
        }
    }
    // With a single lone triangle there is no set-up to share: it tests itself.
    if (loneTriangles_.size() < 2) {
        loneTrianglePack_.assign(boundedShapes_.size(), kNotALoneTriangle);
        loneTriangles_.clear();
    }
}

void Scene::addLight(std::unique_ptr<Light> light) {
    lights_.push_back(std::move(light));
}

void Scene::setEnvironment(std::unique_ptr<EnvironmentLight> environment) {
    environment_ = environment.get();
    addLight(std::move(environment));
}

Color Scene::background(const Vec3& direction) const {
    return environment_ ? environment_->radiance(direction) : background_;
}

std::optional<Hit> Scene::intersect(const Ray& ray, float tMax) const {
    std::optional<SceneCrossing> crossing = cross(ray, tMax);
    if (!crossing) return std::nullopt;
    Hit hit = record(ray, *crossing);
    if (!hasCutOuts_) return hit;
    // Past each cut-away point by a ray spawned beyond it: it moves on at every step, so the walk
    // ends. Its t values are the first ray's, as the direction is the same.
    float travelled = 0;
    while (hit.material && hit.material->isCutAway(hit)) {
        travelled += hit.t;
        const Ray beyond = hit.spawnRay(ray.direction);
        crossing = cross(beyond, tMax - travelled);
        if (!crossing) return std::nullopt;
        hit = record(beyond, *crossing);
    }
    hit.t += travelled;
    return hit;
}

std::optional<SceneCrossing> Scene::cross(const Ray& ray, float tMax) const {
    return loneTriangles_.empty() ? crossWith<false>(ray, tMax) : crossWith<true>(ray, tMax);
}

// The ray's set-up for the lone triangles, made once before the search (a scene of two or more
// lone triangles has rays meet them all over); nothing when the scene tests none itself.
template <bool kLoneTriangles>
using LoneTriangleSetUp = std::conditional_t<kLoneTriangles, TriangleIntersector, std::monostate>;

template <bool kLoneTriangles>
LoneTriangleSetUp<kLoneTriangles> loneTriangleSetUp(const Ray& ray) {
    if constexpr (kLoneTriangles)
        return TriangleIntersector(ray);
    else
        return {};
}

template <bool kLoneTriangles>
std::optional<SceneCrossing> Scene::crossWith(const Ray& ray, float tMax) const {
    // The candidates only cross; the caller records the nearest.
    std::optional<SceneCrossing> nearest;
    const LoneTriangleSetUp<kLoneTriangles> intersector = loneTriangleSetUp<kLoneTriangles>(ray);
    const auto crossShape = [&](std::uint32_t k, float tFar) {
        if constexpr (kLoneTriangles) {
            if (loneTrianglePack_[k] != kNotALoneTriangle)
                return crossLoneTriangle(loneTrianglePack_[k], tFar, intersector);
        }
        return boundedShapes_[k]->cross(ray, tFar);
    };
    const auto crossLeaf = [&](std::uint32_t first, std::uint32_t count, float& tFar) {
        bool found = false;
        for (std::uint32_t k = first; k < first + count; ++k)
            if (const std::optional<SurfaceCrossing> crossing = crossShape(k, tFar)) {
                nearest = SceneCrossing{boundedShapes_[k].get(), *crossing};
                tFar = static_cast<float>(crossing->t);
                found = true;
            }
        return found;
    };
    bvh_->intersect(ray, tMax, crossLeaf, [](std::uint32_t) {});
    for (const auto& shape : unboundedShapes_) {
        if (const std::optional<SurfaceCrossing> crossing = shape->cross(ray, tMax)) {
            nearest = SceneCrossing{shape.get(), *crossing};
            tMax = static_cast<float>(crossing->t);
        }
    }
    return nearest;
}

std::optional<SurfaceCrossing> Scene::crossLoneTriangle(
    std::uint32_t pack, float tMax, const TriangleIntersector& intersector) const {
    if (!intersector.canHit()) return std::nullopt;
    const PackHits hits = intersector.intersect(loneTriangles_[pack], 1, tMax);
    if (hits.lanes == 0) return std::nullopt;
    return Triangle::crossingOf(hits.at(0));
}

Hit Scene::record(const Ray& ray, const SceneCrossing& crossing) const {
    return crossing.shape->record(ray, crossing.crossing);
}

bool Scene::occluded(const Ray& ray, float tMax) const {
    if (hasCutOuts_) return intersect(ray, tMax).has_value();  // a blocker may be cut away
    for (const auto& shape : unboundedShapes_)
        if (shape->occluded(ray, tMax)) return true;
    return loneTriangles_.empty() ? occludedWith<false>(ray, tMax) : occludedWith<true>(ray, tMax);
}

bool Scene::crossSegment(const Ray& ray, float tMax, std::vector<SceneCrossing>& crossings) const {
    crossings.clear();
    thread_local SurfaceCrossings found;
    // Whether light passes every crossing of the shape's.
    const auto collect = [&](const Shape& shape) {
        found.clear();
        shape.crossSegment(ray, tMax, found);
        for (const SurfaceCrossing& crossing : found) {
            const Material* material = shape.primitiveMaterial(crossing.primitive);
            if (material && !material->isTransmissive() && !material->hasCutOuts()) return false;
            crossings.push_back({&shape, crossing});
        }
        return true;
    };
    // The planes first: a floor stops many shadow rays before the hierarchy is entered.
    for (const auto& shape : unboundedShapes_)
        if (!collect(*shape)) return false;
    const auto blockedInLeaf = [&](std::uint32_t first, std::uint32_t count, float) {
        for (std::uint32_t k = first; k < first + count; ++k)
            if (!collect(*boundedShapes_[k])) return true;
        return false;
    };
    if (bvh_->occluded(ray, tMax, blockedInLeaf, [](std::uint32_t) {})) return false;
    std::sort(
        crossings.begin(), crossings.end(),
        [](const SceneCrossing& a, const SceneCrossing& b) { return a.crossing.t < b.crossing.t; });
    return true;
}

template <bool kLoneTriangles>
bool Scene::occludedWith(const Ray& ray, float tMax) const {
    const LoneTriangleSetUp<kLoneTriangles> intersector = loneTriangleSetUp<kLoneTriangles>(ray);
    const auto blocks = [&](std::uint32_t k, float tFar) {
        if constexpr (kLoneTriangles) {
            if (loneTrianglePack_[k] != kNotALoneTriangle)
                return crossLoneTriangle(loneTrianglePack_[k], tFar, intersector).has_value();
        }
        return boundedShapes_[k]->occluded(ray, tFar);
    };
    const auto occludedLeaf = [&](std::uint32_t first, std::uint32_t count, float tFar) {
        for (std::uint32_t k = first; k < first + count; ++k)
            if (blocks(k, tFar)) return true;
        return false;
    };
    return bvh_->occluded(ray, tMax, occludedLeaf, [](std::uint32_t) {});
}

}  // namespace lancer
