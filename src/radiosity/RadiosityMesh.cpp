#include "radiosity/RadiosityMesh.h"

#include <algorithm>

namespace lancer {

std::vector<std::array<Vec3, 3>> RadiosityMesh::subdivide(const std::array<Vec3, 3>& triangle,
                                                          int n) {
    // Grid points a + (i e1 + j e2) / n with i + j <= n; each cell (i, j) gives an upright
    // triangle and, away from the diagonal, an inverted one.
    const Vec3 e1 = triangle[1] - triangle[0], e2 = triangle[2] - triangle[0];
    const float step = 1.0f / static_cast<float>(n);
    const auto at = [&](int i, int j) {
        if (i == n && j == 0) return triangle[1];
        if (i == 0 && j == n) return triangle[2];
        return triangle[0] + (static_cast<float>(i) * step) * e1 +
               (static_cast<float>(j) * step) * e2;
    };
    std::vector<std::array<Vec3, 3>> pieces;
    pieces.reserve(static_cast<std::size_t>(n * n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i + j < n; ++i) {
            pieces.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
            if (i + j + 1 < n) pieces.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return pieces;
}

std::uint32_t RadiosityMesh::addElement(std::uint32_t patch, const std::array<Vec3, 3>& corners,
                                        int level) {
    Element e;
    for (std::size_t k = 0; k < 3; ++k) {
        e.vertices[k] = static_cast<std::uint32_t>(positions.size());
        positions.push_back(corners[k]);
    }
    e.patch = patch;
    e.level = level;
    e.area = 0.5f * length(cross(corners[1] - corners[0], corners[2] - corners[0]));
    e.centroid = (corners[0] + corners[1] + corners[2]) / 3.0f;
    e.normal = patches[patch].normal;
    e.surfacePoint = e.centroid;
    e.surfaceNormal = e.normal;
    elements.push_back(e);
    return static_cast<std::uint32_t>(elements.size() - 1);
}

std::uint32_t RadiosityMesh::split(std::uint32_t element) {
    const std::array<Vec3, 3> c = corners(elements[element]);
    const Vec3 m01 = 0.5f * (c[0] + c[1]), m12 = 0.5f * (c[1] + c[2]), m20 = 0.5f * (c[2] + c[0]);
    const std::uint32_t patch = elements[element].patch;
    const int level = elements[element].level + 1;
    const std::uint32_t first = addElement(patch, {c[0], m01, m20}, level);
    addElement(patch, {m01, c[1], m12}, level);
    addElement(patch, {m20, m12, c[2]}, level);
    addElement(patch, {m12, m20, m01}, level);
    elements[element].firstChild = first;
    return first;
}

std::array<Vec3, 3> RadiosityMesh::corners(const Element& element) const {
    return {positions[element.vertices[0]], positions[element.vertices[1]],
            positions[element.vertices[2]]};
}

std::vector<std::uint32_t> RadiosityMesh::leaves() const {
    std::vector<std::uint32_t> result;
    for (std::uint32_t i = 0; i < elements.size(); ++i)
        if (elements[i].isLeaf()) result.push_back(i);
    return result;
}

float RadiosityMesh::lookupDistance(float patchSize) const {
    float distance = 1e-4f * patchSize;
    for (const Patch& p : patches)
        distance = std::max(distance, p.probeDistance);
    return distance;
}

Color RadiosityMesh::unshotPower() const {
    Color sum;
    for (const Patch& p : patches)
        sum += (p.unshot[0] + p.unshot[1]) * p.area;
    return sum;
}

}  // namespace lancer
