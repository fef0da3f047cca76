#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "math/Color.h"
#include "math/Vec2.h"
#include "math/Vec3.h"
#include "radiosity/Element.h"
#include "radiosity/Patch.h"
#include "radiosity/RadiosityMesh.h"

namespace lancer {

// Clusters for hierarchical radiosity (Smits, Arvo and Greenberg 1994; Sillion 1995): the
// patches' root elements grouped into a binary tree of volumes by median splits along the longest
// axis, so that groups of patches far from each other (a scanned model's many small triangles and
// a wall) are linked as wholes, and the link count stays near linear in the number of elements.
//
// A node is an element or a cluster: cluster nodes carry kTag, so that one number names either
// (a link's ends, a candidate's). A cluster's children are two nodes, clusters or root elements.
// A cluster shines and receives through its members' own orientations (per-member cosines): the
// irradiance it delivers is the sum of its members' point-to-point terms, each from the member's
// side that faces the receiver.
class ClusterHierarchy {
public:
    static constexpr std::uint32_t kTag = std::uint32_t{1} << 31;
    static bool isCluster(std::uint32_t node) { return (node & kTag) != 0; }
    static std::uint32_t indexOf(std::uint32_t node) { return node & ~kTag; }
    static std::uint32_t nodeOf(std::uint32_t cluster) { return cluster | kTag; }

    struct Cluster {
        Vec3 center;            // of the box around its members' corners
        float radius = 0;       // half that box's diagonal: a bounding sphere
        float area = 0;         // its members' total
        float reflectance = 0;  // the largest of its members' (averaged over the channels)
        std::array<std::uint32_t, 2> children{};  // nodes
        std::uint32_t parent = Element::kNone;    // cluster index, kNone for the top
        std::uint32_t firstMember = 0;            // its members are members()[first, first + count)
        std::uint32_t memberCount = 0;
    };
    // Where a node is, as a bounding sphere.
    struct Extent {
        Vec3 center;
        float radius = 0;
    };

    ClusterHierarchy() = default;
    // Over the given root elements of the mesh (at least two make a cluster).
    ClusterHierarchy(const RadiosityMesh& mesh, std::vector<std::uint32_t> roots);

    bool empty() const { return clusters_.empty(); }
    // The top cluster's node.
    std::uint32_t top() const { return nodeOf(0); }
    const std::vector<Cluster>& clusters() const { return clusters_; }
    const Cluster& cluster(std::uint32_t node) const { return clusters_[indexOf(node)]; }
    std::span<const std::uint32_t> members(const Cluster& c) const {
        return {members_.data() + c.firstMember, c.memberCount};
    }
    // The cluster (index) a root element is a child of, kNone for any other element.
    std::uint32_t parentOf(std::uint32_t element) const {
        return element < rootParent_.size() ? rootParent_[element] : Element::kNone;
    }

    Extent extent(const RadiosityMesh& mesh, std::uint32_t node) const;

    // The irradiance a node delivers at `at` across a plane facing it (at normal incidence): the
    // sum over its elements (the node itself, or a cluster's members) of B A cos / (pi d^2), from
    // each element's centroid and with its side that faces `at`, B given by
    // `radiosityOf(element, side)`.
    template <typename RadiosityOf>
    Color irradianceAt(const RadiosityMesh& mesh, std::uint32_t node, const Vec3& at,
                       RadiosityOf radiosityOf) const {
        if (!isCluster(node)) {
            const Element& e = mesh.elements[node];
            return term({e.centroid, e.normal, e.area}, node, at, radiosityOf);
        }
        const Cluster& c = cluster(node);
        Color sum;
        for (std::uint32_t i = c.firstMember; i < c.firstMember + c.memberCount; ++i)
            sum += term(memberShapes_[i], members_[i], at, radiosityOf);
        return sum;
    }

    // A point of the node for a visibility ray towards `towards` (uniform by area over its
    // elements, from `u`), on the side facing it, and that element's patch. A cluster's point is
    // taken on a member whose front faces `towards` where one is near in the members' order (a
    // closed model's outside, a room's inside), since the others send nothing that way.
    struct SurfacePoint {
        Vec3 p;
        Vec3 n;  // the element's normal, turned to the side facing `towards`
        const Patch* patch = nullptr;
    };
    SurfacePoint sample(const RadiosityMesh& mesh, std::uint32_t node, const Vec3& towards,
                        Vec2 u) const;

private:
    // What irradianceAt reads of an element, kept for the members in their order: a sum over a
    // large cluster reads these in a row instead of 160-byte Elements here and there.
    struct MemberShape {
        Vec3 centroid;
        Vec3 normal;
        float area = 0;
    };

    // Element e's term of irradianceAt.
    template <typename RadiosityOf>
    static Color term(const MemberShape& shape, std::uint32_t e, const Vec3& at,
                      RadiosityOf radiosityOf) {
        const Vec3 toward = at - shape.centroid;
        const float d2 = dot(toward, toward);
        if (!(d2 > 0)) return Color(0);
        const float cosine = dot(shape.normal, toward) / std::sqrt(d2);
        const Side side = cosine > 0 ? Side::Front : Side::Back;
        return radiosityOf(e, side) *
               (shape.area * std::abs(cosine) / (std::numbers::pi_v<float> * d2));
    }

    // Builds the subtree over members_[first, first + count) and returns its node.
    std::uint32_t build(const RadiosityMesh& mesh, std::uint32_t first, std::uint32_t count,
                        std::uint32_t parent);

    std::vector<Cluster> clusters_;
    std::vector<std::uint32_t> members_;     // root elements, each cluster's contiguous
    std::vector<MemberShape> memberShapes_;  // in the order of members_
    std::vector<double> areaBefore_;         // area of members_[0, i), for sampling
    std::vector<std::uint32_t> rootParent_;  // per element, for the roots
};

}  // namespace lancer
