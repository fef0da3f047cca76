// lancer::Mesh on every model the project ships, against brute force over its triangles; empty and
// single-triangle meshes; and watertightness: rays aimed exactly at the shared edges and vertices
// of closed meshes, directly and through transformed instances, never slip through.

#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "BvhTestSupport.h"
#include "IntersectInto.h"
#include "accel/Mesh.h"
#include "geometry/Hit.h"
#include "geometry/Instance.h"
#include "geometry/Triangle.h"
#include "geometry/TriangleMesh.h"
#include "io/ObjLoader.h"
#include "materials/BlinnPhongMaterial.h"
#include "materials/ConstantTexture.h"
#include "math/Transform.h"

namespace lancer::test {
namespace {

namespace fs = std::filesystem;

// The issue asks for 100k rays per model; the sanitizers make everything about 3x slower.
#ifdef LANCER_SANITIZED
constexpr int kRayCount = 30000;
#else
constexpr int kRayCount = 100000;
#endif

fs::path sceneModel(const std::string& relativePath) {
    return fs::path(LANCER_SCENE_MODELS) / relativePath;
}

// Every OBJ under scenes/models (the Cornell boxes included), in a fixed order.
std::vector<fs::path> shippedModels() {
    std::vector<fs::path> models;
    for (const auto& entry : fs::recursive_directory_iterator(sceneModel("")))
        if (entry.is_regular_file() && entry.path().extension() == ".obj")
            models.push_back(entry.path());
    std::sort(models.begin(), models.end());
    return models;
}

std::shared_ptr<TriangleMesh> loadModel(const fs::path& path) {
    // Textures play no part in intersection.
    const auto constantTexture = [](const fs::path&,
                                    ImageReader::Content) -> std::shared_ptr<const Texture> {
        return std::make_shared<ConstantTexture>(Color(0.5f));
    };
    std::vector<std::string> warnings;  // the spider's dropped zero-area triangles, for one
    return ObjLoader::load(path, constantTexture, warnings);
}

TriangleSoup soupOf(const TriangleMesh& mesh) {
    TriangleSoup soup;
    for (std::size_t i = 0; i < mesh.triangleCount(); ++i)
        soup.add(mesh.positions[mesh.indices[3 * i]], mesh.positions[mesh.indices[3 * i + 1]],
                 mesh.positions[mesh.indices[3 * i + 2]]);
    return soup;
}

// A mesh of the triangles of a soup, sharing no vertices (neighbours share exact positions).
TriangleMesh meshOf(const TriangleSoup& soup) {
    TriangleMesh mesh;
    mesh.positions = soup.vertices;
    for (std::uint32_t i = 0; i < mesh.positions.size(); ++i)
        mesh.indices.push_back(i);
    mesh.faceMaterials.assign(soup.size(), 0);  // the mesh reorders one per triangle
    return mesh;
}

// A model as a lancer::Mesh, and its triangles in the file's order for brute force. A hit record
// does not name its triangle, and the mesh reorders them; so each triangle is given a material of
// its own, which the mesh moves with it and puts in the hit (intersection never looks at it).
class TaggedMesh {
public:
    explicit TaggedMesh(const TriangleMesh& triangles)
        : soup_(soupOf(triangles)),
          bounds_(soup_.bounds()),
          bruteForce_(bounds_),
          mesh_(withMaterialPerTriangle(triangles, triangleOf_)) {}

    const Mesh& mesh() const { return mesh_; }
    const TriangleSoup& soup() const { return soup_; }
    std::span<const Bounds3> triangleBounds() const { return bounds_; }

    ClosestHit bruteForceClosest(const Ray& ray) const {
        return bruteForce_.closest(ray, [&](std::uint32_t i, const Ray& r, float tMax) {
            return soup_.intersect(i, r, tMax);
        });
    }
    // The mesh's closest hit, with the triangle's index in the file's order.
    ClosestHit meshClosest(const Ray& ray) const {
        Hit hit;
        if (!intersectInto(mesh_, ray, kInfinity, hit)) return {};
        return {hit.t, triangleOf_.at(hit.material)};
    }

private:
    static TriangleMesh withMaterialPerTriangle(
        TriangleMesh mesh, std::unordered_map<const Material*, std::uint32_t>& triangleOf) {
        mesh.materials.clear();
        mesh.faceMaterials.clear();
        for (std::uint32_t i = 0; i < mesh.triangleCount(); ++i) {
            auto material = std::make_shared<const BlinnPhongMaterial>();
            triangleOf[material.get()] = i;
            mesh.materials.push_back(std::move(material));
            mesh.faceMaterials.push_back(i);
        }
        return mesh;
    }

    TriangleSoup soup_;
    std::vector<Bounds3> bounds_;
    BruteForce bruteForce_;
    std::unordered_map<const Material*, std::uint32_t> triangleOf_;
    Mesh mesh_;
};

// Half of randomRays (from around the box in random directions, and from outside towards random
// points in it), half from inside and around the box towards random triangles: a quarter of those
// at a vertex, a quarter at a point of an edge (where neighbours tie), the rest inside.
std::vector<Ray> modelRays(const TriangleSoup& soup, const Bounds3& box, int count,
                           std::uint32_t seed) {
    std::vector<Ray> rays = randomRays(box, count / 2, seed);
    std::mt19937 rng(seed + 1);
    std::uniform_int_distribution<std::uint32_t> pickTriangle(0, soup.size() - 1);
    std::uniform_int_distribution<int> pickCorner(0, 2);
    std::uniform_real_distribution<float> u(0, 1);
    const Bounds3 around = enlarged(box, 0.2f);
    while (rays.size() < static_cast<std::size_t>(count)) {
        const Vec3* v = &soup.vertices[3 * std::size_t{pickTriangle(rng)}];
        const Vec3& a = v[pickCorner(rng)];
        const Vec3& b = v[pickCorner(rng)];
        Vec3 target;
        switch (rays.size() % 4) {
            case 0:
                target = a;
                break;
            case 1:
                target = a + u(rng) * (b - a);
                break;
            default: {
                // Uniform on the triangle.
                const float s = std::sqrt(u(rng)), w = u(rng);
                target = (1 - s) * v[0] + s * (1 - w) * v[1] + s * w * v[2];
            }
        }
        const Vec3 origin = randomPointIn(around, rng);
        if (origin != target) rays.push_back({origin, target - origin});
    }
    return rays;
}

// Checks every ray: the mesh's closest hit is brute force's (the same t to the bit, the same
// triangle unless another is hit at exactly that t, on an edge or vertex they share), and
// occluded(ray, tMax) == (closest t < tMax) for tMax beyond, after, at and before that t.
void expectMatchesBruteForce(const TaggedMesh& tagged, const std::vector<Ray>& rays) {
    const auto tMaxes = [](float t) {
        return std::array<float, 4>{kInfinity, 1.5f * t, t, 0.5f * t};
    };
    struct Result {
        ClosestHit expected, actual;
        std::array<bool, 4> occluded;
    };
    std::vector<Result> results(rays.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size()), [&](const auto& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            Result& r = results[i];
            r.expected = tagged.bruteForceClosest(rays[i]);
            r.actual = tagged.meshClosest(rays[i]);
            const auto tMax = tMaxes(r.expected.t);
            for (std::size_t k = 0; k < tMax.size(); ++k)
                r.occluded[k] = tagged.mesh().occluded(rays[i], tMax[k]);
        }
    });

    int ties = 0, failures = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Result& r = results[i];
        std::ostringstream wrong;
        const bool sameT =
            std::bit_cast<std::uint32_t>(r.actual.t) == std::bit_cast<std::uint32_t>(r.expected.t);
        const bool sameTriangle = r.actual.primitive == r.expected.primitive;
        // Another triangle hit at exactly that t (on an edge or vertex they share) is as right.
        const bool tie = sameT && !sameTriangle && r.actual.primitive >= 0 &&
                         tagged.soup().intersect(static_cast<std::uint32_t>(r.actual.primitive),
                                                 rays[i], kInfinity) == r.expected.t;
        ties += tie;
        if (!sameT || !(sameTriangle || tie))
            wrong << ": the mesh's closest hit is " << describe(r.actual) << ", brute force's "
                  << describe(r.expected);
        const auto tMax = tMaxes(r.expected.t);
        for (std::size_t k = 0; k < tMax.size(); ++k)
            if (r.occluded[k] != (r.expected.t < tMax[k]))
                wrong << ": occluded before tMax = " << std::hexfloat << tMax[k] << " is "
                      << r.occluded[k] << ", the closest hit being " << describe(r.expected);
        if (wrong.tellp() > 0 && ++failures <= 10)
            ADD_FAILURE() << "ray " << i << " " << describe(rays[i]) << wrong.str();
    }
    EXPECT_EQ(failures, 0) << "rays wrong, of " << rays.size();
    // Rays that all miss would prove nothing.
    const auto hits = std::count_if(results.begin(), results.end(),
                                    [](const Result& r) { return r.expected.primitive >= 0; });
    EXPECT_GT(hits, static_cast<std::ptrdiff_t>(rays.size() / 10));
    testing::Test::RecordProperty("hits", static_cast<int>(hits));
    testing::Test::RecordProperty("ties", ties);
}

class ShippedModel : public testing::TestWithParam<fs::path> {};

TEST_P(ShippedModel, MeshMatchesBruteForce) {
    const TaggedMesh tagged(*loadModel(GetParam()));
    ASSERT_GT(tagged.soup().size(), 0u);
    Bounds3 box;
    for (const Bounds3& b : tagged.triangleBounds())
        box = merge(box, b);
    EXPECT_EQ(tagged.mesh().bounds().min, box.min);
    EXPECT_EQ(tagged.mesh().bounds().max, box.max);
    expectMatchesBruteForce(tagged, modelRays(tagged.soup(), box, kRayCount, 1));
}

INSTANTIATE_TEST_SUITE_P(SharedMesh, ShippedModel, testing::ValuesIn(shippedModels()),
                         [](const testing::TestParamInfo<fs::path>& model) {
                             std::string name = model.param.stem().string();
                             std::erase_if(name, [](char c) {
                                 return !std::isalnum(static_cast<unsigned char>(c));
                             });
                             return name;
                         });

TEST(SharedMesh, EveryShippedModelIsTested) {
    std::set<std::string> folders;
    for (const fs::path& model : shippedModels())
        folders.insert(model.parent_path().filename().string());
    EXPECT_EQ(folders, (std::set<std::string>{"cornell_box", "spider", "spot",
                                              "stanford_bunny_lowres", "utah_teapot"}));
    EXPECT_GE(shippedModels().size(), 8u);
}

TEST(SharedMesh, EmptyMeshIsNeverHit) {
    const Mesh mesh{TriangleMesh{}};
    EXPECT_EQ(mesh.triangles().triangleCount(), 0u);
    EXPECT_TRUE(mesh.bounds().isEmpty());
    for (const Ray& ray : randomRays({Vec3(-1), Vec3(1)}, 1000, 2)) {
        Hit hit;
        EXPECT_FALSE(intersectInto(mesh, ray, kInfinity, hit));
        EXPECT_EQ(hit.t, kInfinity) << "the hit record is left untouched";
        EXPECT_FALSE(mesh.occluded(ray, kInfinity));
    }
}

TEST(SharedMesh, SingleTriangleMatchesBruteForce) {
    TriangleSoup one;
    one.add({0.1234f, -0.567f, 0.891f}, {1.357f, 0.2468f, -0.135f}, {-0.975f, 1.0864f, 0.4321f});
    const TaggedMesh tagged(meshOf(one));
    const Bounds3 box = one.triangleBounds(0);
    EXPECT_EQ(tagged.mesh().bounds().min, box.min);
    EXPECT_EQ(tagged.mesh().bounds().max, box.max);
    expectMatchesBruteForce(tagged, modelRays(one, box, 20000, 3));

    // Hit from either side through its centroid, where the triangle test says.
    const Vec3 centroid = (one.vertices[0] + one.vertices[1] + one.vertices[2]) / 3.0f;
    const Vec3 normal = cross(one.vertices[1] - one.vertices[0], one.vertices[2] - one.vertices[0]);
    for (const Vec3& origin : {centroid + normal, centroid - normal}) {
        const Ray ray{origin, centroid - origin};
        Hit hit;
        ASSERT_TRUE(intersectInto(tagged.mesh(), ray, kInfinity, hit));
        EXPECT_EQ(hit.t, one.intersect(0, ray, kInfinity));
        EXPECT_NEAR(hit.t, 1, 1e-6);
        EXPECT_TRUE(tagged.mesh().occluded(ray, kInfinity));
    }
}

// A closed mesh's surface: its triangles joined by exact vertex position (the loader splits a
// vertex that has several uvs), with the triangles on each edge and around each vertex.
struct Surface {
    std::vector<Vec3> points;
    std::vector<std::array<std::uint32_t, 3>> triangles;      // into points, in the mesh's order
    std::vector<std::vector<std::uint32_t>> trianglesAround;  // per point
    // Per directed edge (from, to), the triangles that go round it that way.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edges;
};

Surface surfaceOf(const TriangleMesh& mesh) {
    Surface surface;
    const auto byValue = [](const Vec3& a, const Vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    std::map<Vec3, std::uint32_t, decltype(byValue)> pointOf(byValue);
    for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
        std::array<std::uint32_t, 3> corners;
        for (std::size_t j = 0; j < 3; ++j) {
            const Vec3& p = mesh.positions[mesh.indices[3 * t + j]];
            const auto [it, inserted] =
                pointOf.try_emplace(p, static_cast<std::uint32_t>(surface.points.size()));
            if (inserted) {
                surface.points.push_back(p);
                surface.trianglesAround.emplace_back();
            }
            corners[j] = it->second;
            surface.trianglesAround[it->second].push_back(t);
        }
        surface.triangles.push_back(corners);
        for (std::size_t j = 0; j < 3; ++j)
            surface.edges[{corners[j], corners[(j + 1) % 3]}].push_back(t);
    }
    return surface;
}

// Closed and consistently oriented: every edge is used by exactly one triangle each way round.
testing::AssertionResult isClosed(const Surface& surface) {
    for (const auto& [edge, triangles] : surface.edges) {
        const auto opposite = surface.edges.find({edge.second, edge.first});
        if (triangles.size() != 1 || opposite == surface.edges.end() ||
            opposite->second.size() != 1)
            return testing::AssertionFailure()
                   << "edge between points " << edge.first << " and " << edge.second << " has "
                   << triangles.size() << " triangles one way, "
                   << (opposite == surface.edges.end() ? 0 : opposite->second.size())
                   << " the other";
    }
    return testing::AssertionSuccess();
}

// A point on the surface to aim at, computed in float as a renderer would, and the triangles that
// meet there.
struct Aim {
    const char* what;  // "a vertex", "an edge midpoint"...
    Vec3 point;
    std::vector<std::uint32_t> triangles;
};

// The midpoint and two random points a + s (b - a) of every edge, and every vertex.
std::vector<Aim> aimsAt(const Surface& surface, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> s(0, 1);
    std::vector<Aim> aims;
    for (const auto& [edge, triangles] : surface.edges) {
        if (edge.first > edge.second) continue;  // each edge once
        const Vec3& a = surface.points[edge.first];
        const Vec3& b = surface.points[edge.second];
        const std::vector<std::uint32_t> both = {triangles[0],
                                                 surface.edges.at({edge.second, edge.first})[0]};
        aims.push_back({"an edge midpoint", a + 0.5f * (b - a), both});
        for (int k = 0; k < 2; ++k)
            aims.push_back({"a point on an edge", a + s(rng) * (b - a), both});
    }
    for (std::uint32_t v = 0; v < surface.points.size(); ++v)
        aims.push_back({"a vertex", surface.points[v], surface.trianglesAround[v]});
    return aims;
}

// Whether a ray along d through a point where these triangles meet passes through the surface
// there, rather than grazing it (at a silhouette): when all of them clearly face it the same way,
// their projections along d cover the point's surroundings (the surface is consistently oriented).
bool passesThrough(const std::vector<Vec3d>& points, const Surface& surface,
                   const std::vector<std::uint32_t>& triangles, const Vec3d& d) {
    int front = 0, back = 0;
    for (const std::uint32_t t : triangles) {
        const auto& [i0, i1, i2] = surface.triangles[t];
        const Vec3d n = cross(points[i1] - points[i0], points[i2] - points[i0]);
        const double cosine = dot(n, d) / (length(n) * length(d));
        front += cosine < -0.05;
        back += cosine > 0.05;
    }
    const int count = static_cast<int>(triangles.size());
    return front == count || back == count;
}

// The aimed point is off the true edge by the rounding of a + s (b - a) and of the transform, which
// moves the crossing along the ray by far less than this (in t, the aim being at t = 1); a ray that
// slipped through would meet the surface again on its far side, or nowhere.
constexpr float kAimTolerance = 1e-3f;

// Aims rays at every aim from random origins outside the shape, each reaching its aim at t = 1,
// and expects every one that passes through the surface there to be stopped at t <= 1 (within
// the tolerance): by the aimed point or, on a concave surface, by some part in front of it.
void expectNoRaySlipsThrough(const Shape& shape, const Surface& surface,
                             const Transform& objectToWorld, int originsPerAim,
                             std::uint32_t seed) {
    std::vector<Vec3d> worldPoints;
    for (const Vec3& p : surface.points)
        worldPoints.emplace_back(objectToWorld.applyPoint(p));
    const std::vector<Aim> aims = aimsAt(surface, seed);
    const Bounds3 box = shape.bounds();
    const float radius = length(box.diagonal());  // twice what the box needs

    std::mt19937 rng(seed);
    std::vector<Ray> rays;
    rays.reserve(aims.size() * static_cast<std::size_t>(originsPerAim));
    for (const Aim& aim : aims) {
        // For an instance, the point that the shape's own point becomes in the world.
        const Vec3 target = objectToWorld.applyPoint(aim.point);
        for (int k = 0; k < originsPerAim; ++k) {
            const Vec3 origin = box.centroid() + radius * randomDirection(rng);
            rays.push_back({origin, target - origin});
        }
    }
    const auto aimOf = [&](std::size_t ray) -> const Aim& {
        return aims[ray / static_cast<std::size_t>(originsPerAim)];
    };

    struct Result {
        bool passesThrough;
        float t;  // of the closest hit; infinity for none
        bool occluded;
    };
    std::vector<Result> results(rays.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size()), [&](const auto& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            Result& r = results[i];
            r.passesThrough =
                passesThrough(worldPoints, surface, aimOf(i).triangles, Vec3d(rays[i].direction));
            Hit hit;
            r.t = intersectInto(shape, rays[i], kInfinity, hit) ? hit.t : kInfinity;
            r.occluded = shape.occluded(rays[i], 1 + kAimTolerance);
        }
    });

    int tested = 0, atTheAim = 0, failures = 0;
    for (std::size_t i = 0; i < results.size(); ++i) {
        const Result& r = results[i];
        if (!r.passesThrough) continue;
        ++tested;
        atTheAim += r.t >= 1 - kAimTolerance && r.t <= 1 + kAimTolerance;
        if (r.t <= 1 + kAimTolerance && r.occluded) continue;
        if (++failures > 10) continue;  // the first ten tell enough
        const Aim& aim = aimOf(i);
        ADD_FAILURE() << std::setprecision(9) << "ray " << describe(rays[i]) << " aimed at "
                      << aim.what << " (" << aim.point.x << ", " << aim.point.y << ", "
                      << aim.point.z << ") slips through: closest hit at t = " << r.t
                      << ", occluded up to the aim: " << r.occluded;
    }
    EXPECT_EQ(failures, 0) << "rays slipped through, of " << tested;
    // Most rays must pass through, and many reach their aim unobstructed: else little was tested.
    EXPECT_GT(tested, static_cast<int>(results.size() / 2));
    EXPECT_GT(atTheAim, tested / 4);
}

// Watertightness through the mesh itself and through two instances of it: one rotated, scaled
// unevenly and moved, one mirrored (which turns its triangles' orientation round).
void expectWatertight(const TriangleMesh& triangles) {
    const Surface surface = surfaceOf(triangles);
    ASSERT_TRUE(isClosed(surface));
    const auto mesh = std::make_shared<const Mesh>(triangles);
    {
        SCOPED_TRACE("mesh");
        expectNoRaySlipsThrough(*mesh, surface, Transform(), 8, 4);
    }
    const float size = length(mesh->bounds().diagonal());
    const Transform transforms[] = {
        Transform::translate(size * Vec3(0.37f, -1.91f, 2.53f)) *
            Transform::rotate(41.3f, Vec3(0.3f, -0.8f, 0.5f)) *
            Transform::scale(Vec3(1.7f, 0.45f, 1.15f)),
        Transform::rotate(-73.9f, Vec3(1.1f, 0.2f, 0.7f)) * Transform::scale(Vec3(-0.8f, 1, 1.3f)),
    };
    for (const Transform& objectToWorld : transforms) {
        SCOPED_TRACE(&objectToWorld == &transforms[0] ? "instance" : "mirrored instance");
        expectNoRaySlipsThrough(Instance(mesh, objectToWorld), surface, objectToWorld, 4, 5);
    }
}

TEST(Watertight, SpotNeverLetsARayThroughItsEdgesOrVertices) {
    expectWatertight(*loadModel(sceneModel("spot/spot_textured.obj")));
}

TEST(Watertight, BunnyNeverLetsARayThroughItsEdgesOrVertices) {
    expectWatertight(*loadModel(sceneModel("stanford_bunny_lowres/bunny.obj")));
}

TEST(Watertight, BumpySphereNeverLetsARayThroughItsEdgesOrVertices) {
    expectWatertight(meshOf(bumpySphere(4)));  // 5120 triangles
}

}  // namespace
}  // namespace lancer::test
