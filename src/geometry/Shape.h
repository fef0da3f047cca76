#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "geometry/Hit.h"
#include "geometry/LineCrossing.h"
#include "geometry/ShapeSample.h"
#include "geometry/SurfaceCrossing.h"
#include "geometry/Tessellation.h"
#include "math/Bounds3.h"
#include "math/Ray.h"
#include "math/Vec2.h"

namespace lancer {

class Light;
class Material;

// A surface a ray can hit, sample and mesh. Its surface is made of primitives (a mesh's
// triangles; the shape itself for the others), numbered as Hit::primitive numbers them, each of
// one material. Everything integrators, lights and radiosity need of a shape is asked through
// this interface: none of them needs to know which shape it holds.
class Shape {
public:
    explicit Shape(const Material* material) : material_(material) {}
    virtual ~Shape() = default;
    Shape(const Shape&) = delete;
    Shape& operator=(const Shape&) = delete;

    // The nearest intersection with 0 < t < tMax: a fresh record with every field set (t, p,
    // pError, ng, ns, dpdu, dpdv, uv (or its deferral), shape, primitive, material; the uv
    // footprint is the caller's), or nothing.
    std::optional<Hit> intersect(const Ray& ray, float tMax) const {
        const std::optional<SurfaceCrossing> crossing = cross(ray, tMax);
        if (!crossing) return std::nullopt;
        return record(ray, *crossing);
    }
    // The same in two phases (pbrt-v4's basic intersection, then the interaction), for a caller
    // that tries many shapes and wants the record of the nearest only: the nearest crossing with
    // 0 < t < tMax, then the record of a crossing that cross(ray, ·) found.
    virtual std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const = 0;
    virtual Hit record(const Ray& ray, const SurfaceCrossing& crossing) const = 0;
    // The uv of a record whose uv this shape deferred (Hit::deferUv), from the local point it
    // left there. Only the shapes that defer it are asked.
    virtual Vec2 uvAt(const Vec3&) const { return {}; }

    // Whether anything is hit with 0 < t < tMax: shadow rays, which need no hit record and can
    // stop at the first hit found.
    virtual bool occluded(const Ray& ray, float tMax) const { return cross(ray, tMax).has_value(); }
    // Appends every crossing with 0 < t < tMax, in no particular order, each as cross() would
    // find it were it the nearest (so record() takes it): what a shadow ray through transparent
    // surfaces multiplies, found in one search. By default a solid's crossings of its line
    // (crossLine) within the segment, and for any other shape the one crossing cross() finds:
    // other shapes a line can cross more than once override it.
    virtual void crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const;
    // The corners of a shape that is one triangle crossed as Triangle::intersect crosses them, in
    // that order: a scene may test it itself, with the ray's set-up for triangles made once for
    // all it meets (the same test, so the same crossings). Nothing for any other shape.
    virtual std::optional<std::array<Vec3, 3>> loneTriangle() const { return std::nullopt; }

    // Whether the surface is closed around a volume with its normals pointing out (a sphere, a
    // box, a closed cylinder, a closed mesh...): a solid, which CSG can combine.
    virtual bool isSolid() const { return false; }
    // For a solid: appends every crossing of the ray's whole line with the surface, in
    // increasing t (of either sign), each entering or leaving the solid. Not asked of other
    // shapes (which append nothing, or what they would be crossed at).
    virtual void crossLine(const Ray&, LineCrossings&) const {}
    // For a solid: whether p lies inside it, from the crossings of a line through p (so on the
    // surface the answer is either).
    bool contains(const Vec3& p) const;

    // The box the shape fits in. Only meaningful when isBounded().
    virtual Bounds3 bounds() const = 0;
    // False for shapes that extend to infinity (planes), which stay outside the BVH.
    virtual bool isBounded() const { return true; }

    // Whether a material's emission leaves both sides of the surface (spheres and planes) or
    // only the side the geometric normal points to (triangles, quads).
    virtual bool emitsOnBothSides() const { return true; }

    virtual std::uint32_t primitiveCount() const { return 1; }
    // The primitive's material; null when it has none of its own.
    virtual const Material* primitiveMaterial(std::uint32_t) const { return material_; }

    // The primitive's surface area (infinite for planes).
    virtual float area(std::uint32_t primitive) const = 0;
    // A point of the primitive, uniformly distributed by area for u uniform in [0,1)^2, with its
    // density per unit area; nothing for surfaces that cannot be sampled (infinite ones).
    virtual std::optional<ShapeSample> sample(std::uint32_t primitive, const Vec2& u) const = 0;
    // The density per unit area of sample(primitive, ·) at a point of the surface.
    virtual float areaPdf(std::uint32_t primitive, const Hit& onSurface) const;

    // A point of the primitive for lighting `reference`, with its density per unit solid angle
    // seen from there and the direction to it; nothing if the point is the reference point. By
    // default the area sample converted; shapes may sample better (the sphere samples the cone
    // it subtends).
    virtual std::optional<DirectionSample> sample(std::uint32_t primitive, const Vec3& reference,
                                                  const Vec2& u) const;
    // The solid-angle density with which sample(primitive, reference, ·) picks the direction wi
    // that reaches the surface at `onSurface`.
    virtual float pdf(std::uint32_t primitive, const Vec3& reference, const Vec3& wi,
                      const Hit& onSurface) const;

    // The surface as flat facets, for radiosity.
    virtual Tessellation tessellate(const TessellationRequest& request) const = 0;

    const Material* material() const { return material_; }

    // The light whose visible surface this shape is (an area light of the scene file), or null.
    // Integrators use it to weigh a ray that hits the light against sampling the light directly.
    const Light* areaLight() const { return areaLight_; }
    void setAreaLight(const Light* light) { areaLight_ = light; }

protected:
    // A density per unit area at a point seen from distance sqrt(distanceSquared), at cosine
    // cosSurface to the surface's normal, as a density per unit solid angle: 0 edge-on.
    static float areaToSolidAngle(float areaPdf, float distanceSquared, float cosSurface);
    // The sample `at` as seen from `reference` (its density left as it is); nothing if `at` is the
    // reference point.
    static std::optional<DirectionSample> seenFrom(const Vec3& reference, const ShapeSample& at);

private:
    const Material* material_;
    const Light* areaLight_ = nullptr;
};

}  // namespace lancer
