// Smoothing by angle: vertex normals for meshes without them, hard edges above the threshold.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/SmoothingByAngle.h"

namespace lancer {
namespace {

// Adds a triangle of three new vertices (as an OBJ without normals may share none).
void addTriangle(TriangleMesh& mesh, const Vec3& a, const Vec3& b, const Vec3& c) {
    for (const Vec3& p : {a, b, c}) {
        mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
        mesh.positions.push_back(p);
    }
    mesh.faceMaterials.push_back(0);
}

void addQuad(TriangleMesh& mesh, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    addTriangle(mesh, a, b, c);
    addTriangle(mesh, a, c, d);
}

Vec3 faceNormalOf(const TriangleMesh& mesh, std::size_t t) {
    const auto p = [&](int k) { return mesh.positions[mesh.indices[3 * t + k]]; };
    return normalize(cross(p(1) - p(0), p(2) - p(0)));
}

Vec3 cornerNormal(const TriangleMesh& mesh, std::size_t t, int k) {
    return mesh.normals[mesh.indices[3 * t + k]];
}

// The unit cube, faces outward, corners shared by position only.
TriangleMesh cube() {
    TriangleMesh mesh;
    const auto v = [](int i) {
        return Vec3(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
    };
    addQuad(mesh, v(0), v(2), v(3), v(1));  // z = 0
    addQuad(mesh, v(4), v(5), v(7), v(6));  // z = 1
    addQuad(mesh, v(0), v(1), v(5), v(4));  // y = 0
    addQuad(mesh, v(2), v(6), v(7), v(3));  // y = 1
    addQuad(mesh, v(0), v(4), v(6), v(2));  // x = 0
    addQuad(mesh, v(1), v(3), v(7), v(5));  // x = 1
    return mesh;
}

// Unit vectors agree to this: sums of a few products in float.
constexpr float kTolerance = 1e-5f;

void expectNear(const Vec3& a, const Vec3& b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(SmoothingByAngleTest, ACubeAt60DegreesStaysFlat) {
    TriangleMesh mesh = cube();
    SmoothingByAngle::apply(mesh, 60);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k)
            expectNear(cornerNormal(mesh, t, k), faceNormalOf(mesh, t), kTolerance);
}

TEST(SmoothingByAngleTest, ACubeAbove90DegreesIsSmoothedAlongTheDiagonals) {
    TriangleMesh mesh = cube();
    SmoothingByAngle::apply(mesh, 100);
    // Each of the three faces at a corner has 90 degrees there (one or two triangles).
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            const Vec3 p = mesh.positions[mesh.indices[3 * t + k]];
            expectNear(cornerNormal(mesh, t, k), normalize(2.0f * p - Vec3(1)), kTolerance);
        }
}

// An octagonal prism: 45 degrees between sides, 90 between sides and caps. At 60 degrees the
// sides are smooth (each corner the mean of its two sides: the radial direction) and the caps
// flat and sharp.
TEST(SmoothingByAngleTest, APrismKeepsItsCapsSharpAndItsSidesSmooth) {
    TriangleMesh mesh;
    constexpr int kSides = 8;
    const auto rim = [](int i, float y) {
        // i % kSides: the seam's points are the same floats on both sides.
        const float a = 2 * std::numbers::pi_v<float> * static_cast<float>(i % kSides) / kSides;
        return Vec3(std::cos(a), y, -std::sin(a));
    };
    for (int i = 0; i < kSides; ++i) {
        addQuad(mesh, rim(i, 0), rim(i + 1, 0), rim(i + 1, 1), rim(i, 1));
        addTriangle(mesh, Vec3(0, 1, 0), rim(i, 1), rim(i + 1, 1));
        addTriangle(mesh, Vec3(0, 0, 0), rim(i + 1, 0), rim(i, 0));
    }
    SmoothingByAngle::apply(mesh, 60);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3 face = faceNormalOf(mesh, t);
        for (int k = 0; k < 3; ++k) {
            const Vec3 p = mesh.positions[mesh.indices[3 * t + k]];
            if (std::abs(face.y) > 0.5f)
                expectNear(cornerNormal(mesh, t, k), face, kTolerance);  // a cap
            else
                expectNear(cornerNormal(mesh, t, k), normalize(Vec3(p.x, 0, p.z)), kTolerance);
        }
    }
}

TEST(SmoothingByAngleTest, AFineSphereGetsNormalsCloseToTheAnalyticOnes) {
    TriangleMesh mesh;
    constexpr int kRings = 64, kSegments = 128;
    const auto point = [](int ring, int segment) {
        const float theta = std::numbers::pi_v<float> * static_cast<float>(ring) / kRings;
        const float phi =
            2 * std::numbers::pi_v<float> * static_cast<float>(segment % kSegments) / kSegments;
        return Vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                    -std::sin(theta) * std::sin(phi));
    };
    for (int r = 0; r < kRings; ++r)
        for (int s = 0; s < kSegments; ++s) {
            if (r > 0) addTriangle(mesh, point(r, s), point(r + 1, s), point(r, s + 1));
            if (r + 1 < kRings)
                addTriangle(mesh, point(r, s + 1), point(r + 1, s), point(r + 1, s + 1));
        }
    SmoothingByAngle::apply(mesh, 30);
    // Rings 2.8 degrees apart: a normal within 2 degrees of the true one is closer than a facet's
    // (the worst corners, 1.4 degrees off, are by the poles, where the triangles are thinnest
    // and the angle weights lean towards the ring's direction).
    float worst = 1;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            const Vec3 p = mesh.positions[mesh.indices[3 * t + k]];
            worst = std::min(worst, dot(cornerNormal(mesh, t, k), normalize(p)));
        }
    EXPECT_GT(worst, std::cos(2.0f * std::numbers::pi_v<float> / 180));
}

TEST(SmoothingByAngleTest, TrianglesWithNormalsKeepThem) {
    TriangleMesh mesh = cube();
    mesh.normals.assign(mesh.positions.size(), Vec3());
    for (int k = 0; k < 3; ++k)
        mesh.normals[mesh.indices[k]] = Vec3(0.6f, 0, 0.8f);  // the first triangle's own
    SmoothingByAngle::apply(mesh, 100);
    for (int k = 0; k < 3; ++k)
        expectNear(cornerNormal(mesh, 0, k), Vec3(0.6f, 0, 0.8f), 0);
    expectNear(cornerNormal(mesh, 1, 0), -normalize(Vec3(1, 1, 1)), kTolerance);  // at (0,0,0)
}

}  // namespace
}  // namespace lancer
