// The box: which face a ray meets from outside and from inside, rays along its faces and edges,
// spawned rays that never find the face they leave, and its faces as light samples and patches.

#include <gtest/gtest.h>

#include <cmath>

#include "TestSupport.h"
#include "geometry/Box.h"
#include "geometry/TessellationRequest.h"
#include "math/Float.h"

namespace lancer {
namespace {

const Box kBox(Vec3(-1, -2, -3), Vec3(1, 2, 3), nullptr);

TEST(BoxTest, ARayFromOutsideMeetsTheFaceItEntersBy) {
    const std::optional<Hit> hit = kBox.intersect({Vec3(0.5f, 1, 10), Vec3(0, 0, -1)}, kInfinity);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->t, 7);
    EXPECT_EQ(hit->p, Vec3(0.5f, 1, 3));
    EXPECT_EQ(hit->ng, Vec3(0, 0, 1));
    EXPECT_EQ(hit->primitive, 5u);  // 2 axis + 1: the face at max z
    // On the face at max z, u follows x and v follows y, each from 0 to 1.
    EXPECT_FLOAT_EQ(hit->uv().x, 0.75f);
    EXPECT_FLOAT_EQ(hit->uv().y, 0.75f);
    EXPECT_EQ(hit->dpdu, Vec3(2, 0, 0));
    EXPECT_EQ(hit->dpdv, Vec3(0, 4, 0));
    EXPECT_EQ(hit->pError.z, 0) << "the point lies exactly on the face's plane";
}

TEST(BoxTest, EveryFaceHasItsOutwardNormalAndUvOrientedOutwards) {
    for (std::uint32_t face = 0; face < 6; ++face) {
        const int axis = static_cast<int>(face / 2);
        Vec3 outward(0);
        outward[axis] = face % 2 == 1 ? 1.0f : -1.0f;
        // Aimed at the face's centre from 10 units out along its normal.
        const std::optional<Hit> hit = kBox.intersect({10.0f * outward, -outward}, kInfinity);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->primitive, face);
        EXPECT_EQ(hit->ng, outward);
        EXPECT_GT(dot(cross(hit->dpdu, hit->dpdv), outward), 0) << "face " << face;
        EXPECT_FLOAT_EQ(hit->uv().x, 0.5f);
        EXPECT_FLOAT_EQ(hit->uv().y, 0.5f);
        EXPECT_FLOAT_EQ(length(cross(hit->dpdu, hit->dpdv)), kBox.area(face));
    }
}

TEST(BoxTest, ARayFromInsideMeetsTheFaceItLeavesByWithItsNormalPointingOut) {
    const std::optional<Hit> hit = kBox.intersect({Vec3(0, 0, 0), Vec3(0, 1, 0)}, kInfinity);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->t, 2);
    EXPECT_EQ(hit->primitive, 3u);
    EXPECT_EQ(hit->ng, Vec3(0, 1, 0));
    EXPECT_FALSE(hit->frontFace({Vec3(0, 0, 0), Vec3(0, 1, 0)}));
}

TEST(BoxTest, MissesRaysBesideItBehindItAndBeyondTMax) {
    EXPECT_FALSE(kBox.intersect({Vec3(1.5f, 0, 10), Vec3(0, 0, -1)}, kInfinity));
    EXPECT_FALSE(kBox.intersect({Vec3(0, 0, 10), Vec3(0, 0, 1)}, kInfinity));
    EXPECT_FALSE(kBox.intersect({Vec3(0, 0, 10), Vec3(0, 0, -1)}, 7));
    EXPECT_TRUE(kBox.intersect({Vec3(0, 0, 10), Vec3(0, 0, -1)}, 7.001f));
    // Parallel to the x slabs, outside them.
    EXPECT_FALSE(kBox.intersect({Vec3(1.01f, 0, 10), Vec3(0, 0, -1)}, kInfinity));
}

TEST(BoxTest, ARayAlongAFaceOrThroughAnEdgeIsHandledWithoutNaN) {
    // In the plane x = 1 of a face, parallel to it: it grazes the face, and meets the end faces.
    const std::optional<Hit> along = kBox.intersect({Vec3(1, 0, 10), Vec3(0, 0, -1)}, kInfinity);
    ASSERT_TRUE(along);
    EXPECT_EQ(along->t, 7);
    EXPECT_TRUE(test::isFiniteHit(*along));
    // Diagonally through the edge x = 1, z = 3: it meets the box there and nowhere else.
    const Ray diagonal{Vec3(3, 0, 5), normalize(Vec3(-1, 0, -1))};
    const std::optional<Hit> edge = kBox.intersect(diagonal, kInfinity);
    ASSERT_TRUE(edge);
    EXPECT_NEAR(edge->p.x, 1, 1e-6f);
    EXPECT_NEAR(edge->p.z, 3, 1e-6f);
    EXPECT_TRUE(edge->primitive == 1u || edge->primitive == 5u);
}

TEST(BoxTest, RaysSpawnedFromAFaceNeverFindThatFace) {
    test::Random random(3);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 origin = 20.0f * random.unitVector();
        const Vec3 aim(static_cast<float>(random.uniform(-1, 1)),
                       static_cast<float>(random.uniform(-2, 2)),
                       static_cast<float>(random.uniform(-3, 3)));
        const std::optional<Hit> hit = kBox.intersect({origin, normalize(aim - origin)}, kInfinity);
        if (!hit) continue;
        // Reflected: out of the box, nothing more to meet.
        const Vec3 out = random.unitVector();
        const Vec3 reflected = dot(out, hit->ng) > 0 ? out : -out;
        EXPECT_FALSE(kBox.intersect(hit->spawnRay(reflected), kInfinity));
        // Refracted: into the box, across to another face.
        const std::optional<Hit> across = kBox.intersect(hit->spawnRay(-reflected), kInfinity);
        ASSERT_TRUE(across);
        EXPECT_NE(across->primitive, hit->primitive);
    }
}

TEST(BoxTest, FacesAreSampledUniformlyAndTessellatedOutwards) {
    float total = 0;
    for (std::uint32_t face = 0; face < 6; ++face)
        total += kBox.area(face);
    EXPECT_FLOAT_EQ(total, 2 * (2 * 4 + 4 * 6 + 2 * 6));
    const std::optional<ShapeSample> s = kBox.sample(0, Vec2(0.25f, 0.5f));
    ASSERT_TRUE(s);
    EXPECT_EQ(s->n, Vec3(-1, 0, 0));
    EXPECT_FLOAT_EQ(s->pdf, 1 / kBox.area(0));
    EXPECT_EQ(s->p.x, -1);

    const Tessellation tessellation = kBox.tessellate({0.5f, kBox.bounds()});
    float area = 0;
    for (const auto& facet : tessellation.facets) {
        const Vec3 n =
            cross(facet.corners[1] - facet.corners[0], facet.corners[2] - facet.corners[0]);
        area += length(n) / 2;
        const std::optional<ShapeSample> onFace = kBox.sample(facet.primitive, Vec2(0.5f, 0.5f));
        ASSERT_TRUE(onFace);
        EXPECT_GT(dot(n, onFace->n), 0) << "counter-clockwise seen from outside";
    }
    EXPECT_NEAR(area, total, 1e-3f * total);
    EXPECT_EQ(tessellation.facets.size(), 2u * 2 * (4 * 8 + 8 * 12 + 4 * 12));
}

}  // namespace
}  // namespace lancer
