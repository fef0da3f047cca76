#include "accel/Mesh.h"

#include <algorithm>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "geometry/Triangle.h"
#include "util/ParallelFor.h"

namespace lancer {

namespace {

constexpr std::size_t kGrainSize = 16 * 1024;

std::vector<Bounds3> triangleBounds(const TriangleMesh& mesh) {
    std::vector<Bounds3> bounds(mesh.triangleCount());
    parallelFor(bounds.size(), kGrainSize, [&](std::size_t i) {
        const std::uint32_t* v = &mesh.indices[3 * i];
        bounds[i] =
            merge(Bounds3(mesh.positions[v[0]], mesh.positions[v[1]]), mesh.positions[v[2]]);
    });
    return bounds;
}

// Puts the triangles in the order of the BVH's leaves.
void reorderTriangles(TriangleMesh& mesh, std::span<const std::uint32_t> order) {
    std::vector<std::uint32_t> indices(mesh.indices.size());
    std::vector<std::uint32_t> faceMaterials(mesh.faceMaterials.size());
    parallelFor(order.size(), kGrainSize, [&](std::size_t k) {
        for (std::size_t j = 0; j < 3; ++j)
            indices[3 * k + j] = mesh.indices[3 * std::size_t{order[k]} + j];
        faceMaterials[k] = mesh.faceMaterials[order[k]];
    });
    mesh.indices = std::move(indices);
    mesh.faceMaterials = std::move(faceMaterials);
}

std::uint32_t packCount(std::uint32_t triangleCount) {
    return (triangleCount + TrianglePack::kLanes - 1) / TrianglePack::kLanes;
}

// The lanes holding a leaf's triangles in the pack-th pack of a leaf of `count`.
int leafLanes(std::uint32_t pack, std::uint32_t count) {
    const std::uint32_t left = count - pack * TrianglePack::kLanes;
    return left >= TrianglePack::kLanes ? Float4::kAllLanes : (1 << left) - 1;
}

}  // namespace

Mesh::Mesh(TriangleMesh triangles) : Shape(nullptr), triangles_(std::move(triangles)) {
    // The binary tree (and its primitive order) is dropped once collapsed.
    const Bvh binary(triangleBounds(triangles_), Bvh::kDefaultMaxLeafSize, TrianglePack::kLanes);
    reorderTriangles(triangles_, binary.primitiveOrder());
    // Leaves get their packs in the order the collapse meets them, which keeps the leaves of a
    // node side by side in memory; the packs are filled afterwards, in parallel.
    struct Leaf {
        std::uint32_t first, count, firstPack;
    };
    std::vector<Leaf> leaves;
    std::uint32_t packsSoFar = 0;
    bvh_ = WideBvh(binary, [&](std::uint32_t first, std::uint32_t count) {
        leaves.push_back({first, count, packsSoFar});
        packsSoFar += packCount(count);
        return leaves.back().firstPack;
    });
    packs_.resize(packsSoFar);  // zeros in the lanes left over
    parallelFor(leaves.size(), kGrainSize, [&](std::size_t i) {
        const Leaf& leaf = leaves[i];
        for (std::uint32_t k = 0; k < leaf.count; ++k) {
            TrianglePack& pack = packs_[leaf.firstPack + k / TrianglePack::kLanes];
            const auto lane = static_cast<int>(k % TrianglePack::kLanes);
            const std::uint32_t triangle = leaf.first + k;
            const std::uint32_t* v = &triangles_.indices[3 * std::size_t{triangle}];
            pack.set(lane, triangles_.positions[v[0]], triangles_.positions[v[1]],
                     triangles_.positions[v[2]]);
            pack.triangle[lane] = triangle;
        }
    });
}

namespace {

// Why `triangles` cannot be a mesh's, or nothing.
const char* misfit(const TriangleMesh& triangles) {
    const std::size_t vertexCount = triangles.positions.size();
    if (triangles.indices.empty() || triangles.indices.size() % 3 != 0) return "no triangles";
    if ((!triangles.normals.empty() && triangles.normals.size() != vertexCount) ||
        (!triangles.uvs.empty() && triangles.uvs.size() != vertexCount))
        return "a vertex attribute is not given for every vertex";
    if (triangles.faceMaterials.size() != triangles.triangleCount())
        return "not every triangle has a material";
    for (const std::uint32_t vertex : triangles.indices)
        if (vertex >= vertexCount) return "a triangle's vertex is past the vertices";
    for (const std::uint32_t material : triangles.faceMaterials)
        if (material >= triangles.materials.size()) return "a triangle's material is missing";
    return nullptr;
}

}  // namespace

Mesh::Mesh(Parts parts) : Shape(nullptr), triangles_(std::move(parts.triangles)) {
    if (const char* why = misfit(triangles_)) throw std::invalid_argument(why);
    packs_ = std::move(parts.packs);
    const std::size_t triangleCount = triangles_.triangleCount();
    for (const TrianglePack& pack : packs_)
        for (const std::uint32_t triangle : pack.triangle)
            if (triangle >= triangleCount)
                throw std::invalid_argument("a pack's triangle is past the triangles");
    bvh_ = WideBvh(parts.bounds, std::move(parts.nodes),
                   [&](std::uint32_t firstPack, std::uint32_t count) {
                       return std::uint64_t{firstPack} + packCount(count) <= packs_.size();
                   });
}

void Mesh::prefetchPack(std::uint32_t pack) const {
    // Packs are 16-byte aligned, so one may start anywhere in a cache line.
    const auto* first = reinterpret_cast<const char*>(&packs_[pack]);
    for (std::size_t offset = 0; offset < sizeof(TrianglePack); offset += 64)
        prefetch(first + offset);
    prefetch(first + sizeof(TrianglePack) - 1);
}

std::optional<SurfaceCrossing> Mesh::cross(const Ray& ray, float tMax) const {
    const TriangleIntersector intersector(ray);
    if (!intersector.canHit()) return std::nullopt;
    // Only barycentrics and t during traversal; the hit record is filled once, for the nearest.
    TriangleIntersection nearest{};
    std::uint32_t nearestIndex = 0;
    // Inlined into each traversal kernel (WideBvh), and compiled with its instructions.
    const auto intersectLeaf = [&](std::uint32_t firstPack, std::uint32_t count,
                                   float& tFar) LANCER_INLINE_LAMBDA {
        bool found = false;
        for (std::uint32_t p = 0; p < packCount(count); ++p) {
            const TrianglePack& pack = packs_[firstPack + p];
            const PackHits hits = intersector.intersect(pack, leafLanes(p, count), tFar);
            if (hits.lanes == 0) continue;
            const int lane = hits.nearestLane();
            nearest = hits.at(lane);
            nearestIndex = pack.triangle[lane];
            tFar = nearest.t;
            found = true;
        }
        return found;
    };
    const auto prefetchLeaf = [&](std::uint32_t firstPack) { prefetchPack(firstPack); };
    if (!bvh_.intersect(ray, tMax, intersectLeaf, prefetchLeaf)) return std::nullopt;
    return SurfaceCrossing{nearest.t, nearest.t, nearestIndex, nearest.b0, nearest.b1, nearest.b2};
}

Hit Mesh::record(const Ray&, const SurfaceCrossing& crossing) const {
    Hit hit = Triangle::makeHit(
        triangles_, crossing.primitive,
        {crossing.b0, crossing.b1, crossing.b2, static_cast<float>(crossing.tShape)},
        Triangle::surfaceFrameOf(triangles_, crossing.primitive));
    hit.shape = this;
    return hit;
}

bool Mesh::occluded(const Ray& ray, float tMax) const {
    const TriangleIntersector intersector(ray);
    if (!intersector.canHit()) return false;
    const auto occludedLeaf = [&](std::uint32_t firstPack, std::uint32_t count,
                                  float tFar) LANCER_INLINE_LAMBDA {
        for (std::uint32_t p = 0; p < packCount(count); ++p)
            if (intersector.intersect(packs_[firstPack + p], leafLanes(p, count), tFar).lanes != 0)
                return true;
        return false;
    };
    const auto prefetchLeaf = [&](std::uint32_t firstPack) { prefetchPack(firstPack); };
    return bvh_.occluded(ray, tMax, occludedLeaf, prefetchLeaf);
}

void Mesh::crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const {
    const TriangleIntersector intersector(ray);
    if (!intersector.canHit()) return;
    const std::size_t first = crossings.size();
    const auto collectLeaf = [&](std::uint32_t firstPack, std::uint32_t count, float tFar) {
        for (std::uint32_t p = 0; p < packCount(count); ++p) {
            const TrianglePack& pack = packs_[firstPack + p];
            const PackHits hits = intersector.intersect(pack, leafLanes(p, count), tFar);
            for (int lane = 0; lane < TrianglePack::kLanes; ++lane)
                if (hits.lanes >> lane & 1)
                    crossings.push_back(SurfaceCrossing{hits.t[lane], hits.t[lane],
                                                        pack.triangle[lane], hits.b0[lane],
                                                        hits.b1[lane], hits.b2[lane]});
        }
        return false;  // every leaf the segment reaches
    };
    const auto prefetchLeaf = [&](std::uint32_t firstPack) { prefetchPack(firstPack); };
    bvh_.occluded(ray, tMax, collectLeaf, prefetchLeaf);
    // A line through an edge (or a vertex) meets every triangle there at the same t, computed
    // from the same shared vertices: one crossing of the surface.
    const auto begin = crossings.begin() + static_cast<std::ptrdiff_t>(first);
    std::sort(begin, crossings.end(),
              [](const SurfaceCrossing& a, const SurfaceCrossing& b) { return a.t < b.t; });
    crossings.erase(
        std::unique(begin, crossings.end(),
                    [](const SurfaceCrossing& a, const SurfaceCrossing& b) { return a.t == b.t; }),
        crossings.end());
}

void Mesh::crossLine(const Ray& ray, LineCrossings& crossings) const {
    // Every hit of the ray forward, and of its reverse backward, each tested from the ray's own
    // origin as cross() tests it: the signs of t are those cross() sees.
    std::array<LineCrossings, 2> halves;  // behind the origin, then ahead of it
    for (const int half : {0, 1}) {
        const float way = half == 0 ? -1.0f : 1.0f;
        const Ray halfRay{ray.origin, way * ray.direction};
        const TriangleIntersector intersector(halfRay);
        if (!intersector.canHit()) return;
        const auto collectLeaf = [&](std::uint32_t firstPack, std::uint32_t count, float tFar) {
            for (std::uint32_t p = 0; p < packCount(count); ++p) {
                const TrianglePack& pack = packs_[firstPack + p];
                const PackHits hits = intersector.intersect(pack, leafLanes(p, count), tFar);
                for (int lane = 0; lane < TrianglePack::kLanes; ++lane) {
                    if (!(hits.lanes >> lane & 1)) continue;
                    const std::uint32_t triangle = pack.triangle[lane];
                    const std::array<Vec3, 3> v = vertices(triangle);
                    const Vec3 front = lancer::cross(v[1] - v[0], v[2] - v[0]);
                    const double t = way * static_cast<double>(hits.t[lane]);
                    halves[half].push_back({SurfaceCrossing{t, t, triangle, hits.b0[lane],
                                                            hits.b1[lane], hits.b2[lane]},
                                            dot(ray.direction, front) < 0});
                }
            }
            return false;  // every leaf the ray reaches
        };
        const auto prefetchLeaf = [&](std::uint32_t firstPack) { prefetchPack(firstPack); };
        bvh_.occluded(halfRay, kInfinity, collectLeaf, prefetchLeaf);
        std::sort(halves[half].begin(), halves[half].end(),
                  [](const LineCrossing& a, const LineCrossing& b) {
                      return a.crossing.t < b.crossing.t;
                  });
    }
    // Along a line through a closed, outward-wound surface the crossings alternate, entering
    // first: two in a row of the same kind are one crossing counted by both triangles of an edge
    // (or the corners of a vertex) that the line passes through.
    bool inside = false;
    const auto add = [&](const LineCrossing& c) {
        if (c.entering == inside) return;
        crossings.push_back(c);
        inside = c.entering;
    };
    for (const LineCrossing& c : halves[0])
        add(c);
    // The surface a spawned ray leaves lies within rounding error of its origin, where both
    // tests reject t as not certainly of its sign: the alternation says when one was lost. It
    // comes back at t = 0, where nothing is recorded, only the inside changes.
    const LineCrossings& ahead = halves[1];
    if (ahead.empty() ? inside : ahead.front().entering == inside) {
        crossings.push_back({SurfaceCrossing{0, 0}, !inside});
        inside = !inside;
    }
    for (const LineCrossing& c : ahead)
        add(c);
}

bool Mesh::isSolid() const {
    // Closed: the vertices welded by position, every directed edge of a triangle is met once,
    // and once in the other direction by a neighbour (which also makes the winding consistent).
    std::vector<Vec3> positions = triangles_.positions;
    const auto before = [](const Vec3& a, const Vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    std::sort(positions.begin(), positions.end(), before);
    positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
    const auto welded = [&](std::uint32_t vertex) {
        const Vec3& p = triangles_.positions[vertex];
        return static_cast<std::uint32_t>(
            std::lower_bound(positions.begin(), positions.end(), p, before) - positions.begin());
    };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(triangles_.indices.size());
    for (std::size_t i = 0; i < triangles_.indices.size(); i += 3) {
        const std::array<std::uint32_t, 3> v{welded(triangles_.indices[i]),
                                             welded(triangles_.indices[i + 1]),
                                             welded(triangles_.indices[i + 2])};
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;  // no area: no surface
        for (int k = 0; k < 3; ++k)
            edges.emplace_back(v[k], v[(k + 1) % 3]);
    }
    if (edges.empty()) return false;
    std::sort(edges.begin(), edges.end());
    if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;
    return std::all_of(edges.begin(), edges.end(), [&](const auto& edge) {
        return std::binary_search(edges.begin(), edges.end(), std::pair{edge.second, edge.first});
    });
}

const Material* Mesh::primitiveMaterial(std::uint32_t triangle) const {
    return triangles_.materials.empty()
               ? material()
               : triangles_.materials[triangles_.faceMaterials[triangle]].get();
}

std::array<Vec3, 3> Mesh::vertices(std::uint32_t triangle) const {
    const std::uint32_t* v = &triangles_.indices[3 * std::size_t{triangle}];
    const std::vector<Vec3>& p = triangles_.positions;
    return {p[v[0]], p[v[1]], p[v[2]]};
}

float Mesh::area(std::uint32_t triangle) const {
    return Triangle::areaOf(vertices(triangle));
}

std::optional<ShapeSample> Mesh::sample(std::uint32_t triangle, const Vec2& u) const {
    return Triangle::sampleUniformly(vertices(triangle), u);
}

Tessellation Mesh::tessellate(const TessellationRequest&) const {
    Tessellation tessellation;
    tessellation.facets.reserve(triangles_.triangleCount());
    for (std::uint32_t i = 0; i < primitiveCount(); ++i)
        tessellation.facets.push_back({vertices(i), i});
    return tessellation;
}

std::size_t Mesh::memoryBytes() const {
    const TriangleMesh& m = triangles_;
    return m.positions.size() * sizeof(Vec3) + m.normals.size() * sizeof(Vec3) +
           m.uvs.size() * sizeof(Vec2) + m.indices.size() * sizeof(std::uint32_t) +
           m.faceMaterials.size() * sizeof(std::uint32_t) + bvh_.memoryBytes() +
           packs_.size() * sizeof(TrianglePack);
}

}  // namespace lancer
