// The kernels chosen at run time by the CPU (CpuFeatures: the BVH's 8-wide box test in one AVX2
// pass, or in two SSE halves) give the same answers to the bit: an image never depends on the
// machine. Every ray is traced under both, including rays along the axes (zero and negative
// zero direction components), from inside the mesh's box and from far away.

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "accel/Mesh.h"
#include "io/ObjLoader.h"
#include "materials/ConstantTexture.h"
#include "math/Ray.h"
#include "util/CpuFeatures.h"

namespace lancer::test {
namespace {

struct Answer {
    std::optional<SurfaceCrossing> crossing;
    bool occluded = false;
    bool occludedNear = false;
};

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

class SimdKernelTest : public ::testing::Test {
protected:
    static void TearDownTestSuite() { CpuFeatures::useBaselineOnly(false); }

    static std::shared_ptr<const Mesh> bunny() {
        std::vector<std::string> warnings;
        const auto texture = [](const std::filesystem::path&, ImageReader::Content) {
            return std::shared_ptr<const Texture>(std::make_shared<ConstantTexture>(Color(0.5f)));
        };
        auto triangles = ObjLoader::load(
            std::filesystem::path(LANCER_SCENE_MODELS) / "stanford_bunny_lowres/bunny.obj", texture,
            warnings);
        return std::make_shared<const Mesh>(std::move(*triangles));
    }

    // Rays through the mesh's box from all around and from inside, in every direction, a
    // tenth of them along an axis.
    static std::vector<Ray> rays(const Bounds3& box) {
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> unit(0, 1), signed_(-1, 1);
        std::vector<Ray> out;
        const Vec3 size = box.diagonal();
        for (int i = 0; i < 20000; ++i) {
            const Vec3 inside =
                box.min + Vec3(unit(rng) * size.x, unit(rng) * size.y, unit(rng) * size.z);
            Vec3 direction(signed_(rng), signed_(rng), signed_(rng));
            if (i % 10 == 0) {
                const int axis = i / 10 % 3;
                direction = Vec3(0.0f, -0.0f, 0.0f);
                direction[axis] = i % 20 == 0 ? 1.0f : -1.0f;
            }
            direction = normalize(direction);
            const Vec3 origin = i % 2 == 0 ? inside : inside - 2 * length(size) * direction;
            out.push_back({origin, direction});
        }
        return out;
    }

    static std::vector<Answer> trace(const Mesh& mesh, const std::vector<Ray>& rays) {
        std::vector<Answer> answers;
        for (const Ray& ray : rays)
            answers.push_back({mesh.cross(ray, kInfinity), mesh.occluded(ray, kInfinity),
                               mesh.occluded(ray, 0.01f * length(mesh.bounds().diagonal()))});
        return answers;
    }
};

TEST_F(SimdKernelTest, TheCpusKernelsAndTheBaselineAnswerAlike) {
    const std::shared_ptr<const Mesh> mesh = bunny();
    const std::vector<Ray> all = rays(mesh->bounds());
    CpuFeatures::useBaselineOnly(true);
    ASSERT_FALSE(CpuFeatures::avx2());
    const std::vector<Answer> baseline = trace(*mesh, all);
    CpuFeatures::useBaselineOnly(false);
    const std::vector<Answer> best = trace(*mesh, all);
    if (!CpuFeatures::avx2()) GTEST_SKIP() << "this CPU runs the baseline kernels only";

    int hits = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Answer &a = baseline[i], &b = best[i];
        ASSERT_EQ(a.crossing.has_value(), b.crossing.has_value()) << "ray " << i;
        EXPECT_EQ(a.occluded, b.occluded) << "ray " << i;
        EXPECT_EQ(a.occludedNear, b.occludedNear) << "ray " << i;
        if (!a.crossing) continue;
        ++hits;
        EXPECT_EQ(a.crossing->primitive, b.crossing->primitive) << "ray " << i;
        EXPECT_EQ(a.crossing->t, b.crossing->t) << "ray " << i;
        EXPECT_TRUE(sameBits(a.crossing->b0, b.crossing->b0) &&
                    sameBits(a.crossing->b1, b.crossing->b1) &&
                    sameBits(a.crossing->b2, b.crossing->b2))
            << "ray " << i;
    }
    EXPECT_GT(hits, 5000);
}

}  // namespace
}  // namespace lancer::test

namespace lancer::test {
namespace {

// The traversal checks the ray's six numbers at once: a ray with any of them NaN or infinite,
// alone or with others, ends without a hit, where the same ray with that number finite meets the
// model.
TEST_F(SimdKernelTest, RaysWithANumberNotFiniteEndWithoutAHit) {
    const std::shared_ptr<const Mesh> mesh = bunny();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Vec3 centre = mesh->bounds().centroid();
    const Ray towardsCentre{centre - Vec3(0, 0, 1), Vec3(0, 0, 1)};
    std::vector<Ray> rays = {Ray{Vec3(nan, 0, 0), Vec3(0, 0, 1)},
                             Ray{Vec3(0, 0, 0), Vec3(nan, nan, nan)},
                             Ray{Vec3(nan, nan, nan), Vec3(0, 1, 0)}};
    for (int number = 0; number < 6; ++number)
        for (const float bad : {nan, kInfinity, -kInfinity}) {
            Ray ray = towardsCentre;
            (number < 3 ? ray.origin : ray.direction)[number % 3] = bad;
            rays.push_back(ray);
        }
    for (const bool baseline : {true, false}) {
        CpuFeatures::useBaselineOnly(baseline);
        ASSERT_TRUE(mesh->occluded(towardsCentre, kInfinity));
        for (std::size_t i = 0; i < rays.size(); ++i) {
            EXPECT_FALSE(mesh->cross(rays[i], kInfinity).has_value()) << "ray " << i;
            EXPECT_FALSE(mesh->occluded(rays[i], kInfinity)) << "ray " << i;
        }
    }
}

}  // namespace
}  // namespace lancer::test
