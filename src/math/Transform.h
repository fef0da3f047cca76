#pragma once

#include <array>

#include "math/Bounds3.h"
#include "math/Vec3.h"

namespace lancer {

// An affine transform as a homogeneous 4x4 matrix, kept with its inverse. Points, vectors and
// normals transform differently: normals by the inverse transpose, so that they stay
// perpendicular to the transformed surface under non-uniform scale.
class Transform {
public:
    using Matrix = std::array<std::array<float, 4>, 4>;  // row-major: m[row][column]

    Transform();  // the identity
    // Throws std::invalid_argument when m is singular or not affine (last row not 0 0 0 1).
    explicit Transform(const Matrix& m);

    static Transform translate(const Vec3& delta);
    static Transform scale(const Vec3& factors);
    // Rotation by `degrees` about `axis` through the origin (counter-clockwise looking down the
    // axis).
    static Transform rotate(float degrees, const Vec3& axis);

    // (a * b) applies b first, then a.
    Transform operator*(const Transform& b) const;
    Transform inverse() const;

    Vec3 applyPoint(const Vec3& p) const;
    Vec3 applyVector(const Vec3& v) const;
    Vec3 applyNormal(const Vec3& n) const;  // not normalised
    Bounds3 applyBounds(const Bounds3& b) const;

    // The transformed point and a bound on the rounding error of the result, given a bound
    // `pError` on the error already in p (pbrt 6.8.6).
    Vec3 applyPoint(const Vec3& p, const Vec3& pError, Vec3& resultError) const;
    // The transformed vector and a bound on its rounding error.
    Vec3 applyVector(const Vec3& v, Vec3& resultError) const;

    const Matrix& matrix() const { return m_; }
    // Exactly the identity: applying it changes nothing, with no rounding to account for.
    bool isIdentity() const { return m_ == Transform().m_; }

private:
    Transform(const Matrix& m, const Matrix& inverse) : m_(m), inverse_(inverse) {}

    Matrix m_;
    Matrix inverse_;
};

}  // namespace lancer
