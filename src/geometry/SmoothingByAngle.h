#pragma once

#include "geometry/TriangleMesh.h"

namespace lancer {

// Vertex normals for the triangles of a mesh that have none (as Blender's auto-smooth): at each
// corner, the mean of the normals of the triangles around that point (by position) whose normal
// is within the threshold angle of the corner's own triangle's, each weighted by its angle at
// the point. Edges sharper than the threshold stay hard; triangles with normals keep them.
class SmoothingByAngle {
public:
    // The most degrees a "smooth" key may give: beyond 180 every edge is smoothed already.
    static constexpr float kMaxDegrees = 180;

    static void apply(TriangleMesh& mesh, float thresholdDegrees);
};

}  // namespace lancer
