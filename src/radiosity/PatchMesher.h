#pragma once

#include <array>

#include "math/Bounds3.h"
#include "radiosity/RadiosityMesh.h"
#include "scene/RadiositySettings.h"

namespace lancer {

class Material;
class Scene;
class Shape;

// Cuts every diffuse or emissive surface of a scene into patches no longer than the patch size,
// and each patch into elements no longer than the element size, from the facets each shape
// tessellates itself into (in world space; a sphere's are chords, probed onto the true sphere;
// infinite planes are clipped to the box of the bounded shapes and the camera, enlarged a little).
// Surfaces that reflect no diffuse light and emit none (mirrors, clear glass, area lights' own
// surfaces) are not meshed: they only block or transmit the form factors' rays.
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

    void addShape(RadiosityMesh& mesh, const Shape& shape) const;
    // Cuts a surface triangle into patches, and those into elements.
    void addSurfaceTriangle(RadiosityMesh& mesh, const std::array<Vec3, 3>& corners,
                            const Source& source) const;

    const Scene& scene_;
    float patchSize_;
    float elementSize_;
    Bounds3 clipBox_;  // where infinite shapes are cut
};

}  // namespace lancer
