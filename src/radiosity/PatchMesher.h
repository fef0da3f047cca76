#pragma once

#include <array>
#include <vector>

#include "math/Bounds3.h"
#include "radiosity/RadiosityMesh.h"
#include "scene/RadiositySettings.h"

namespace lancer {

class ContactCutter;
class Material;
class Scene;
class Shape;
struct Tessellation;

// Cuts every diffuse or emissive surface of a scene into patches no longer than the patch size,
// and each patch into elements no longer than the element size, from the facets each shape
// tessellates itself into (in world space; a sphere's are chords, probed onto the true sphere;
// infinite planes are clipped to the box of the bounded shapes and the camera, enlarged a little).
// Surfaces that reflect no diffuse light and emit none (mirrors, clear glass, area lights' own
// surfaces) are not meshed: they only block or transmit the form factors' rays. Flat surfaces are
// first cut along the contact lines of the objects standing on them (ContactCutter), and the
// pieces inside those objects are left out, so that no element straddles a contact line or lies
// where no light reaches. A facet repeated at the same place (the same three corners, either way
// round) is meshed once: every receiver would see it twice. McGuire's Cornell boxes give a face of
// each block twice (their bottom faces name the wrong vertices), and a wall may be modelled as two
// faces back to back. A repeat is meshed all the same where it emits on a side the first does not
// (a two-sided lamp made of two faces).
class PatchMesher {
public:
    PatchMesher(const Scene& scene, const RadiositySettings& settings);

    RadiosityMesh mesh() const;

    float patchSize() const { return patchSize_; }
    float elementSize() const { return elementSize_; }

private:
    // Where a surface triangle comes from, for its patches.
    struct Source {
        const Shape* surface;
        const Material* material;
        bool emitsOnBothSides;
        bool curved;
        float probeDistance;
    };

    // Per shape and facet, whether it repeats an earlier meshed facet and is not meshed.
    std::vector<std::vector<bool>> repeatedFacets(
        const std::vector<const Shape*>& shapes,
        const std::vector<Tessellation>& tessellations) const;
    void addShape(RadiosityMesh& mesh, const Shape& shape, const Tessellation& tessellation,
                  const std::vector<bool>& repeated, const ContactCutter& cutter) const;
    // The parts of a convex polygon in the cells of a square grid in its plane, each cell a pair of
    // patches.
    std::vector<std::vector<Vec3d>> gridCells(const std::vector<Vec3d>& polygon,
                                              const Vec3& normal) const;
    // Whether a piece of a surface is enclosed by a solid standing on it: rays from its centre
    // over its front hemisphere all meet, within about `reach`, the back of an opaque surface
    // first.
    bool isEnclosed(const std::vector<Vec3d>& piece, const Vec3& normal, float reach) const;
    // Cuts a surface triangle into patches, and those into elements.
    void addSurfaceTriangle(RadiosityMesh& mesh, const std::array<Vec3, 3>& corners,
                            const Source& source) const;

    const Scene& scene_;
    float patchSize_;
    float elementSize_;
    Bounds3 clipBox_;  // where infinite shapes are cut
    // How far from a surface's plane another facet's corner may lie and count as in it (a ten
    // thousandth of the scene's size).
    float contactTolerance_;
};

}  // namespace lancer
