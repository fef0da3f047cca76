// Homogeneous transforms: points, vectors and normals, composition, inverses, error bounds.

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "TestSupport.h"
#include "math/Transform.h"

namespace lancer {
namespace {

void expectNear(const Vec3& actual, const Vec3& expected, float tolerance = 1e-6f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(TransformTest, TranslateMovesPointsButNotVectors) {
    const Transform t = Transform::translate({1, 2, 3});
    expectNear(t.applyPoint({1, 1, 1}), {2, 3, 4});
    expectNear(t.applyVector({1, 1, 1}), {1, 1, 1});
}

TEST(TransformTest, ScaleIsPerAxis) {
    const Transform s = Transform::scale({2, 3, 4});
    expectNear(s.applyPoint({1, 1, 1}), {2, 3, 4});
    expectNear(s.inverse().applyPoint({2, 3, 4}), {1, 1, 1});
}

TEST(TransformTest, RotationIsCounterClockwiseLookingDownTheAxis) {
    // Right-handed: a quarter turn about +y takes +x to -z, about +z takes +x to +y.
    expectNear(Transform::rotate(90, {0, 1, 0}).applyVector({1, 0, 0}), {0, 0, -1});
    expectNear(Transform::rotate(90, {0, 0, 1}).applyVector({1, 0, 0}), {0, 1, 0});
    expectNear(Transform::rotate(90, {1, 0, 0}).applyVector({0, 1, 0}), {0, 0, 1});
    // The axis need not be unit length, and the rotation keeps lengths.
    const Vec3 v = Transform::rotate(33, {1, 2, 2}).applyVector({3, -1, 2});
    EXPECT_NEAR(length(v), length(Vec3(3, -1, 2)), 1e-5f);
}

TEST(TransformTest, ProductAppliesTheRightFactorFirst) {
    const Transform scaleThenMove = Transform::translate({10, 0, 0}) * Transform::scale({2, 2, 2});
    expectNear(scaleThenMove.applyPoint({1, 0, 0}), {12, 0, 0});
    const Transform moveThenScale = Transform::scale({2, 2, 2}) * Transform::translate({10, 0, 0});
    expectNear(moveThenScale.applyPoint({1, 0, 0}), {22, 0, 0});
}

TEST(TransformTest, InverseUndoesAGeneralTransform) {
    const Transform t = Transform::translate({1, -2, 5}) * Transform::rotate(37, {1, 1, 0}) *
                        Transform::scale({0.5f, 2, 3});
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coordinate(-10, 10);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
        expectNear(t.inverse().applyPoint(t.applyPoint(p)), p, 1e-4f);
        expectNear((t * t.inverse()).applyPoint(p), p, 1e-4f);
    }
}

TEST(TransformTest, MatrixConstructorComputesTheInverse) {
    const Transform::Matrix m{{{2, 0, 0, 1}, {0, 0, -3, 2}, {0, 1, 0, 3}, {0, 0, 0, 1}}};
    const Transform t(m);
    expectNear(t.applyPoint({1, 1, 1}), {3, -1, 4});
    expectNear(t.inverse().applyPoint({3, -1, 4}), {1, 1, 1});
}

TEST(TransformTest, SingularOrProjectiveMatricesAreRejected) {
    const Transform::Matrix flat{{{1, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    EXPECT_THROW(Transform{flat}, std::invalid_argument);
    const Transform::Matrix projective{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 1, 1}}};
    EXPECT_THROW(Transform{projective}, std::invalid_argument);
    EXPECT_THROW(Transform::scale({1, 0, 1}), std::invalid_argument);
    EXPECT_THROW(Transform::rotate(10, {0, 0, 0}), std::invalid_argument);
}

TEST(TransformTest, NormalsStayPerpendicularUnderNonUniformScale) {
    // The plane x + y = 0 squashed along x: a normal transformed as a vector would tilt off the
    // surface; transformed by the inverse transpose it stays perpendicular.
    const Transform t = Transform::rotate(20, {0, 0, 1}) * Transform::scale({4, 1, 0.5f});
    const Vec3 n(1, 1, 0);
    const Vec3 tangent1(1, -1, 0), tangent2(0, 0, 1);
    const Vec3 transformedNormal = normalize(t.applyNormal(n));
    EXPECT_NEAR(dot(transformedNormal, normalize(t.applyVector(tangent1))), 0, 1e-6f);
    EXPECT_NEAR(dot(transformedNormal, normalize(t.applyVector(tangent2))), 0, 1e-6f);
    EXPECT_GT(std::abs(dot(normalize(t.applyVector(n)), normalize(t.applyVector(tangent1)))), 0.5f);
}

TEST(TransformTest, BoundsContainEveryTransformedCorner) {
    const Transform t = Transform::rotate(45, {0, 1, 0}) * Transform::scale({1, 2, 3});
    const Bounds3 box({-1, -1, -1}, {1, 1, 1});
    const Bounds3 transformed = t.applyBounds(box);
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p((corner & 1) ? 1.f : -1.f, (corner & 2) ? 1.f : -1.f,
                     (corner & 4) ? 1.f : -1.f);
        EXPECT_TRUE(transformed.contains(t.applyPoint(p)));
    }
}

TEST(TransformTest, PointErrorBoundCoversTheRoundingOfTheProduct) {
    const Transform t = Transform::translate({1e4f, -3e3f, 7}) * Transform::rotate(29, {2, 1, 3}) *
                        Transform::scale({3, 0.25f, 1.5f});
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> coordinate(-1e3f, 1e3f);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
        Vec3 error;
        const Vec3 result = t.applyPoint(p, Vec3(0), error);
        for (int axis = 0; axis < 3; ++axis) {
            const auto& row = t.matrix()[static_cast<std::size_t>(axis)];
            const long double exact = static_cast<long double>(row[0]) * p.x +
                                      static_cast<long double>(row[1]) * p.y +
                                      static_cast<long double>(row[2]) * p.z + row[3];
            EXPECT_LE(std::abs(static_cast<long double>(result[axis]) - exact), error[axis]);
        }
    }
}

}  // namespace
}  // namespace lancer
