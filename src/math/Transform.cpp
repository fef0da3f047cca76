#include "math/Transform.h"

#include <cmath>
#include <stdexcept>

#include "math/Float.h"

namespace lancer {

namespace {

constexpr Transform::Matrix kIdentity{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

Transform::Matrix multiply(const Transform::Matrix& a, const Transform::Matrix& b) {
    Transform::Matrix r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double sum = 0;
            for (int k = 0; k < 4; ++k)
                sum += double(a[i][k]) * double(b[k][j]);
            r[i][j] = static_cast<float>(sum);
        }
    return r;
}

// Gauss-Jordan elimination with partial pivoting, in double precision.
bool invert(const Transform::Matrix& m, Transform::Matrix& result) {
    double a[4][8];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            a[i][j] = m[i][j];
            a[i][j + 4] = i == j ? 1 : 0;
        }
    for (int column = 0; column < 4; ++column) {
        int pivot = column;
        for (int row = column + 1; row < 4; ++row)
            if (std::abs(a[row][column]) > std::abs(a[pivot][column])) pivot = row;
        if (std::abs(a[pivot][column]) < 1e-30) return false;
        std::swap(a[pivot], a[column]);
        const double scale = 1 / a[column][column];
        for (double& v : a[column])
            v *= scale;
        for (int row = 0; row < 4; ++row) {
            if (row == column) continue;
            const double factor = a[row][column];
            for (int j = 0; j < 8; ++j)
                a[row][j] -= factor * a[column][j];
        }
    }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            result[i][j] = static_cast<float>(a[i][j + 4]);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(result[i][j])) return false;
    return true;
}

}  // namespace

Transform::Transform() : m_(kIdentity), inverse_(kIdentity) {}

Transform::Transform(const Matrix& m) : m_(m) {
    if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1)
        throw std::invalid_argument("the matrix is not affine: its last row must be 0 0 0 1");
    if (!invert(m, inverse_))
        throw std::invalid_argument("the matrix is singular (it flattens space)");
}

Transform Transform::translate(const Vec3& d) {
    Matrix m = kIdentity, inv = kIdentity;
    for (int i = 0; i < 3; ++i) {
        m[i][3] = d[i];
        inv[i][3] = -d[i];
    }
    return {m, inv};
}

Transform Transform::scale(const Vec3& s) {
    if (s.x == 0 || s.y == 0 || s.z == 0) throw std::invalid_argument("a scale factor is zero");
    Matrix m = kIdentity, inv = kIdentity;
    for (int i = 0; i < 3; ++i) {
        m[i][i] = s[i];
        inv[i][i] = 1 / s[i];
    }
    return {m, inv};
}

Transform Transform::rotate(float degrees, const Vec3& axis) {
    if (!(lengthSquared(axis) > 0)) throw std::invalid_argument("the rotation axis is zero");
    const Vec3 a = normalize(axis);
    const double theta = double(degrees) * (3.14159265358979323846 / 180.0);
    const double s = std::sin(theta), c = std::cos(theta);
    // Rodrigues' formula.
    Matrix m = kIdentity;
    const double x = a.x, y = a.y, z = a.z;
    const double r[3][3] = {
        {c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s},
        {y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s},
        {z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)}};
    Matrix inv = kIdentity;  // a rotation's inverse is its transpose
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            m[i][j] = static_cast<float>(r[i][j]);
            inv[j][i] = static_cast<float>(r[i][j]);
        }
    return {m, inv};
}

Transform Transform::operator*(const Transform& b) const {
    return {multiply(m_, b.m_), multiply(b.inverse_, inverse_)};
}

Transform Transform::inverse() const {
    return {inverse_, m_};
}

Vec3 Transform::applyPoint(const Vec3& p) const {
    Vec3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = m_[i][0] * p.x + m_[i][1] * p.y + m_[i][2] * p.z + m_[i][3];
    return r;
}

Vec3 Transform::applyVector(const Vec3& v) const {
    Vec3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = m_[i][0] * v.x + m_[i][1] * v.y + m_[i][2] * v.z;
    return r;
}

Vec3 Transform::applyNormal(const Vec3& n) const {
    Vec3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = inverse_[0][i] * n.x + inverse_[1][i] * n.y + inverse_[2][i] * n.z;
    return r;
}

Bounds3 Transform::applyBounds(const Bounds3& b) const {
    Bounds3 r;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                     (corner & 4) ? b.max.z : b.min.z);
        r = merge(r, applyPoint(p));
    }
    return r;
}

Vec3 Transform::applyPoint(const Vec3& p, const Vec3& pError, Vec3& resultError) const {
    for (int i = 0; i < 3; ++i) {
        const float absTerms = std::abs(m_[i][0] * p.x) + std::abs(m_[i][1] * p.y) +
                               std::abs(m_[i][2] * p.z) + std::abs(m_[i][3]);
        const float propagated = std::abs(m_[i][0]) * pError.x + std::abs(m_[i][1]) * pError.y +
                                 std::abs(m_[i][2]) * pError.z;
        resultError[i] = (gamma(3) + 1) * propagated + gamma(3) * absTerms;
    }
    return applyPoint(p);
}

Vec3 Transform::applyVector(const Vec3& v, Vec3& resultError) const {
    for (int i = 0; i < 3; ++i)
        resultError[i] = gamma(3) * (std::abs(m_[i][0] * v.x) + std::abs(m_[i][1] * v.y) +
                                     std::abs(m_[i][2] * v.z));
    return applyVector(v);
}

}  // namespace lancer
