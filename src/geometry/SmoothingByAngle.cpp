#include "geometry/SmoothingByAngle.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

namespace lancer {

namespace {

using PositionKey = std::tuple<float, float, float>;

PositionKey keyOf(const Vec3& p) {
    return {p.x, p.y, p.z};
}

// The unit normal of a triangle, zero if it has no area.
Vec3 faceNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = cross(b - a, c - a);
    const float l = length(n);
    return l > 0 ? n / l : Vec3();
}

}  // namespace

void SmoothingByAngle::apply(TriangleMesh& mesh, float thresholdDegrees) {
    const std::size_t triangles = mesh.triangleCount();
    if (mesh.normals.empty()) mesh.normals.assign(mesh.positions.size(), Vec3());
    const auto vertex = [&](std::size_t t, int k) { return mesh.indices[3 * t + k]; };
    const auto lacksNormals = [&](std::size_t t) {
        for (int k = 0; k < 3; ++k)
            if (mesh.normals[vertex(t, k)] != Vec3()) return false;
        return true;
    };

    std::vector<Vec3> faceNormals(triangles);
    // Each position's corners, as 3 * triangle + corner.
    std::map<PositionKey, std::vector<std::size_t>> cornersAt;
    for (std::size_t t = 0; t < triangles; ++t) {
        faceNormals[t] = faceNormal(mesh.positions[vertex(t, 0)], mesh.positions[vertex(t, 1)],
                                    mesh.positions[vertex(t, 2)]);
        for (int k = 0; k < 3; ++k)
            cornersAt[keyOf(mesh.positions[vertex(t, k)])].push_back(3 * t + k);
    }
    const auto angleAt = [&](std::size_t corner) {
        const std::size_t t = corner / 3;
        const int k = static_cast<int>(corner % 3);
        const Vec3& p = mesh.positions[vertex(t, k)];
        return angleBetween(mesh.positions[vertex(t, (k + 1) % 3)] - p,
                            mesh.positions[vertex(t, (k + 2) % 3)] - p);
    };

    const float cosThreshold =
        std::cos(std::min(thresholdDegrees, kMaxDegrees) * std::numbers::pi_v<float> / 180);
    // A vertex per distinct (original vertex, normal), so that corners that agree share one.
    std::map<std::tuple<std::uint32_t, float, float, float>, std::uint32_t> smoothedVertices;
    for (std::size_t t = 0; t < triangles; ++t) {
        if (!lacksNormals(t) || faceNormals[t] == Vec3()) continue;
        for (int k = 0; k < 3; ++k) {
            Vec3 sum;
            for (const std::size_t corner : cornersAt[keyOf(mesh.positions[vertex(t, k)])]) {
                const Vec3& n = faceNormals[corner / 3];
                if (dot(n, faceNormals[t]) >= cosThreshold) sum += angleAt(corner) * n;
            }
            const Vec3 normal = lengthSquared(sum) > 0 ? normalize(sum) : faceNormals[t];
            const std::uint32_t original = vertex(t, k);
            const auto [it, added] =
                smoothedVertices.try_emplace({original, normal.x, normal.y, normal.z},
                                             static_cast<std::uint32_t>(mesh.positions.size()));
            if (added) {
                const Vec3 position = mesh.positions[original];  // a copy: push_back may move it
                mesh.positions.push_back(position);
                mesh.normals.push_back(normal);
                if (!mesh.uvs.empty()) {
                    const Vec2 uv = mesh.uvs[original];
                    mesh.uvs.push_back(uv);
                }
            }
            mesh.indices[3 * t + k] = it->second;
        }
    }
}

}  // namespace lancer
