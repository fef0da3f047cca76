#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "math/Color.h"
#include "math/ColorLanes.h"
#include "math/Vec2.h"
#include "math/Vec3.h"
#include "radiosity/Element.h"
#include "radiosity/Patch.h"
#include "radiosity/RadiosityMesh.h"
#include "util/CpuFeatures.h"

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
        std::array<std::uint32_t, 2> children{};  // nodes, clusters after their parent
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
    // extent(mesh, node).center, without the radius.
    Vec3 center(const RadiosityMesh& mesh, std::uint32_t node) const {
        return isCluster(node) ? cluster(node).center : mesh.elements[node].centroid;
    }

    // The radiosities of ColorLanes::kLanes members (a block) per side, one array per number:
    // what a cluster's irradianceAt reads beside their shapes (ShapeBlock), a group of lanes at a
    // time.
    using Lanes = std::array<float, ColorLanes::kLanes>;
    struct alignas(64) RadiosityBlock {
        std::array<Lanes, 2> r, g, b;  // per side
    };
    // The members' radiosities in the members' order (member i in block i / kLanes, lane
    // i % kLanes), filled from the elements' by fillMemberRadiosities.
    using MemberRadiosities = std::vector<RadiosityBlock>;
    template <typename RadiosityOf>
    void fillMemberRadiosities(MemberRadiosities& into, RadiosityOf radiosityOf) const {
        into.assign(blockCount(), RadiosityBlock{});
        for (std::size_t i = 0; i < members_.size(); ++i) {
            RadiosityBlock& block = into[i / ColorLanes::kLanes];
            const std::size_t lane = i % ColorLanes::kLanes;
            for (Side side : kBothSides) {
                const Color B = radiosityOf(members_[i], side);
                block.r[sideIndex(side)][lane] = B.r;
                block.g[sideIndex(side)][lane] = B.g;
                block.b[sideIndex(side)][lane] = B.b;
            }
        }
    }

    // Per cluster, whether any of its members is one of which `holds` (a predicate on root
    // elements) is true.
    template <typename Predicate>
    std::vector<char> clustersHolding(Predicate holds) const {
        std::vector<char> result(clusters_.size(), 0);
        // Children come after their parent: from the last back, each child is done first.
        for (std::size_t k = clusters_.size(); k-- > 0;)
            for (std::uint32_t child : clusters_[k].children)
                if (isCluster(child) ? result[indexOf(child)] != 0 : holds(child)) result[k] = 1;
        return result;
    }

    // The irradiance a cluster (a node) delivers at `at` across a plane facing it (at normal
    // incidence): the sum over its members of B A cos / (pi d^2), from each member's centroid and
    // with its side that faces `at`, B from `radiosities`.
    Color irradianceAt(std::uint32_t node, const Vec3& at,
                       const MemberRadiosities& radiosities) const;
    // The same for one element, of the given radiosity per side.
    static Color irradianceAt(const Element& e, const Vec3& at,
                              const std::array<Color, 2>& radiosity);

    // The cosine between a unit normal n and t, and t's squared length: what a point-to-point
    // transfer weighs by. The smallest normal float added to the squared length changes none of
    // 1e-15 or more, and makes the cosine 0 for t = 0 without a branch: the sums over many terms
    // run this in SIMD lanes, which the compiler does only where nothing decides whether a
    // division runs.
    struct Toward {
        float cosine, distance2;
    };
    static Toward toward(float tx, float ty, float tz, float nx, float ny, float nz) {
        const float d2 = tx * tx + ty * ty + tz * tz + std::numeric_limits<float>::min();
        return {(nx * tx + ny * ty + nz * tz) / std::sqrt(d2), d2};
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
    // What irradianceAt and sample read of ColorLanes::kLanes members (laid out as their
    // radiosities, RadiosityBlock), one array per number: a sum over a small cluster reads a
    // block or two here and its radiosities there, where arrays of one number for all the
    // members made it a cache miss per number (the 200k knot's solve: 53 s with those, 49 s
    // with blocks).
    struct alignas(64) ShapeBlock {
        Lanes x, y, z;     // centroid
        Lanes nx, ny, nz;  // normal
        Lanes area;
        std::array<std::uint32_t, ColorLanes::kLanes> patch;
    };
    std::size_t blockCount() const {
        return (members_.size() + ColorLanes::kLanes - 1) / ColorLanes::kLanes;
    }

    // One term of irradianceAt: its weight A |cos| / (pi d^2) (none at the element's centroid),
    // and whether `toward` (from the centroid to the point) leaves by the front.
    struct Term {
        float weight;
        bool front;
    };
    static Term term(float tx, float ty, float tz, float nx, float ny, float nz, float area) {
        const Toward t = toward(tx, ty, tz, nx, ny, nz);
        return {area * std::abs(t.cosine) / (std::numbers::pi_v<float> * t.distance2),
                t.cosine > 0};
    }

    // irradianceAt's sum over a cluster's members, compiled for the baseline and for AVX2 (twice
    // the lanes per instruction, the same bits: the same operations lane by lane).
    LANCER_ALWAYS_INLINE Color memberSum(std::uint32_t node, const Vec3& at,
                                         const MemberRadiosities& radiosities) const;
#if LANCER_HAS_AVX2_TARGET
    LANCER_AVX2_TARGET Color memberSumAvx2(std::uint32_t node, const Vec3& at,
                                           const MemberRadiosities& radiosities) const;
#endif

    // Builds the subtree over members_[first, first + count) and returns its node.
    std::uint32_t build(const RadiosityMesh& mesh, std::uint32_t first, std::uint32_t count,
                        std::uint32_t parent);

    std::vector<Cluster> clusters_;
    std::vector<std::uint32_t> members_;  // root elements, each cluster's contiguous
    // The members' shapes, and the corners sample reads.
    std::vector<ShapeBlock> memberShapes_;
    std::vector<std::array<Vec3, 3>> memberCorners_;
    std::vector<double> areaBefore_;         // area of members_[0, i), for sampling
    std::vector<std::uint32_t> rootParent_;  // per element, for the roots
};

}  // namespace lancer
