#include "radiosity/RadiosityMesh.h"

#include <algorithm>
#include <bit>

#include "lights/Light.h"
#include "sampling/Sampling.h"
#include "scene/Scene.h"

namespace lancer {

namespace {

std::uint64_t fold(std::uint64_t h, float v) {
    return hashValues(h, std::bit_cast<std::uint32_t>(v));
}
std::uint64_t fold(std::uint64_t h, const Vec3& v) {
    return fold(fold(fold(h, v.x), v.y), v.z);
}
std::uint64_t fold(std::uint64_t h, const Color& c) {
    return fold(fold(fold(h, c.r), c.g), c.b);
}

}  // namespace

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

float RadiosityMesh::longestEdge(const std::array<Vec3, 3>& t) {
    return std::max({length(t[1] - t[0]), length(t[2] - t[1]), length(t[0] - t[2])});
}

std::uint32_t RadiosityMesh::addElement(std::uint32_t patch, const std::array<Vec3, 3>& corners,
                                        int level) {
    Element e;
    e.corners = corners;
    e.patch = patch;
    e.level = level;
    e.area = 0.5f * length(cross(corners[1] - corners[0], corners[2] - corners[0]));
    e.centroid = (corners[0] + corners[1] + corners[2]) / 3.0f;
    e.longestEdge = longestEdge(corners);
    for (const Vec3& corner : corners)
        e.radius = std::max(e.radius, length(corner - e.centroid));
    e.normal = patches[patch].normal;
    e.surfacePoint = e.centroid;
    e.surfaceNormal = e.normal;
    elements.push_back(e);
    return static_cast<std::uint32_t>(elements.size() - 1);
}

std::uint32_t RadiosityMesh::split(std::uint32_t element) {
    const std::array<Vec3, 3> c = elements[element].corners;
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

std::vector<std::uint32_t> RadiosityMesh::leaves() const {
    std::vector<std::uint32_t> result;
    for (std::uint32_t i = 0; i < elements.size(); ++i)
        if (elements[i].isLeaf()) result.push_back(i);
    return result;
}

std::uint64_t RadiosityMesh::fingerprint(const Scene& scene,
                                         const RadiositySettings& settings) const {
    std::uint64_t h = hashValues(patches.size(), elements.size());
    for (const Patch& p : patches) {
        for (const Vec3& c : p.corners)
            h = fold(h, c);
        h = fold(fold(h, p.emission[0]), p.emission[1]);
        for (std::uint32_t e = p.firstElement; e < p.firstElement + p.elementCount; ++e)
            h = fold(h, elements[e].reflectance);
    }
    // A light is known by what it delivers to two fixed points, and by its power.
    for (const auto& light : scene.lights())
        for (const Vec3& probe : {Vec3(0.123f, 0.456f, 0.789f), Vec3(-7.1f, 3.3f, -2.9f)}) {
            const LightSample s = light->sample(probe, Vec2(0.25f, 0.75f));
            h = fold(fold(fold(fold(h, s.wi), s.irradiance), s.position), light->power(1));
        }
    h = fold(fold(fold(h, settings.patchSize), settings.elementSize), settings.threshold);
    h = fold(h, settings.subdivisionTolerance);
    // The glossy transport's samples, where there is a glossy surface for it to follow.
    h = hashValues(h, scene.hasGlossyMaterial() ? settings.glossySamples : 0);
    return hashValues(h, settings.maxShots, settings.subdivisionLevels, settings.visibilityRays);
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
