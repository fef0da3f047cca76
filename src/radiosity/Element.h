#pragma once

#include <array>
#include <cstdint>

#include "math/Color.h"
#include "math/Vec3.h"
#include "radiosity/Patch.h"

namespace lancer {

// A receiving element: a flat triangle of a patch, whose irradiance the solution stores. Elements
// that the adaptive subdivision splits get four children (the triangle cut at its edges'
// midpoints), stored one after the other; the leaves are what the image shows.
//
// Three cache lines: the refinement reads the first (its shape) of most elements it judges, the
// second of some, the third hardly ever (the corners were in an array of their own, which made
// two cache misses of one, the most frequent of the 200k-triangle knot's refinement).
struct alignas(64) Element {
    static constexpr std::uint32_t kNone = ~std::uint32_t{0};

    std::array<Vec3, 3> corners;
    Vec3 centroid;  // on the flat triangle
    float area = 0;
    float longestEdge = 0;
    float radius = 0;  // the distance from the centroid to the farthest corner
    std::uint32_t patch = 0;

    std::uint32_t firstChild = kNone;  // the first of 4 children, or kNone for a leaf
    int level = 0;                     // 0 for the elements cut from a patch
    Vec3 normal;                       // unit, the patch's
    Color reflectance;                 // kd averaged over the element
    // The centroid moved onto the shape's true surface, where rays start, and the surface's
    // geometric normal there (which rays are offset along).
    Vec3 surfacePoint;
    Vec3 surfaceNormal;
    // Irradiance (W/m^2) on each side, from the lights and all patches.
    std::array<Color, 2> irradiance;
    // Radiosity (W/m^2) emitted or reflected and not shot yet, and shot so far, per side (for the
    // elements cut from patches, which shoot; subdivision's children only receive).
    std::array<Color, 2> unshot;
    std::array<Color, 2> shot;

    bool isLeaf() const { return firstChild == kNone; }
    // Side `side`'s normal at the surface point: the true surface's there (a curved patch's flat
    // element leans away from it, and light falling on the surface goes by that), turned to the
    // side.
    Vec3 surfaceSideNormal(Side side) const {
        const Vec3 front = dot(surfaceNormal, normal) < 0 ? -surfaceNormal : surfaceNormal;
        return side == Side::Front ? front : -front;
    }
};
static_assert(sizeof(Element) == 3 * 64);

}  // namespace lancer
