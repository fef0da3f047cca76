#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "math/Color.h"
#include "radiosity/Element.h"
#include "radiosity/RadiosityMesh.h"
#include "radiosity/RadiositySolution.h"

namespace lancer {

class Scene;

// The leaves of a radiosity mesh welded into shared vertices for smooth (Gouraud) interpolation:
// corners at one place are one vertex where the leaves' normals agree within 60 degrees, and each
// vertex starts with the area-weighted mean irradiance of the leaves around it. A solver may then
// gather the irradiance at the vertices themselves (Wallace et al. 1989 evaluate at vertices):
// corners and contact lines come out right, where averaging the leaves' values smooths them away.
class VertexSmoothing {
public:
    // `cell`: corners closer than this are one vertex (midpoints of a shared edge are computed
    // alike on both sides, so the cells only absorb rounding).
    VertexSmoothing(const RadiosityMesh& mesh, std::vector<std::uint32_t> leaves, double cell);

    // Per leaf (in the order given), its corners' vertices.
    std::vector<std::array<std::uint32_t, 3>> faceVertices;
    // Per vertex, its irradiance on the front and back, and the part of it straight from the
    // sampled emitters (SplitIrradiance; none until a solver gathers it at the vertices).
    std::vector<std::array<Color, 2>> vertexIrradiance;
    std::vector<std::array<Color, 2>> vertexDirect;

    // Where to gather a vertex's irradiance: a copy of the brightest leaf around it (so that a
    // corner on a contact line takes the visible side's value), moved 2% of the way from the
    // vertex to the leaf's centroid (inside the leaf, not on its edge), or from halfway to
    // another surface the vertex lies beyond (a box's edge sunk into the floor), or from a tenth
    // of the way in when a surface meets the vertex itself (a contact line). The copy faces the
    // angle-weighted mean normal of the leaves around the vertex: on a curved mesh the brightest
    // leaf's own normal is the one turned most towards the light, which would make the vertex
    // take the brightest value of its fan. The copy's surface point is on the shape's true
    // surface. `rayCount` grows by the rays traced.
    Element gatherSite(const Scene& scene, std::size_t vertex, std::uint64_t& rayCount) const;
    // The leaf a vertex is gathered on (see gatherSite).
    std::uint32_t siteLeaf(std::size_t vertex) const { return sites_[vertex].leaf; }

    // The solution these vertices make, looked up within `lookupDistance` of the leaves.
    RadiositySolution solution(float lookupDistance, std::uint64_t fingerprint,
                               const RadiosityStatistics& statistics) &&;

private:
    struct Site {
        std::uint32_t leaf = Element::kNone;
        std::size_t corner = 0;
        float brightness = -1;
    };
    const RadiosityMesh& mesh_;
    std::vector<std::uint32_t> leaves_;
    std::vector<Site> sites_;
    std::vector<Vec3> meanNormals_;
};

}  // namespace lancer
