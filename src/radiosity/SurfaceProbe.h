#pragma once

#include <array>
#include <optional>

#include "geometry/Hit.h"
#include "math/Color.h"
#include "radiosity/Element.h"
#include "radiosity/Patch.h"

namespace lancer {

// Finds, for a point of a flat patch, the matching point of the shape the patch meshes, by a
// short ray along the patch's normal: the true surface of a sphere the patch is a chord of, and
// the material and texture coordinates there.
class SurfaceProbe {
public:
    // The surface hit nearest the point, if the probe finds it.
    static std::optional<Hit> at(const Patch& patch, const Vec3& point);
    // The point moved onto the true surface (unchanged on flat surfaces, or if the probe fails).
    static Vec3 onSurface(const Patch& patch, const Vec3& point);
    // Sets the element's surface point and normal from its centroid, and its reflectance.
    static void place(const Patch& patch, const std::array<Vec3, 3>& corners, Element& element);
    // kd averaged over four points of the triangle (its centroid and three points around it).
    static Color reflectance(const Patch& patch, const std::array<Vec3, 3>& corners);
    // The emitted radiance averaged over the same four points (a textured emitter's patch).
    static Color emission(const Patch& patch, const std::array<Vec3, 3>& corners);

private:
    // `ofHit` averaged over the four points, the material at the point `p` (uv (0, 0)) standing
    // in where the probe misses.
    template <typename OfHit>
    static Color average(const Patch& patch, const std::array<Vec3, 3>& corners, OfHit ofHit);
};

}  // namespace lancer
