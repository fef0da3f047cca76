#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "geometry/Shape.h"
#include "geometry/TriangleIntersector.h"
#include "geometry/TriangleMesh.h"

namespace lancer {

// Triangle `index` of a TriangleMesh. Its front side, the one (v1 - v0) x (v2 - v0) points to, is
// the side it emits light on. Vertex normals, where the mesh has them, give smooth shading; uvs
// default to (0,0), (1,0), (0,1). The static functions are the triangle code that meshes share.
class Triangle final : public Shape {
public:
    Triangle(std::shared_ptr<const TriangleMesh> mesh, std::uint32_t index,
             const Material* material);
    // A standalone triangle (the scene file's), owning a mesh of one triangle.
    Triangle(const std::array<Vec3, 3>& vertices, const Material* material,
             const std::optional<std::array<Vec3, 3>>& normals = std::nullopt,
             const std::optional<std::array<Vec2, 3>>& uvs = std::nullopt);

    using Shape::intersect;  // beside the static test of a triangle's vertices below
    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    std::optional<std::array<Vec3, 3>> loneTriangle() const override { return vertices(); }
    Bounds3 bounds() const override;
    bool emitsOnBothSides() const override { return false; }
    float area(std::uint32_t primitive) const override;
    std::optional<ShapeSample> sample(std::uint32_t primitive, const Vec2& u) const override;
    Tessellation tessellate(const TessellationRequest& request) const override;

    std::array<Vec3, 3> vertices() const;

    // The crossing cross() gives for an intersection found by the watertight test (the scene's
    // own test of lone triangles gives the same).
    static SurfaceCrossing crossingOf(const TriangleIntersection& at) {
        return SurfaceCrossing{at.t, at.t, 0, at.b0, at.b1, at.b2};
    }
    // Watertight ray/triangle intersection with 0 < t < tMax (see TriangleIntersector).
    static std::optional<TriangleIntersection> intersect(const Vec3& p0, const Vec3& p1,
                                                         const Vec3& p2, const Ray& ray,
                                                         float tMax);
    // What every hit of a triangle shares: its unit geometric normal (the normalized edge
    // product) and the derivatives of its points along its uvs.
    struct SurfaceFrame {
        Vec3 ng, dpdu, dpdv;
    };
    static SurfaceFrame surfaceFrameOf(const TriangleMesh& mesh, std::uint32_t index);
    // The hit record of triangle `index` of `mesh` (primitive `index`), whose surfaceFrameOf is
    // `frame`, with the mesh's material for it, if the mesh has materials; `shape` is left to the
    // caller.
    static Hit makeHit(const TriangleMesh& mesh, std::uint32_t index,
                       const TriangleIntersection& at, const SurfaceFrame& frame);
    // A point uniformly distributed over the triangle's area for u uniform in [0,1)^2 (the
    // square-root warp onto barycentrics), with its density per unit area and front normal.
    static float areaOf(const std::array<Vec3, 3>& vertices);
    static ShapeSample sampleUniformly(const std::array<Vec3, 3>& vertices, const Vec2& u);

private:
    // What every uniform sample of a triangle shares: its front normal and density.
    struct UniformSampling {
        Vec3 frontNormal;
        float inverseArea;
    };
    static UniformSampling uniformSamplingOf(const std::array<Vec3, 3>& vertices);
    // The square-root warp of u onto the triangle.
    static Vec3 uniformPoint(const std::array<Vec3, 3>& vertices, const Vec2& u);

    std::shared_ptr<const TriangleMesh> mesh_;
    std::uint32_t index_;
    // Kept, as every hit and sample of the triangle would work them out again.
    SurfaceFrame frame_;
    float inverseArea_;
};

}  // namespace lancer
