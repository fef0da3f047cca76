#pragma once

#include <array>

#include "math/Bounds3.h"
#include "radiosity/RadiosityMesh.h"
#include "scene/RadiositySettings.h"

namespace lancer {

class Material;
class Scene;
class Shape;
class Transform;

// Cuts every diffuse or emissive surface of a scene into patches no longer than the patch size,
// and each patch into elements no longer than the element size: triangles and meshes (instances
// included, in world space), spheres tessellated (the patches are chords, probed onto the true
// sphere), quads, and infinite planes clipped to the scene's box, enlarged a little. Surfaces that
// reflect no diffuse light and emit none (mirrors, clear glass, area lights' own surfaces) are not
// meshed: they only block or transmit the form factors' rays.
class PatchMesher {
public:
    PatchMesher(const Scene& scene, const RadiositySettings& settings);

    RadiosityMesh mesh() const;

    float patchSize() const { return patchSize_; }
    float elementSize() const { return elementSize_; }
    // The box infinite planes are clipped to: the bounded shapes and the camera, enlarged.
    const Bounds3& clipBox() const { return clipBox_; }

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
    void addSphere(RadiosityMesh& mesh, Source source, const Vec3& center, float radius,
                   const Transform& objectToWorld) const;
    // Cuts a surface triangle into patches, and those into elements.
    void addSurfaceTriangle(RadiosityMesh& mesh, const std::array<Vec3, 3>& corners,
                            const Source& source) const;

    const Scene& scene_;
    float patchSize_;
    float elementSize_;
    Bounds3 clipBox_;
};

}  // namespace lancer
