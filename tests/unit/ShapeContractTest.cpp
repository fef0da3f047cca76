// What the Shape interface promises, checked on every shape alike: each hit record is complete
// and fresh (every field set, dpdu/dpdv the derivatives of the surface's own uv
// parameterisation), samples lie on the surface with the density they claim, and the solid-angle
// densities integrate to one over the directions that see the shape.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "TestSupport.h"
#include "accel/Mesh.h"
#include "geometry/Box.h"
#include "geometry/Cone.h"
#include "geometry/Csg.h"
#include "geometry/Cylinder.h"
#include "geometry/Disk.h"
#include "geometry/Instance.h"
#include "geometry/Plane.h"
#include "geometry/Quad.h"
#include "geometry/Sphere.h"
#include "geometry/Torus.h"
#include "geometry/Triangle.h"
#include "materials/BlinnPhongMaterial.h"
#include "math/Transform.h"

namespace lancer {
namespace {

using test::Random;

const BlinnPhongMaterial kMaterial;

struct ShapeCase {
    std::string name;
    std::function<std::unique_ptr<Shape>()> make;
    // Whether every point the area sampling picks is the first surface seen from outside along
    // its direction (so that the solid-angle densities integrate to one).
    bool samplesAreVisible;
    // Whether area samples can fall where there is no surface (on a CSG child's hidden part),
    // and give nothing.
    bool samplesCanMiss = false;
};

std::unique_ptr<Shape> makeMesh() {
    TriangleMesh m;
    m.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0.5f, 1}, {-1, 0.5f, 1}};
    m.uvs = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
    m.indices = {0, 2, 1, 0, 3, 2};
    m.faceMaterials = {0, 0};
    return std::make_unique<Mesh>(std::move(m));
}

// A cube of side 1.6 about c, its faces' vertices not shared (as a model with face normals
// comes): a closed surface once welded.
std::unique_ptr<Shape> makeClosedMesh(const Vec3& c) {
    TriangleMesh m;
    for (int axis = 0; axis < 3; ++axis)
        for (const float side : {-1.0f, 1.0f}) {
            Vec3 n, u, v;
            n[axis] = side;
            u[(axis + 1) % 3] = 1;
            v[(axis + 2) % 3] = side;  // u x v = n: counter-clockwise seen from outside
            const auto first = static_cast<std::uint32_t>(m.positions.size());
            for (const auto& [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
                m.positions.push_back(
                    c + 0.8f * (n + static_cast<float>(a) * u + static_cast<float>(b) * v));
            for (const std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u})
                m.indices.push_back(first + k);
            m.faceMaterials.insert(m.faceMaterials.end(), {0, 0});
        }
    return std::make_unique<Mesh>(std::move(m));
}

std::unique_ptr<Shape> makeCsg(Csg::Operation operation, std::unique_ptr<Shape> a,
                               std::unique_ptr<Shape> b) {
    return test::combine(operation, std::move(a), std::move(b), &kMaterial);
}

std::vector<ShapeCase> shapeCases() {
    const Transform stretchAndTurn = Transform::translate(Vec3(0.5f, -0.25f, 0.3f)) *
                                     Transform::rotate(35, Vec3(1, 2, 0.5f)) *
                                     Transform::scale(Vec3(1.5f, 0.75f, 1));
    return {
        {"Sphere",
         [] { return std::make_unique<Sphere>(Vec3(0.2f, -0.1f, 0.3f), 0.8f, &kMaterial); }, true},
        {"Plane",
         [] { return std::make_unique<Plane>(Vec3(0, -0.5f, 0), Vec3(0.2f, 1, 0.1f), &kMaterial); },
         true},
        {"Quad",
         [] {
             return std::make_unique<Quad>(Vec3(-1, 0, -0.5f), Vec3(2, 0.2f, 0),
                                           Vec3(0.1f, 0.3f, 1.2f), &kMaterial);
         },
         true},
        {"Triangle",
         [] {
             return std::make_unique<Triangle>(
                 std::array<Vec3, 3>{Vec3(-1, 0, -1), Vec3(1, 0.2f, -0.8f), Vec3(0, 0.5f, 1)},
                 &kMaterial, std::nullopt,
                 std::array<Vec2, 3>{Vec2(0.1f, 0.2f), Vec2(0.9f, 0.1f), Vec2(0.4f, 0.8f)});
         },
         true},
        {"Mesh", makeMesh, true},
        {"Disk",
         [] {
             return std::make_unique<Disk>(Vec3(0.1f, 0.2f, -0.3f), Vec3(0.3f, 1, 0.2f), 1.2f, 0,
                                           &kMaterial);
         },
         true},
        {"Annulus",
         [] { return std::make_unique<Disk>(Vec3(0), Vec3(-0.5f, 0.2f, 1), 1, 0.4f, &kMaterial); },
         true},
        // Samples on the faces turned away from the reference are hidden by the others.
        {"Box",
         [] {
             return std::make_unique<Box>(Vec3(-0.6f, -0.2f, -0.9f), Vec3(0.7f, 0.5f, 0.4f),
                                          &kMaterial);
         },
         false},
        {"InstancedBox",
         [=] {
             return std::make_unique<Instance>(
                 std::make_shared<Box>(Vec3(-1), Vec3(0.5f, 1, 1), nullptr), stretchAndTurn,
                 &kMaterial);
         },
         false},
        {"Cylinder",
         [] {
             return std::make_unique<Cylinder>(Vec3(0.1f, -0.6f, 0.2f), Vec3(-0.3f, 0.7f, 0.1f),
                                               0.5f, false, &kMaterial);
         },
         false},
        {"OpenCylinder",
         [] {
             return std::make_unique<Cylinder>(Vec3(0, -1, 0), Vec3(0, 1, 0), 0.7f, true,
                                               &kMaterial);
         },
         false},
        {"TruncatedCone",
         [] {
             return std::make_unique<Cone>(Vec3(0.2f, -0.5f, 0), 0.9f, Vec3(0, 0.6f, 0.3f), 0.3f,
                                           false, &kMaterial);
         },
         false},
        {"PointedCone",
         [] {
             return std::make_unique<Cone>(Vec3(0, -0.5f, 0), 0.8f, Vec3(0.2f, 0.9f, 0), 0, false,
                                           &kMaterial);
         },
         false},
        {"InstancedCone",
         [=] {
             return std::make_unique<Instance>(
                 std::make_shared<Cone>(Vec3(0, -0.5f, 0), 0.4f, Vec3(0, 0.5f, 0), 0.8f, false,
                                        nullptr),
                 stretchAndTurn, &kMaterial);
         },
         false},
        // Samples on the far side of the tube, or across the hole, are hidden by the near side.
        {"Torus",
         [] {
             return std::make_unique<Torus>(Vec3(0.1f, -0.2f, 0.15f), Vec3(0.3f, 1, -0.4f), 0.8f,
                                            0.3f, &kMaterial);
         },
         false},
        {"InstancedTorus",
         [=] {
             return std::make_unique<Instance>(
                 std::make_shared<Torus>(Vec3(0), Vec3(0, 1, 0), 0.7f, 0.25f, nullptr),
                 stretchAndTurn, &kMaterial);
         },
         false},
        {"InstancedSphere",
         [=] {
             return std::make_unique<Instance>(std::make_shared<Sphere>(Vec3(0), 0.7f, nullptr),
                                               stretchAndTurn, &kMaterial);
         },
         false},
        {"InstancedQuad",
         [=] {
             return std::make_unique<Instance>(
                 std::make_shared<Quad>(Vec3(-1, 0, -1), Vec3(2, 0, 0), Vec3(0, 0, 2), nullptr),
                 stretchAndTurn, &kMaterial);
         },
         true},
        {"InstancedMesh",
         [=] {
             return std::make_unique<Instance>(std::shared_ptr<Shape>(makeMesh()), stretchAndTurn,
                                               &kMaterial);
         },
         true},
        {"ClosedMesh", [] { return makeClosedMesh(Vec3(0.1f, -0.2f, 0.3f)); }, false},
        // A lens: the intersection of two spheres.
        {"CsgIntersection",
         [] {
             return makeCsg(Csg::Operation::kIntersection,
                            std::make_unique<Sphere>(Vec3(0, 0, -0.5f), 1, &kMaterial),
                            std::make_unique<Sphere>(Vec3(0, 0, 0.5f), 1, &kMaterial));
         },
         false, true},
        {"CsgUnion",
         [] {
             return makeCsg(
                 Csg::Operation::kUnion,
                 std::make_unique<Box>(Vec3(-1, -0.5f, -0.5f), Vec3(0.3f, 0.5f, 0.5f), &kMaterial),
                 std::make_unique<Sphere>(Vec3(0.4f, 0.1f, 0), 0.7f, &kMaterial));
         },
         false, true},
        // A box with a hole through it, a turned cylinder carving it.
        {"CsgDifference",
         [=] {
             return makeCsg(Csg::Operation::kDifference,
                            std::make_unique<Box>(Vec3(-0.8f), Vec3(0.8f), &kMaterial),
                            std::make_unique<Instance>(
                                std::make_shared<Cylinder>(Vec3(0, -1, 0), Vec3(0, 1, 0), 0.4f,
                                                           false, &kMaterial),
                                Transform::rotate(30, Vec3(1, 0, 0.2f))));
         },
         false, true},
        // Nested and placed: (torus minus a closed mesh) under a transform.
        {"InstancedNestedCsg",
         [=] {
             std::shared_ptr<Shape> inner =
                 makeCsg(Csg::Operation::kDifference,
                         std::make_unique<Torus>(Vec3(0), Vec3(0, 1, 0), 0.8f, 0.3f, &kMaterial),
                         makeClosedMesh(Vec3(0.8f, 0, 0)));
             return std::make_unique<Instance>(
                 makeCsg(Csg::Operation::kUnion, std::make_unique<Instance>(inner, Transform()),
                         std::make_unique<Cone>(Vec3(0, -0.2f, 0), 0.4f, Vec3(0, 0.6f, 0), 0.1f,
                                                false, &kMaterial)),
                 stretchAndTurn, nullptr);
         },
         false, true},
    };
}

class ShapeContract : public testing::TestWithParam<ShapeCase> {
protected:
    void SetUp() override { shape = GetParam().make(); }

    // Points of the surface to aim at: samples of the bounded shapes, a patch of the plane.
    Vec3 target(Random& random) const {
        const Vec2 u(static_cast<float>(random.uniform(0.05, 0.95)),
                     static_cast<float>(random.uniform(0.05, 0.95)));
        const std::uint32_t primitive =
            static_cast<std::uint32_t>(random.uniform() * shape->primitiveCount()) %
            shape->primitiveCount();
        if (const auto s = shape->sample(primitive, u)) return s->p;
        return Vec3(4 * u.x - 2, -0.5f, 4 * u.y - 2);  // on the plane, nearly
    }

    std::unique_ptr<Shape> shape;
};

TEST_P(ShapeContract, EveryFieldOfTheRecordIsSet) {
    Random random(7);
    for (int i = 0; i < 200; ++i) {
        const Vec3 aim = target(random);
        const Vec3 origin = aim + 5.0f * random.unitVector();
        const Ray ray{origin, normalize(aim - origin)};
        const std::optional<Hit> hit = shape->intersect(ray, kInfinity);
        if (!hit) continue;
        EXPECT_GT(hit->t, 0);
        EXPECT_LT(length(hit->p - ray.at(hit->t)), 1e-4f);
        EXPECT_NEAR(length(hit->ng), 1, 1e-5f);
        EXPECT_NEAR(length(hit->ns), 1, 1e-5f);
        EXPECT_GT(dot(hit->ns, hit->ng), 0);
        EXPECT_TRUE(isFinite(hit->pError) && hit->pError.x >= 0 && hit->pError.y >= 0 &&
                    hit->pError.z >= 0);
        EXPECT_GT(lengthSquared(cross(hit->dpdu, hit->dpdv)), 0)
            << "dpdu and dpdv span the surface";
        EXPECT_NEAR(dot(hit->dpdu, hit->ng), 0, 1e-3f * length(hit->dpdu));
        EXPECT_NEAR(dot(hit->dpdv, hit->ng), 0, 1e-3f * length(hit->dpdv));
        EXPECT_TRUE(std::isfinite(hit->uv().x) && std::isfinite(hit->uv().y));
        EXPECT_EQ(hit->shape, shape.get());
        ASSERT_LT(hit->primitive, shape->primitiveCount());
        EXPECT_EQ(hit->material, shape->primitiveMaterial(hit->primitive));
        EXPECT_EQ(hit->dudx, 0);  // the footprint is the integrator's
        // The first phase alone finds the same crossing.
        const std::optional<SurfaceCrossing> crossing = shape->cross(ray, kInfinity);
        ASSERT_TRUE(crossing);
        EXPECT_EQ(static_cast<float>(crossing->t), hit->t);
        EXPECT_EQ(crossing->primitive, hit->primitive);
        EXPECT_TRUE(shape->occluded(ray, kInfinity));
        EXPECT_FALSE(shape->occluded(ray, 0.999f * hit->t)) << "nothing nearer";
    }
}

TEST_P(ShapeContract, DpduAndDpdvAreTheDerivativesOfTheUvParameterisation) {
    Random random(11);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3 aim = target(random);
        const Vec3 origin = aim + 5.0f * random.unitVector();
        const auto first = shape->intersect({origin, normalize(aim - origin)}, kInfinity);
        if (!first) continue;
        // A second point a small step away on the tangent plane, found by a ray from the same
        // origin: to first order p2 - p1 = dpdu du + dpdv dv.
        Vec3 a, b;
        coordinateSystem(first->ng, a, b);
        const float step = 1e-3f;
        const Vec3 aim2 = first->p + step * (a * 0.6f + b * 0.8f);
        const auto second = shape->intersect({origin, normalize(aim2 - origin)}, kInfinity);
        if (!second || second->primitive != first->primitive) continue;
        const Vec2 duv = second->uv() - first->uv();
        if (std::abs(duv.x) > 0.25f || std::abs(duv.y) > 0.25f) continue;  // across a uv seam
        const Vec3 moved = second->p - first->p;
        const Vec3 predicted = duv.x * first->dpdu + duv.y * first->dpdv;
        EXPECT_LT(length(moved - predicted), 0.02f * length(moved))
            << "moved by " << length(moved) << ", off by " << length(moved - predicted);
        ++checked;
    }
    EXPECT_GT(checked, 50);
}

TEST_P(ShapeContract, AreaSamplesLieOnTheSurfaceWithDensityOneOverTheArea) {
    if (!shape->isBounded()) {
        EXPECT_FALSE(shape->sample(0, Vec2(0.5f, 0.5f))) << "an infinite surface is not sampled";
        return;
    }
    Random random(13);
    for (int i = 0; i < 200; ++i) {
        const auto primitive = static_cast<std::uint32_t>(i) % shape->primitiveCount();
        const Vec2 u(static_cast<float>(random.uniform()), static_cast<float>(random.uniform()));
        const std::optional<ShapeSample> s = shape->sample(primitive, u);
        if (!s && GetParam().samplesCanMiss) continue;
        ASSERT_TRUE(s);
        EXPECT_NEAR(length(s->n), 1, 1e-5f);
        // Found again by a ray from off the surface along the normal.
        const auto hit = shape->intersect({s->p + 1e-2f * s->n, -s->n}, 2e-2f);
        ASSERT_TRUE(hit);
        EXPECT_LT(length(hit->p - s->p), 1e-4f);
        EXPECT_GT(dot(hit->ng, s->n), 0.999f) << "the sample's normal is the front's";
        EXPECT_NEAR(s->pdf, shape->areaPdf(primitive, *hit), 1e-3f * s->pdf);
    }
}

TEST_P(ShapeContract, SolidAngleDensitiesAgreeWithTheSamplesAndIntegrateToOne) {
    if (!shape->isBounded()) return;
    const Vec3 reference(0.3f, 2.5f, -1.7f);
    Random random(17);
    for (std::uint32_t primitive = 0; primitive < shape->primitiveCount(); ++primitive) {
        for (int i = 0; i < 100; ++i) {
            const Vec2 u(static_cast<float>(random.uniform()),
                         static_cast<float>(random.uniform()));
            const auto seen = shape->sample(primitive, reference, u);
            if (!seen) continue;
            const ShapeSample* s = &seen->at;
            const Vec3 wi = normalize(s->p - reference);
            EXPECT_LT(length(seen->wi - wi), 1e-6f) << "the direction to the point";
            const auto hit = shape->intersect({reference, wi}, kInfinity);
            ASSERT_TRUE(hit);
            // Points hidden behind the surface, and grazing ones (where a point a rounding error
            // away has a very different density), are not the ones to compare.
            if (hit->primitive != primitive || length(hit->p - s->p) > 1e-3f ||
                std::abs(dot(hit->ng, wi)) < 0.1f)
                continue;
            EXPECT_NEAR(shape->pdf(primitive, reference, wi, *hit), s->pdf, 2e-3f * s->pdf);
        }
        if (!GetParam().samplesAreVisible) continue;
        // Over uniformly random directions, pdf / (1 / 4 pi) averages to one.
        constexpr int kDirections = 400000;
        double sum = 0;
        for (int i = 0; i < kDirections; ++i) {
            const Vec3 wi = random.unitVector();
            const auto hit = shape->intersect({reference, wi}, kInfinity);
            if (hit && hit->primitive == primitive)
                sum += shape->pdf(primitive, reference, wi, *hit);
        }
        EXPECT_NEAR(sum * 4 * 3.14159265358979323846 / kDirections, 1, 0.03)
            << "primitive " << primitive;
    }
}

TEST_P(ShapeContract, SolidsListTheCrossingsOfALineInOrderEachEnteringOrLeaving) {
    if (!shape->isSolid()) return;  // only solids have an inside
    Random random(19);
    int crossed = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3 aim = target(random);
        // Origins outside, and inside or on the surface (between two crossings) as well.
        const Vec3 origin = aim + static_cast<float>(random.uniform(-3, 5)) * random.unitVector();
        const Ray ray{origin, normalize(aim - origin)};
        LineCrossings crossings;
        shape->crossLine(ray, crossings);
        if (crossings.empty()) continue;
        ++crossed;
        ASSERT_EQ(crossings.size() % 2, 0u) << "a line leaves what it enters";
        for (std::size_t k = 0; k < crossings.size(); ++k) {
            EXPECT_EQ(crossings[k].entering, k % 2 == 0) << "crossing " << k;
            if (k > 0) {
                EXPECT_LE(crossings[k - 1].crossing.t, crossings[k].crossing.t);
            }
            ASSERT_LT(crossings[k].crossing.primitive, shape->primitiveCount());
            // Each crossing is a point of the surface, its normal out of the solid.
            const Hit hit = shape->record(ray, crossings[k].crossing);
            EXPECT_LT(length(hit.p - ray.at(static_cast<float>(crossings[k].crossing.t))), 1e-3f);
            if (std::abs(dot(hit.ng, ray.direction)) > 0.05f) {
                EXPECT_EQ(dot(hit.ng, ray.direction) < 0, crossings[k].entering);
            }
        }
        // The first crossing ahead is the one cross() finds...
        const auto ahead = std::find_if(crossings.begin(), crossings.end(),
                                        [](const LineCrossing& c) { return c.crossing.t > 0; });
        const std::optional<SurfaceCrossing> nearest = shape->cross(ray, kInfinity);
        ASSERT_EQ(ahead != crossings.end(), nearest.has_value());
        if (nearest) {
            EXPECT_NEAR(nearest->t, ahead->crossing.t, 1e-5 * (1 + nearest->t));
        }
        // ...and the points between two crossings are inside exactly when the first enters.
        for (std::size_t k = 0; k + 1 < crossings.size(); ++k) {
            const double t0 = crossings[k].crossing.t, t1 = crossings[k + 1].crossing.t;
            if (t1 - t0 < 1e-2) continue;  // too close to the surface to ask
            const Vec3 between = ray.at(static_cast<float>(0.5 * (t0 + t1)));
            EXPECT_EQ(shape->contains(between), crossings[k].entering) << "between " << k;
        }
    }
    EXPECT_GT(crossed, 100);
}

TEST_P(ShapeContract, ASegmentListsTheCrossingsThatWalkingItSurfaceBySurfaceFinds) {
    Random random(23);
    int compared = 0, severalCrossings = 0;
    for (int i = 0; i < 600; ++i) {
        const Vec3 aim = target(random);
        const Vec3 origin = aim + static_cast<float>(random.uniform(-3, 5)) * random.unitVector();
        Ray ray{origin, normalize(aim - origin)};
        // Every third ray leaves the surface as a shadow ray does: spawned from a hit.
        if (i % 3 == 0) {
            const std::optional<Hit> hit = shape->intersect(ray, kInfinity);
            if (!hit) continue;
            ray = hit->spawnRay(random.unitVector());
        }
        const float tMax = i % 2 == 0 ? kInfinity : static_cast<float>(random.uniform(0.1, 4));
        SurfaceCrossings crossings;
        shape->crossSegment(ray, tMax, crossings);
        std::sort(crossings.begin(), crossings.end(),
                  [](const SurfaceCrossing& a, const SurfaceCrossing& b) { return a.t < b.t; });
        // The walk shadow rays made before: the nearest crossing, then the nearest seen from a
        // ray spawned beyond it, and so on to the segment's end.
        std::vector<double> walked;
        // Crossings within rounding of one another or of the segment's ends, and those at a
        // grazing angle (where t moves far with the ray's origin), may be told apart differently
        // by the two ways: those rays are left out.
        bool unclear = false;
        Ray from = ray;
        for (int k = 0; k < 16; ++k) {
            const float travelled = dot(from.origin - ray.origin, ray.direction);
            const std::optional<SurfaceCrossing> next = shape->cross(from, tMax - travelled);
            if (!next) break;
            walked.push_back(travelled + next->t);
            const Hit hit = shape->record(from, *next);
            unclear = unclear || std::abs(dot(hit.ng, ray.direction)) < 0.01f;
            from = hit.spawnRay(ray.direction);
        }
        const auto close = [&](const std::vector<double>& ts) {
            for (std::size_t k = 0; k < ts.size(); ++k)
                if (ts[k] < 1e-3 || std::abs(ts[k] - tMax) < 1e-3 * (1 + ts[k]) ||
                    (k > 0 && ts[k] - ts[k - 1] < 1e-3))
                    return true;
            return false;
        };
        std::vector<double> listed;
        for (const SurfaceCrossing& c : crossings) {
            listed.push_back(c.t);
            unclear = unclear || std::abs(dot(shape->record(ray, c).ng, ray.direction)) < 0.01f;
        }
        if (unclear || close(walked) || close(listed)) continue;
        ++compared;
        severalCrossings += crossings.size() > 1;
        ASSERT_EQ(crossings.size(), walked.size()) << "ray " << i;
        for (std::size_t k = 0; k < crossings.size(); ++k) {
            EXPECT_NEAR(crossings[k].t, walked[k], 1e-4 * (1 + walked[k])) << "ray " << i;
            ASSERT_LT(crossings[k].primitive, shape->primitiveCount());
            // Each is a point of the surface that record() takes.
            const Hit hit = shape->record(ray, crossings[k]);
            EXPECT_LT(length(hit.p - ray.at(static_cast<float>(crossings[k].t))), 1e-3f);
        }
        // The first is the crossing cross() finds, to the bit.
        if (!crossings.empty()) {
            EXPECT_EQ(crossings.front().t, shape->cross(ray, tMax)->t) << "ray " << i;
        }
    }
    EXPECT_GT(compared, 300);
    if (shape->isSolid()) {
        EXPECT_GT(severalCrossings, 50) << "rays through the solid";
    }
}

TEST(ClosedMeshSegment, ALinePassingThroughAnEdgeCrossesTheSurfaceOnce) {
    // Through the middle of two opposite faces of the cube, where each face's two triangles
    // meet on their shared diagonal, and along a diagonal of one face (x = y on the +z face).
    const std::unique_ptr<Shape> cube = makeClosedMesh(Vec3(0));
    for (const Ray& ray : {Ray{Vec3(0, 0, 3), Vec3(0, 0, -1)}, Ray{Vec3(0, 0, -3), Vec3(0, 0, 1)},
                           Ray{Vec3(0.3f, 0.3f, 3), Vec3(0, 0, -1)}}) {
        SurfaceCrossings crossings;
        cube->crossSegment(ray, kInfinity, crossings);
        ASSERT_EQ(crossings.size(), 2u) << "entering and leaving";
        EXPECT_NEAR(std::min(crossings[0].t, crossings[1].t), 2.2, 1e-6);
        EXPECT_NEAR(std::max(crossings[0].t, crossings[1].t), 3.8, 1e-6);
    }
}

INSTANTIATE_TEST_SUITE_P(AllShapes, ShapeContract, testing::ValuesIn(shapeCases()),
                         [](const testing::TestParamInfo<ShapeCase>& param) {
                             return param.param.name;
                         });

}  // namespace
}  // namespace lancer
