#include "geometry/Triangle.h"

#include <cmath>

namespace lancer {

namespace {

std::shared_ptr<const TriangleMesh> makeSingleTriangleMesh(
    const std::array<Vec3, 3>& vertices, const std::optional<std::array<Vec3, 3>>& normals,
    const std::optional<std::array<Vec2, 3>>& uvs) {
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->positions.assign(vertices.begin(), vertices.end());
    if (normals) mesh->normals.assign(normals->begin(), normals->end());
    if (uvs) mesh->uvs.assign(uvs->begin(), uvs->end());
    mesh->indices = {0, 1, 2};
    mesh->faceMaterials = {0};
    return mesh;
}

// A triangle's vertex uvs: the mesh's, or the unit right triangle's where the mesh has none.
std::array<Vec2, 3> vertexUvs(const TriangleMesh& mesh, const std::uint32_t* v) {
    if (mesh.uvs.empty()) return {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
    return {mesh.uvs[v[0]], mesh.uvs[v[1]], mesh.uvs[v[2]]};
}

}  // namespace

Triangle::Triangle(std::shared_ptr<const TriangleMesh> mesh, std::uint32_t index,
                   const Material* material)
    : Shape(material),
      mesh_(std::move(mesh)),
      index_(index),
      frame_(surfaceFrameOf(*mesh_, index_)),
      inverseArea_(uniformSamplingOf(vertices()).inverseArea) {}

Triangle::Triangle(const std::array<Vec3, 3>& vertices, const Material* material,
                   const std::optional<std::array<Vec3, 3>>& normals,
                   const std::optional<std::array<Vec2, 3>>& uvs)
    : Triangle(makeSingleTriangleMesh(vertices, normals, uvs), 0, material) {}

float Triangle::areaOf(const std::array<Vec3, 3>& p) {
    return 0.5f * length(lancer::cross(p[1] - p[0], p[2] - p[0]));
}

float Triangle::area(std::uint32_t) const {
    return areaOf(vertices());
}

Triangle::UniformSampling Triangle::uniformSamplingOf(const std::array<Vec3, 3>& p) {
    const Vec3 normal = lancer::cross(p[1] - p[0], p[2] - p[0]);
    // normalize(normal) and 1 / areaOf(p) from one division: halving the length is exact, so
    // 1 / (length / 2) rounds to twice 1 / length.
    const float inverseLength = 1 / length(normal);
    return {normal * inverseLength, 2 * inverseLength};
}

Vec3 Triangle::uniformPoint(const std::array<Vec3, 3>& p, const Vec2& u) {
    const float su0 = std::sqrt(u.x);
    const float b0 = 1 - su0, b1 = u.y * su0;
    return b0 * p[0] + b1 * p[1] + (1 - b0 - b1) * p[2];
}

ShapeSample Triangle::sampleUniformly(const std::array<Vec3, 3>& p, const Vec2& u) {
    const UniformSampling sampling = uniformSamplingOf(p);
    return {uniformPoint(p, u), sampling.frontNormal, sampling.inverseArea};
}

std::optional<ShapeSample> Triangle::sample(std::uint32_t, const Vec2& u) const {
    // frame_.ng is the normalized edge product, as uniformSamplingOf gives it.
    return ShapeSample{uniformPoint(vertices(), u), frame_.ng, inverseArea_};
}

Tessellation Triangle::tessellate(const TessellationRequest&) const {
    Tessellation tessellation;
    tessellation.facets = {{vertices(), 0}};
    return tessellation;
}

std::array<Vec3, 3> Triangle::vertices() const {
    const std::uint32_t* v = &mesh_->indices[3 * std::size_t{index_}];
    const std::vector<Vec3>& p = mesh_->positions;
    return {p[v[0]], p[v[1]], p[v[2]]};
}

Bounds3 Triangle::bounds() const {
    const std::uint32_t* v = &mesh_->indices[3 * std::size_t{index_}];
    const std::vector<Vec3>& p = mesh_->positions;
    return merge(Bounds3(p[v[0]], p[v[1]]), p[v[2]]);
}

std::optional<SurfaceCrossing> Triangle::cross(const Ray& ray, float tMax) const {
    const std::uint32_t* v = &mesh_->indices[3 * std::size_t{index_}];
    const std::vector<Vec3>& p = mesh_->positions;
    const auto at = intersect(p[v[0]], p[v[1]], p[v[2]], ray, tMax);
    if (!at) return std::nullopt;
    return crossingOf(*at);
}

Hit Triangle::record(const Ray&, const SurfaceCrossing& crossing) const {
    Hit hit = makeHit(*mesh_, index_,
                      {crossing.b0, crossing.b1, crossing.b2, static_cast<float>(crossing.tShape)},
                      frame_);
    hit.shape = this;
    hit.primitive = 0;  // the triangle is this shape's one primitive
    if (material()) hit.material = material();
    return hit;
}

std::optional<TriangleIntersection> Triangle::intersect(const Vec3& v0, const Vec3& v1,
                                                        const Vec3& v2, const Ray& ray,
                                                        float tMax) {
    const TriangleIntersector intersector(ray);
    if (!intersector.canHit()) return std::nullopt;
    return intersector.intersect(v0, v1, v2, tMax);
}

Triangle::SurfaceFrame Triangle::surfaceFrameOf(const TriangleMesh& mesh, std::uint32_t index) {
    const std::uint32_t* v = &mesh.indices[3 * std::size_t{index}];
    const Vec3& p0 = mesh.positions[v[0]];
    const Vec3& p1 = mesh.positions[v[1]];
    const Vec3& p2 = mesh.positions[v[2]];
    SurfaceFrame frame;
    frame.ng = normalize(lancer::cross(p1 - p0, p2 - p0));
    const auto [uv0, uv1, uv2] = vertexUvs(mesh, v);
    // dp/du and dp/dv: solve p0 - p2 = du02 dpdu + dv02 dpdv, p1 - p2 = du12 dpdu + dv12 dpdv.
    const Vec2 duv02 = uv0 - uv2, duv12 = uv1 - uv2;
    const Vec3 dp02 = p0 - p2, dp12 = p1 - p2;
    const float uvDet = duv02.x * duv12.y - duv02.y * duv12.x;
    if (std::abs(uvDet) > 1e-12f) {
        const float inv = 1 / uvDet;
        frame.dpdu = (duv12.y * dp02 - duv02.y * dp12) * inv;
        frame.dpdv = (duv02.x * dp12 - duv12.x * dp02) * inv;
    } else {
        coordinateSystem(frame.ng, frame.dpdu, frame.dpdv);  // uvs do not span the triangle
    }
    return frame;
}

Hit Triangle::makeHit(const TriangleMesh& mesh, std::uint32_t index, const TriangleIntersection& at,
                      const SurfaceFrame& frame) {
    Hit hit;
    const std::uint32_t* v = &mesh.indices[3 * std::size_t{index}];
    const Vec3& p0 = mesh.positions[v[0]];
    const Vec3& p1 = mesh.positions[v[1]];
    const Vec3& p2 = mesh.positions[v[2]];
    const float b0 = at.b0, b1 = at.b1, b2 = at.b2;

    hit.t = at.t;
    hit.primitive = index;
    hit.p = b0 * p0 + b1 * p1 + b2 * p2;
    hit.pError = gamma(7) * (abs(b0 * p0) + abs(b1 * p1) + abs(b2 * p2));
    hit.ng = frame.ng;
    hit.ns = hit.ng;
    if (!mesh.normals.empty()) {
        const Vec3 ns = b0 * mesh.normals[v[0]] + b1 * mesh.normals[v[1]] + b2 * mesh.normals[v[2]];
        // A vertex without a normal (zero) makes the interpolation meaningless: keep the flat
        // normal.
        const bool complete = lengthSquared(mesh.normals[v[0]]) > 0 &&
                              lengthSquared(mesh.normals[v[1]]) > 0 &&
                              lengthSquared(mesh.normals[v[2]]) > 0;
        if (complete && lengthSquared(ns) > 0)
            hit.ns = dot(ns, hit.ng) < 0 ? -normalize(ns) : normalize(ns);
    }
    const auto [uv0, uv1, uv2] = vertexUvs(mesh, v);
    hit.setUv(b0 * uv0 + b1 * uv1 + b2 * uv2);
    hit.dpdu = frame.dpdu;
    hit.dpdv = frame.dpdv;
    if (!mesh.materials.empty()) hit.material = mesh.materials[mesh.faceMaterials[index]].get();
    return hit;
}

}  // namespace lancer
