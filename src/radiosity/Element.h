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
struct Element {
    static constexpr std::uint32_t kNone = ~std::uint32_t{0};

    std::array<std::uint32_t, 3> vertices{};  // indices into RadiosityMesh::positions
    std::uint32_t patch = 0;
    std::uint32_t firstChild = kNone;  // the first of 4 children, or kNone for a leaf
    int level = 0;                     // 0 for the elements cut from a patch
    float area = 0;
    // Its longest edge, and the distance from its centroid to its farthest corner (the radius of
    // a bounding sphere): what the refinement reads of most elements it judges, kept here, near
    // the centroid, rather than read from the three corners.
    float longestEdge = 0;
    float radius = 0;
    Vec3 centroid;  // on the flat triangle
    Vec3 normal;    // unit, the patch's
    // The centroid moved onto the shape's true surface, where rays start, and the surface's
    // geometric normal there (which rays are offset along).
    Vec3 surfacePoint;
    Vec3 surfaceNormal;
    Color reflectance;  // kd averaged over the element
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

}  // namespace lancer
