#pragma once

#include <array>
#include <cstdint>

#include "math/Color.h"
#include "math/Vec3.h"

namespace lancer {

class Material;
class Shape;

// A surface's two sides: the front is the side the patch's normal points to.
enum class Side : std::uint8_t { Front = 0, Back = 1 };
inline constexpr std::array<Side, 2> kBothSides{Side::Front, Side::Back};
inline constexpr std::size_t sideIndex(Side s) {
    return static_cast<std::size_t>(s);
}

// A shooting patch of progressive refinement radiosity: a flat triangle of a diffuse surface,
// cut into elements (its receivers). A patch shoots what its elements have not shot yet, each
// element from its own place (so that a patch partly in shadow or hidden under an object shoots
// from its lit part). Each side shoots on its own: the unshot radiosity is kept
// per side, so that a wall lit from both sides is right on both.
struct Patch {
    std::array<Vec3, 3> corners;  // counter-clockwise about the normal
    Vec3 normal;                  // unit
    float area = 0;
    // The scene shape it meshes: its true surface, where visibility rays must start and end.
    const Shape* surface = nullptr;
    const Material* material = nullptr;  // the face's, when the probe cannot tell
    // Whether the flat patch only approximates a curved surface (a sphere), so that points on
    // it are moved onto the surface before rays are traced; probeDistance bounds the gap.
    bool curved = false;
    float probeDistance = 0;
    // Radiance emitted on each side (zero on a side that does not emit).
    std::array<Color, 2> emission;
    // Radiosity (W/m^2) not yet shot per side: the area-weighted mean of its elements'.
    std::array<Color, 2> unshot;
    std::uint32_t firstElement = 0;  // its elements are [firstElement, firstElement + elementCount)
    std::uint32_t elementCount = 0;

    Vec3 centroid() const { return (corners[0] + corners[1] + corners[2]) / 3.0f; }
};

}  // namespace lancer
