// Cones and cylinders: where rays meet the side and the caps, from outside and inside, the normals
// of a slanted side, uniform sampling of the side, and a tessellation whose side and caps share
// their rims.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "TestSupport.h"
#include "geometry/Cone.h"
#include "geometry/Cylinder.h"
#include "geometry/TessellationRequest.h"

namespace lancer {
namespace {

constexpr float kTolerance = 1e-5f;

// Radius 1 about the y axis, from y = 0 to y = 2.
const Cylinder kCylinder(Vec3(0, 0, 0), Vec3(0, 2, 0), 1, false, nullptr);

TEST(ConeTest, ARayMeetsACylindersSideWhereTheCircleSays) {
    const std::optional<Hit> hit =
        kCylinder.intersect({Vec3(0.6f, 1.5f, 5), Vec3(0, 0, -1)}, kInfinity);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->primitive, 0u);
    EXPECT_NEAR(hit->t, 5 - 0.8f, kTolerance);
    EXPECT_VEC3_NEAR(hit->ng, Vec3(0.6f, 0, 0.8f), kTolerance);
    EXPECT_NEAR(hit->uv().y, 0.75f, kTolerance);
    EXPECT_GT(dot(cross(hit->dpdu, hit->dpdv), hit->ng), 0) << "dpdu x dpdv points out";
}

TEST(ConeTest, ARayDownTheAxisMeetsTheTopCapAndFromInsideTheBaseCap) {
    const std::optional<Hit> top =
        kCylinder.intersect({Vec3(0.2f, 5, 0.1f), Vec3(0, -1, 0)}, kInfinity);
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->t, 3, kTolerance);
    EXPECT_EQ(top->ng, Vec3(0, 1, 0));
    EXPECT_EQ(top->primitive, 2u);
    const std::optional<Hit> base =
        kCylinder.intersect({Vec3(0.2f, 1, 0.1f), Vec3(0, -1, 0)}, kInfinity);
    ASSERT_TRUE(base);
    EXPECT_NEAR(base->t, 1, kTolerance);
    EXPECT_EQ(base->ng, Vec3(0, -1, 0)) << "out of the solid";
    EXPECT_EQ(base->primitive, 1u);
    EXPECT_EQ(base->shape, &kCylinder);
}

TEST(ConeTest, AnOpenCylinderIsSeenThroughItsEndsFromInside) {
    const Cylinder tube(Vec3(0, 0, 0), Vec3(0, 2, 0), 1, true, nullptr);
    EXPECT_EQ(tube.primitiveCount(), 1u);
    EXPECT_TRUE(tube.emitsOnBothSides());
    // Down through the open top, slanted: it meets the inside of the wall.
    const std::optional<Hit> hit =
        tube.intersect({Vec3(0, 3, 0), normalize(Vec3(1, -2, 0))}, kInfinity);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->p.x, 1, kTolerance);
    EXPECT_NEAR(hit->p.y, 1, kTolerance);
    EXPECT_VEC3_NEAR(hit->ng, Vec3(1, 0, 0), kTolerance);
    EXPECT_FALSE(hit->frontFace({Vec3(0, 3, 0), normalize(Vec3(1, -2, 0))}));
    // Straight down the axis it meets nothing.
    EXPECT_FALSE(tube.intersect({Vec3(0, 3, 0), Vec3(0, -1, 0)}, kInfinity));
}

TEST(ConeTest, APointedConesSideHasTheSlantedNormal) {
    // Radius 1 at y = 0 to a point at y = 1: x^2 + z^2 = (1 - y)^2, the normal at 45 degrees.
    const Cone cone(Vec3(0, 0, 0), 1, Vec3(0, 1, 0), 0, false, nullptr);
    EXPECT_EQ(cone.primitiveCount(), 2u) << "the side and the base; no cap at the point";
    const std::optional<Hit> hit = cone.intersect({Vec3(0, 0.5f, 5), Vec3(0, 0, -1)}, kInfinity);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->p.z, 0.5f, kTolerance);
    EXPECT_VEC3_NEAR(hit->ng, normalize(Vec3(0, 1, 1)), kTolerance);
    // Beside the point, above the side: nothing.
    EXPECT_FALSE(cone.intersect({Vec3(0.2f, 0.9f, 5), Vec3(0, 0, -1)}, kInfinity));
    EXPECT_NEAR(cone.area(0), kPi * std::sqrt(2.0f), 1e-5f);
}

TEST(ConeTest, SideSamplesAreUniformByArea) {
    // Radii 1 and 0.5 over a height of 1: the part below half height, of radii 1 and 0.75, holds
    // (1 - 0.75^2) / (1 - 0.5^2) = 7/12 of the side.
    const Cone cone(Vec3(0, 0, 0), 1, Vec3(0, 1, 0), 0.5f, false, nullptr);
    test::Random random(5);
    constexpr int kSamples = 40000;
    int below = 0;
    for (int i = 0; i < kSamples; ++i) {
        const Vec2 u(static_cast<float>(random.uniform()), static_cast<float>(random.uniform()));
        const std::optional<ShapeSample> s = cone.sample(0, u);
        ASSERT_TRUE(s);
        const float r = std::hypot(s->p.x, s->p.z);
        EXPECT_NEAR(r, 1 - 0.5f * s->p.y, 1e-5f) << "on the side";
        if (s->p.y < 0.5f) ++below;
    }
    // Three standard deviations of a binomial proportion.
    EXPECT_NEAR(static_cast<double>(below) / kSamples, 7.0 / 12, 3 * std::sqrt(0.25 / kSamples));
}

TEST(ConeTest, TheSideAndTheCapsShareTheirRimsVertices) {
    const Cone cone(Vec3(0.1f, 0.2f, 0.3f), 0.8f, Vec3(0.5f, 1.7f, -0.2f), 0.4f, false, nullptr);
    const Tessellation tessellation = cone.tessellate({0.2f, cone.bounds()});
    EXPECT_TRUE(tessellation.curved);
    std::set<std::array<float, 3>> sideVertices;
    float sideArea = 0;
    for (const auto& facet : tessellation.facets) {
        const Vec3 n =
            cross(facet.corners[1] - facet.corners[0], facet.corners[2] - facet.corners[0]);
        ASSERT_GT(length(n), 0) << "no facet of zero area";
        const Vec3 centre = (facet.corners[0] + facet.corners[1] + facet.corners[2]) / 3.0f;
        // Outward: a side facet's normal points away from the axis, a cap facet's along the
        // cap's normal.
        const std::optional<ShapeSample> onPiece = cone.sample(facet.primitive, Vec2(0.5f, 0.5f));
        ASSERT_TRUE(onPiece);
        if (facet.primitive == 0) {
            sideArea += length(n) / 2;
            for (const Vec3& c : facet.corners)
                sideVertices.insert({c.x, c.y, c.z});
            const Vec3 axisPoint =
                Vec3(0.1f, 0.2f, 0.3f) +
                dot(centre - Vec3(0.1f, 0.2f, 0.3f), normalize(Vec3(0.4f, 1.5f, -0.5f))) *
                    normalize(Vec3(0.4f, 1.5f, -0.5f));
            EXPECT_GT(dot(n, centre - axisPoint), 0) << "counter-clockwise seen from outside";
        } else {
            EXPECT_GT(dot(n, onPiece->n), 0) << "counter-clockwise seen from outside";
        }
    }
    EXPECT_NEAR(sideArea, cone.area(0), 0.01f * cone.area(0));
    int rimVertices = 0;
    for (const auto& facet : tessellation.facets) {
        if (facet.primitive == 0) continue;
        for (const Vec3& c : facet.corners) {
            const float r = length(
                c - (facet.primitive == 1 ? Vec3(0.1f, 0.2f, 0.3f) : Vec3(0.5f, 1.7f, -0.2f)));
            const float rim = facet.primitive == 1 ? 0.8f : 0.4f;
            if (std::abs(r - rim) > 1e-4f) continue;
            ++rimVertices;
            EXPECT_EQ(sideVertices.count({c.x, c.y, c.z}), 1u)
                << "a cap's rim vertex is the side's";
        }
    }
    EXPECT_GT(rimVertices, 32);
}

}  // namespace
}  // namespace lancer
