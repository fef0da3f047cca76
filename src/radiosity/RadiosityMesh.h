#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "radiosity/Element.h"
#include "radiosity/Patch.h"
#include "scene/RadiositySettings.h"

namespace lancer {

class Scene;

// The scene's diffuse surfaces cut into shooting patches and, below them, receiving elements
// (two-level substructuring, Cohen et al. 1986), all flat triangles in world space.
class RadiosityMesh {
public:
    std::vector<Patch> patches;
    std::vector<Element> elements;

    // The triangle cut into n^2 triangles like it (n pieces per edge), oriented like it.
    static std::vector<std::array<Vec3, 3>> subdivide(const std::array<Vec3, 3>& triangle, int n);

    static float longestEdge(const std::array<Vec3, 3>& triangle);

    // Appends an element of `patch` over `corners` (its surface point and reflectance are left
    // for the caller) and returns its index.
    std::uint32_t addElement(std::uint32_t patch, const std::array<Vec3, 3>& corners, int level);
    // Splits a leaf into four children at its edges' midpoints; returns the first child's index.
    std::uint32_t split(std::uint32_t element);

    // The indices of the elements that have no children.
    std::vector<std::uint32_t> leaves() const;
    // A hash of the patches (geometry, emission, the elements' reflectance), the scene's lights
    // and the radiosity settings, for the solutions' fingerprints.
    std::uint64_t fingerprint(const Scene& scene, const RadiositySettings& settings) const;
    // How far from a leaf a solution looks its points up: beyond rounding on flat patches, and
    // as far as the true surface of curved ones is from their chords.
    float lookupDistance(float patchSize) const;
    // The power (W) received by the patches and not shot yet, over both sides.
    Color unshotPower() const;
};

}  // namespace lancer
