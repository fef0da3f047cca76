#include "radiosity/VertexSmoothing.h"

#include <cmath>
#include <unordered_map>

#include "radiosity/SurfaceProbe.h"
#include "sampling/Sampling.h"
#include "scene/Scene.h"

namespace lancer {

VertexSmoothing::VertexSmoothing(const RadiosityMesh& mesh, std::vector<std::uint32_t> leaves,
                                 double cell)
    : mesh_(mesh), leaves_(std::move(leaves)) {
    struct Key {
        std::int64_t x, y, z;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            return static_cast<std::size_t>(hashValues(static_cast<std::uint64_t>(k.x),
                                                       static_cast<std::uint64_t>(k.y),
                                                       static_cast<std::uint64_t>(k.z)));
        }
    };
    std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> buckets;
    std::vector<Vec3> vertexNormals;
    std::vector<float> weights;
    faceVertices.resize(leaves_.size());
    for (std::size_t i = 0; i < leaves_.size(); ++i) {
        const Element& e = mesh.elements[leaves_[i]];
        const float brightness = std::max(e.irradiance[0].average(), e.irradiance[1].average());
        for (std::size_t k = 0; k < 3; ++k) {
            const Vec3& p = e.corners[k];
            const Key key{std::llround(p.x / cell), std::llround(p.y / cell),
                          std::llround(p.z / cell)};
            std::vector<std::uint32_t>& bucket = buckets[key];
            std::uint32_t vertex = Element::kNone;
            for (std::uint32_t v : bucket)
                if (dot(vertexNormals[v], e.normal) > 0.5f) vertex = v;
            if (vertex == Element::kNone) {
                vertex = static_cast<std::uint32_t>(vertexNormals.size());
                vertexNormals.push_back(e.normal);
                meanNormals_.emplace_back();
                vertexIrradiance.emplace_back();
                weights.push_back(0);
                sites_.emplace_back();
                bucket.push_back(vertex);
            }
            faceVertices[i][k] = vertex;
            weights[vertex] += e.area;
            // Each leaf's normal weighs by its angle at the vertex (Thuermer and Wuethrich 1998):
            // unlike its area, that angle does not change when the leaves around are split.
            meanNormals_[vertex] +=
                angleBetween(e.corners[(k + 1) % 3] - p, e.corners[(k + 2) % 3] - p) * e.normal;
            for (std::size_t side = 0; side < 2; ++side)
                vertexIrradiance[vertex][side] += e.irradiance[side] * e.area;
            Site& site = sites_[vertex];
            // (The first leaf stands where the brightness is NaN, from an emission so large that
            // the irradiance overflows: no comparison is true.)
            if (site.leaf == Element::kNone || brightness > site.brightness)
                site = {leaves_[i], k, brightness};
        }
    }
    for (std::size_t v = 0; v < weights.size(); ++v) {
        for (Color& c : vertexIrradiance[v])
            c /= weights[v];
        // (Leaves of no area leave the first leaf's normal.)
        meanNormals_[v] =
            length(meanNormals_[v]) > 0 ? normalize(meanNormals_[v]) : vertexNormals[v];
    }
    vertexDirect.resize(vertexIrradiance.size());
}

Element VertexSmoothing::gatherSite(const Scene& scene, std::size_t vertex,
                                    std::uint64_t& rayCount) const {
    const Site& site = sites_[vertex];
    Element at = mesh_.elements[site.leaf];
    Vec3 corner = at.corners[site.corner];
    const Patch& patch = mesh_.patches[at.patch];
    // (A curved patch's corners are on its own surface, which the chord to them would meet.)
    if (!patch.curved) {
        const Ray towards{at.surfacePoint, corner - at.surfacePoint};
        ++rayCount;
        const std::optional<Hit> blocker = scene.intersect(towards, 1);
        // A surface met at the vertex itself stands on the leaf there (a contact line, a room's
        // edge): the vertex is gathered a tenth of the way in, close to the contact, where the
        // light falls steeply, but off the concave edge, where links are least accurate.
        if (blocker && blocker->t > 1e-3f)
            corner = at.surfacePoint +
                     (blocker->t < 1 - 1e-3f ? 0.5f * blocker->t : 0.9f) * towards.direction;
    }
    at.centroid = corner + 0.02f * (at.centroid - corner);
    at.surfacePoint = at.centroid;
    if (patch.curved) {
        // (A curved patch's true normal is known: the leaves' normals are only its chords'.)
        at.surfaceNormal = at.normal;
        if (const std::optional<Hit> hit = SurfaceProbe::at(patch, at.centroid)) {
            at.surfacePoint = hit->p;
            at.surfaceNormal = hit->ng;
        }
    } else {
        at.normal = at.surfaceNormal = meanNormals_[vertex];
    }
    return at;
}

RadiositySolution VertexSmoothing::solution(float lookupDistance, std::uint64_t fingerprint,
                                            const RadiosityStatistics& statistics) && {
    std::vector<std::array<Vec3, 3>> faces;
    faces.reserve(leaves_.size());
    for (std::uint32_t e : leaves_)
        faces.push_back(mesh_.elements[e].corners);
    return RadiositySolution(std::move(faces), std::move(faceVertices), std::move(vertexIrradiance),
                             std::move(vertexDirect), lookupDistance, fingerprint, statistics);
}

}  // namespace lancer
