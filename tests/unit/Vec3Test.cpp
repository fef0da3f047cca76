// The small vector library: arithmetic, products, and the helpers that intersection code uses.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "TestSupport.h"
#include "math/Float.h"
#include "math/Vec3.h"

namespace lancer {
namespace {

using test::Random;

// One float rounding of a value near 1.
constexpr float kUlpNearOne = std::numeric_limits<float>::epsilon();

TEST(Vec3Test, ArithmeticIsComponentWise) {
    const Vec3 a(1, 2, 3), b(4, -5, 6);
    EXPECT_EQ(a + b, Vec3(5, -3, 9));
    EXPECT_EQ(a - b, Vec3(-3, 7, -3));
    EXPECT_EQ(-a, Vec3(-1, -2, -3));
    EXPECT_EQ(a * 2.0f, Vec3(2, 4, 6));
    EXPECT_EQ(2.0f * a, Vec3(2, 4, 6));
    EXPECT_EQ(b / 2.0f, Vec3(2, -2.5f, 3));
    EXPECT_EQ(Vec3(7), Vec3(7, 7, 7));
    Vec3 c = a;
    c += b;
    c -= Vec3(1, 1, 1);
    c *= 3.0f;
    EXPECT_EQ(c, Vec3(12, -12, 24));
}

TEST(Vec3Test, IndexingReadsAndWritesEachComponent) {
    Vec3 v(1, 2, 3);
    EXPECT_EQ(v[0], 1);
    EXPECT_EQ(v[1], 2);
    EXPECT_EQ(v[2], 3);
    v[1] = 9;
    EXPECT_EQ(v, Vec3(1, 9, 3));
}

TEST(Vec3Test, DotProduct) {
    EXPECT_EQ(dot(Vec3(1, 2, 3), Vec3(4, -5, 6)), 12);  // 4 - 10 + 18
    EXPECT_EQ(dot(Vec3(1, 0, 0), Vec3(0, 1, 0)), 0);
    EXPECT_EQ(lengthSquared(Vec3(2, 3, 6)), 49);
    EXPECT_EQ(length(Vec3(2, 3, 6)), 7);
}

TEST(Vec3Test, CrossProductOfTheAxesIsRightHanded) {
    const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    EXPECT_EQ(cross(x, y), z);
    EXPECT_EQ(cross(y, z), x);
    EXPECT_EQ(cross(z, x), y);
    EXPECT_EQ(cross(y, x), -z);
}

TEST(Vec3Test, CrossProductIsOrthogonalToBothFactors) {
    const Vec3 a(1, 2, 3), b(4, 5, 6);
    EXPECT_EQ(cross(a, b), Vec3(-3, 6, -3));  // (2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4)
    EXPECT_EQ(dot(cross(a, b), a), 0);
    EXPECT_EQ(dot(cross(a, b), b), 0);
    EXPECT_EQ(cross(a, a), Vec3(0, 0, 0));
}

TEST(Vec3Test, NormalizeGivesAUnitVectorInTheSameDirection) {
    const Vec3 n = normalize(Vec3(3, 4, 12));  // length 13
    EXPECT_NEAR(n.x, 3.0 / 13, kUlpNearOne);
    EXPECT_NEAR(n.y, 4.0 / 13, kUlpNearOne);
    EXPECT_NEAR(n.z, 12.0 / 13, kUlpNearOne);
    Random random(1);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 v = random.pointInBox(1e3f);
        EXPECT_NEAR(length(normalize(v)), 1.0f, 2 * kUlpNearOne);
    }
}

TEST(Vec3Test, ComponentWiseHelpers) {
    const Vec3 a(-1, 5, -3), b(2, -6, -3);
    EXPECT_EQ(abs(a), Vec3(1, 5, 3));
    EXPECT_EQ(min(a, b), Vec3(-1, -6, -3));
    EXPECT_EQ(max(a, b), Vec3(2, 5, -3));
    EXPECT_EQ(maxComponent(a), 5);
    EXPECT_TRUE(isFinite(a));
    EXPECT_FALSE(isFinite(Vec3(0, kInfinity, 0)));
    EXPECT_FALSE(isFinite(Vec3(0, 0, std::nanf(""))));
}

TEST(Vec3Test, MaxDimensionIsTheLargestAbsoluteComponent) {
    EXPECT_EQ(maxDimension(Vec3(-7, 1, 2)), 0);
    EXPECT_EQ(maxDimension(Vec3(1, -5, 2)), 1);
    EXPECT_EQ(maxDimension(Vec3(1, 2, -3)), 2);
    EXPECT_EQ(maxDimension(Vec3(0, 0, -1)), 2);
    EXPECT_EQ(maxDimension(Vec3(0.5f, -0.25f, 0.4f)), 0);
}

TEST(Vec3Test, PermuteReordersComponents) {
    const Vec3 v(1, 2, 3);
    EXPECT_EQ(permute(v, 0, 1, 2), v);
    EXPECT_EQ(permute(v, 2, 0, 1), Vec3(3, 1, 2));
    EXPECT_EQ(permute(v, 1, 2, 0), Vec3(2, 3, 1));
    EXPECT_EQ(permute(v, 2, 2, 0), Vec3(3, 3, 1));
}

TEST(Vec3Test, AngleBetweenIsAccurateAtEveryAngle) {
    EXPECT_FLOAT_EQ(angleBetween(Vec3(2, 0, 0), Vec3(0, 0, 3)), kPi / 2);
    EXPECT_FLOAT_EQ(angleBetween(Vec3(1, 1, 0), Vec3(1, 0, 0)), kPi / 4);
    EXPECT_FLOAT_EQ(angleBetween(Vec3(1, 0, 0), Vec3(-1, 0, 0)), kPi);
    EXPECT_EQ(angleBetween(Vec3(0, 1, 0), Vec3(0, 5, 0)), 0.0f);
    // 1e-4 radians, where acos of the dot product (1 - 5e-9, which rounds to 1) gives 0.
    EXPECT_NEAR(angleBetween(Vec3(1, 0, 0), Vec3(1, 1e-4f, 0)), 1e-4f, 1e-9f);
}

TEST(Vec3Test, ReflectMirrorsAboutTheNormal) {
    // Exact for an axis normal: the tangential part flips, the normal part stays.
    EXPECT_EQ(reflect(Vec3(1, 2, 3), Vec3(0, 1, 0)), Vec3(-1, 2, -3));
    Random random(2);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 n = random.unitVector();
        const Vec3 wo = random.unitVector();
        const Vec3 r = reflect(wo, n);
        EXPECT_NEAR(length(r), 1.0f, 4 * kUlpNearOne);
        EXPECT_NEAR(dot(r, n), dot(wo, n), 4 * kUlpNearOne);  // equal angles with the normal
        // wo, n and r are coplanar, and r + wo lies along n.
        EXPECT_NEAR(length(cross(r + wo, n)), 0.0f, 8 * kUlpNearOne);
    }
}

// Checks that (s, t, n) is a right-handed orthonormal basis.
void expectOrthonormalBasis(const Vec3& n) {
    Vec3 s, t;
    coordinateSystem(n, s, t);
    const float tolerance = 4 * kUlpNearOne;
    EXPECT_NEAR(length(s), 1.0f, tolerance);
    EXPECT_NEAR(length(t), 1.0f, tolerance);
    EXPECT_NEAR(dot(s, n), 0.0f, tolerance);
    EXPECT_NEAR(dot(t, n), 0.0f, tolerance);
    EXPECT_NEAR(dot(s, t), 0.0f, tolerance);
    EXPECT_VEC3_NEAR(cross(s, t), n, tolerance);
}

TEST(Vec3Test, CoordinateSystemIsOrthonormalForAxes) {
    for (const Vec3& n : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0),
                          Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
        SCOPED_TRACE(testing::Message() << "n = (" << n.x << ", " << n.y << ", " << n.z << ")");
        expectOrthonormalBasis(n);
    }
}

TEST(Vec3Test, CoordinateSystemIsOrthonormalForRandomNormals) {
    Random random(3);
    for (int i = 0; i < 10000; ++i)
        expectOrthonormalBasis(random.unitVector());
}

TEST(Vec3Test, ConvertsBetweenPrecisions) {
    const Vec3d d(Vec3(0.1f, -2, 3));
    EXPECT_EQ(d.x, static_cast<double>(0.1f));
    EXPECT_EQ(Vec3(Vec3d(1.0 / 3, 0, 0)).x, 1.0f / 3);
}

}  // namespace
}  // namespace lancer
