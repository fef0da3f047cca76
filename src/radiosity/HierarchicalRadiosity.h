#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "math/ColorArrays.h"
#include "radiosity/ClusterHierarchy.h"
#include "radiosity/FormFactor.h"
#include "radiosity/GlossyTransport.h"
#include "radiosity/RadiosityMesh.h"
#include "radiosity/RadiosityMethod.h"
#include "scene/RadiositySettings.h"

namespace lancer {

class Scene;
class VertexSmoothing;

// Hierarchical radiosity (Hanrahan, Salzman and Aupperle 1991) over the scene's patches:
//  1. every patch is the root of a hierarchy of elements, each split in four at its edges'
//     midpoints when needed, down to `element_size / 2^subdivision_levels`;
//  2. every pair of patches that see each other is linked, and a link whose reflected radiosity
//     may be wrong by more than `refinement_tolerance` times the mean radiosity put in (the power
//     put in over the area; the error: reflectance x source radiosity x the spread of the form
//     factor over the receiver, plus the whole form factor when the link is partly occluded) is
//     replaced by links from the longer of its two ends' children; the form factor of a link is the
//     exact point-to-polygon formula averaged over three points of the receiver, its visibility the
//     share of `visibility_rays` rays from points of the receiver to points of the source that
//     get through, each weighed by its piece of the source's form factor (FormFactor);
//  3. elements whose light from the scene's lights (point, spot, area...) varies across them are
//     split too, where reflectance x that variation x their area exceeds the same threshold;
//  4. Jacobi iterations: each element gathers the radiosity of its links' sources, each leaf adds
//     what its ancestors gathered (push), and the radiosities are averaged back up (pull), until
//     the power still to come (extrapolated from the last two iterations) is below `threshold`
//     times the power put in;
//  5. steps 2-4 again with the new radiosities (links refined where they now carry more; where
//     all of a refined link's rays got through, its ends most likely see each other wholly, and
//     the links that replace it trace `refined_visibility_rays` rays each, one by default: an
//     unbiased estimate all the same, a lamp's links excepted), until
//     nothing more is refined, for at most three passes; the last (the third, or one that finds
//     fewer than a thousandth of the links to refine) refines and is not examined again (its
//     links are iterated over in step 6, or here where step 6 is skipped);
//  6. a last round of iterations where each leaf gathers through the links of itself and its
//     ancestors with form factors from the leaf itself (in a closed room they add up to 1);
//  7. the irradiance at every vertex of the leaves is gathered there through the same links,
//     from the children of the sources it sees large, each link's visibility traced again from
//     the vertex.
// With clusters ("clusters": true; Smits, Arvo and Greenberg 1994; Sillion 1995), step 2 starts
// instead from the top cluster's link to itself (see ClusterHierarchy): a cluster's link to
// itself becomes its children's links to each other and to themselves, and a link with a cluster
// at an end carries the irradiance its source delivers at the receiver's centre (each member
// with its own cosine), which every leaf under the receiver takes at its own centroid with its
// own cosine. Its error is the reflected radiosity times (twice the ends' radii over their
// distance, or 64 where they are less than 3 times their radii apart, plus 1 when partly
// occluded); the larger end is split (a cluster into its two children) until that is below the
// threshold, so the link count grows near linearly with the elements. Bright sources (lamps) are
// never clustered.
// Where a leaf's form factors add up to more than 1 (within the refinement's error), what they
// bring is scaled back: no element gains power, and the iterations converge.
// The result does not depend on the number of threads: every form factor and visibility is
// computed on its own from seeds of its two elements, and the refinement decisions are taken in
// element order.
class HierarchicalRadiosity : public RadiosityMethod {
public:
    explicit HierarchicalRadiosity(const Scene& scene);

    // Over the patches, the lights and the radiosity settings (not the same as progressive's).
    std::uint64_t fingerprint() const override { return fingerprint_; }
    const RadiosityMesh& mesh() const { return mesh_; }

    std::optional<RadiositySolution> solve(
        const std::function<void(const RadiosityProgress&)>& onProgress,
        const std::atomic<bool>* cancel) override;
    // The leaves' irradiance averaged at their corners, without the final gather.
    RadiositySolution snapshot() const override;

    // A link gathers the radiosity of one side of its source element onto one side of the element
    // that holds it, with the form factor from the receiver to the source.
    struct Link {
        std::uint32_t source = 0;
        Side receiverSide = Side::Front;
        Side sourceSide = Side::Front;
        float unoccluded = 0;  // the form factor without occlusion
        float spread = 0;      // its spread over the receiver (max - min of the three points)
        Color visibility;      // the weighed share of rays that got through, per channel
        Color formFactor() const { return unoccluded * visibility; }
        bool partlyVisible() const {
            return visibility.maxComponent() > 0 &&
                   std::min({visibility.r, visibility.g, visibility.b}) < 1;
        }
    };
    // The links gathered by each element (index as in mesh().elements), between elements.
    const std::vector<std::vector<Link>>& links() const { return links_; }
    // A link with a cluster at one end or both: the receiver gathers the irradiance the source
    // delivers at its centre, times the fraction of visibility rays between points of the two
    // that got through; each of its elements takes that from the source's centre, by the inverse
    // square of its own distance and its own cosine. Its ends' centres are their nodes'
    // (ClusterHierarchy::center).
    struct ClusterLink {
        std::uint32_t receiver = 0, source = 0;  // nodes (ClusterHierarchy)
        Color visibility;
        bool partlyVisible() const {
            return visibility.maxComponent() > 0 &&
                   std::min({visibility.r, visibility.g, visibility.b}) < 1;
        }
    };
    // (The 200k knot has 18 million: its spread, which the ends give, is not kept.)
    static_assert(sizeof(ClusterLink) == 20);
    const std::vector<ClusterLink>& clusterLinks() const { return clusterLinks_; }
    const ClusterHierarchy& clusters() const { return clusters_; }
    // Both kinds.
    std::size_t linkCount() const;
    // The relative error of the point-to-point transfer between two nodes (a cluster link's),
    // from their bounding spheres.
    float clusterSpread(std::uint32_t receiver, std::uint32_t source) const;
    // The power (W per channel) a cluster link brings to its receiver's elements (a cluster's
    // members) from the present radiosities.
    Color clusterLinkPower(const ClusterLink& link) const;
    // The fraction an element of a link's receiver takes, on one side, of the irradiance the link
    // brings at normal incidence to the receiver's centre: none for an element at the source's
    // centre.
    struct ReceivedShare {
        float fraction = 0;
        Side side = Side::Front;
    };
    ReceivedShare receivedShare(const Element& element, const ClusterLink& link) const;

    // Radiosity (W/m^2) leaving each side of each element, as the last iteration left it.
    const std::vector<std::array<Color, 2>>& radiosity() const { return radiosity_; }
    // How wrong the radiosity a link brings to its receiver may be (W/m^2), by the oracle of
    // step 2.
    double linkError(std::uint32_t receiver, const Link& link) const;
    // The form factors a leaf gathers through, added up on one side.
    float coverage(std::uint32_t leaf, Side side) const { return coverage_[leaf][sideIndex(side)]; }
    // Below this (W/m^2), a link is not refined.
    double refinementThreshold() const { return epsilon_; }

private:
    struct Candidate {
        std::uint32_t receiver, source;
        // Per receiver side (bit sideIndex), whether a link between ends that hold these two had
        // all its rays through: their own link then traces `refined_visibility_rays` rays.
        std::uint8_t seenWhole = 0;
    };
    static constexpr std::uint8_t kSeenWholeBothSides = 3;
    // What to do with a candidate link: the links it makes, or which end to split (a node).
    struct Decision {
        std::array<Link, 2> links;
        int linkCount = 0;
        std::optional<ClusterLink> clusterLink;
        std::uint32_t split = Element::kNone;
    };

    // Resizes the per-element state to the mesh's elements (new ones inherit their parent's
    // radiosity until the next push-pull).
    void grow();
    // Splits an element (unless it is already split) and returns its first child.
    std::uint32_t split(std::uint32_t element);
    bool splittable(std::uint32_t element) const;
    // The same for an element whose longest edge is given.
    bool splittableAt(float longestEdge) const { return !full_ && longestEdge > smallestEdge_; }
    // Whether the hierarchy, with `candidates` more links, reaches its memory bounds (then nothing
    // more is split).
    void checkSize(std::size_t candidates);
    // Which end of the pair to split (the one with the longer longest edge, of the splittable
    // ones), or kNone.
    std::uint32_t splitChoice(std::uint32_t receiver, std::uint32_t source) const;
    // Places the elements from `first` on (surface point, reflectance) and computes the light
    // they receive from the scene's lights.
    void prepareElements(std::size_t first);
    Decision decide(const Candidate& candidate, std::uint64_t& rayCount) const;
    // Makes a decision's links, or splits its end and adds the pairs that replace it to `next`.
    void apply(const Candidate& candidate, const Decision& decision, std::vector<Candidate>& next);
    // decide() where an end is a cluster.
    Decision decideWithCluster(const Candidate& candidate, std::uint64_t& rayCount) const;
    // The squared distance between a pair's centres, as cluster links use it.
    float linkDistance2(std::uint32_t receiver, std::uint32_t source) const;
    // The larger end of a pair with a cluster (a cluster, or an element that may be split).
    std::uint32_t clusterSplitChoice(std::uint32_t receiver, std::uint32_t source) const;
    // The oracle's error for a cluster link: the radiosity it brings to the receiver may be off by
    // this much (W/m^2).
    double clusterLinkError(const ClusterLink& link) const;
    // The same, given what its source brings without occlusion (deliveredAt) and its spread.
    double clusterLinkError(const ClusterLink& link, const Color& unoccluded, float spread) const;
    // The power (W, averaged over the channels) a node's elements send from both sides.
    double sourcePower(std::uint32_t node) const;
    // The irradiance at normal incidence the link brings, from the present radiosities.
    Color clusterTransfer(const ClusterLink& link) const;
    // The fraction of `rays` rays between points of the two ends that get through.
    Color clusterVisibility(std::uint32_t receiver, std::uint32_t source, int rays,
                            std::uint64_t seed, std::uint64_t& rayCount) const;
    // What the cluster links received by a leaf, its ancestors and the clusters above its root
    // bring to `at` (the leaf, or a gather site on it) when each brings `perLink` (at normal
    // incidence, at its receiver's centre; in clusterLinks_'s order, that of their receivers):
    // see receivedShare().
    std::array<Color, 2> clusterLinksAt(const Element& at, std::uint32_t leaf,
                                        const ColorArrays& perLink) const;
    // Its sums, compiled for the baseline and for AVX2 (the same bits: the same operations lane
    // by lane).
    LANCER_ALWAYS_INLINE std::array<Color, 2> linkSums(const Element& at, std::uint32_t leaf,
                                                       const ColorArrays& perLink) const;
#if LANCER_HAS_AVX2_TARGET
    LANCER_AVX2_TARGET std::array<Color, 2> linkSumsAvx2(const Element& at, std::uint32_t leaf,
                                                         const ColorArrays& perLink) const;
#endif
    // The same at every leaf (indexed by element).
    std::vector<std::array<Color, 2>> gatherThroughClusters(const ColorArrays& perLink) const;
    // What a node (an element or a cluster) delivers at `at` at normal incidence, from the
    // present radiosities, or from radiosity 1 everywhere (`unit`).
    Color deliveredAt(std::uint32_t node, const Vec3& at, bool unit) const;
    // memberRadiosities_ from the root elements' present radiosities.
    void refreshMemberRadiosities();
    // Puts the cluster links in the order of their receivers for clusterLinksAt.
    void indexClusterLinks();
    // clusterTransfers_ from the present radiosities.
    void updateClusterTransfers();
    // clusterTransfers_, and fromClusters_ from them.
    void updateFromClusters();
    // The element links a leaf gathers through: its own and its ancestors' (at most a leaf term
    // each).
    std::size_t linksGatheredBy(std::uint32_t leaf) const;
    // How many terms the round resolved at the leaves would keep: linksGatheredBy, summed.
    std::size_t leafTermCount() const;
    // The refinement's first candidates: the top cluster's link to itself, or every pair of
    // patches.
    std::vector<Candidate> firstCandidates() const;
    // Refines the candidates, and the candidates their splits make, into links; then splits the
    // leaves whose light varies too much.
    void refine(std::vector<Candidate> candidates);
    // The candidates from re-examining every link with the present radiosities.
    std::vector<Candidate> relink();
    // Jacobi iterations with push-pull until converged; false once cancelled.
    bool iterate(bool resolved, const std::function<bool()>& carryOn);
    // One Jacobi iteration: every element gathers through its links and the leaves add what
    // their ancestors gathered (push), or, `resolved`, every leaf gathers through its terms; then
    // the radiosities are pulled up the hierarchies. Returns the change in power.
    double iteration(bool resolved);
    // The leaves' coverage from the links of the leaves and their ancestors, and, `resolved`,
    // their terms.
    void resolveAtLeaves(bool resolved);
    // What scales back the irradiance a leaf's links bring on one side, where their form factors
    // add up to more than it can see (1 elsewhere).
    float coverageScale(std::uint32_t leaf, std::size_t side) const;
    // The irradiance at every vertex, and its part straight from the sampled emitters.
    void gatherAtVertices(VertexSmoothing& smoothing);
    // fromGlossy_ at every leaf, from the solution as it stands (`round` seeds the samples).
    void gatherThroughGlossy(int round);
    // What a link brings to a gather site: all of it, and the part its source emits.
    struct Brought {
        Color total, direct;
    };
    // What a link brings to the gather site `at` from `source` (the link's source or one of its
    // descendants).
    Brought gatherFrom(const Element& at, const Link& link, std::uint32_t source, std::uint64_t key,
                       std::uint64_t& rayCount) const;
    // An element's emitted radiosity on one side where a render samples it (SplitIrradiance: the
    // emissive surfaces of bounded shapes), else none.
    Color emittedDirectly(std::uint32_t element, Side side) const;
    RadiosityStatistics statistics(std::size_t leaves) const;
    bool cancelled() const {
        return cancel_ && cancel_->load(std::memory_order_relaxed);
    }

    const Scene& scene_;
    RadiositySettings settings_;
    float patchSize_ = 0;
    float smallestEdge_ = 0;  // elements with edges below it are not split
    RadiosityMesh mesh_;
    FormFactor formFactor_;
    std::uint64_t fingerprint_ = 0;
    std::vector<std::uint32_t> roots_;
    std::vector<std::uint32_t> parent_;
    std::vector<std::array<Color, 2>> emitted_;     // pi Le
    std::vector<std::array<Color, 2>> fromLights_;  // irradiance from the scene's lights
    // Irradiance through glossy reflections (GlossyTransport), from the last gatherThroughGlossy.
    std::vector<std::array<Color, 2>> fromGlossy_;
    std::optional<GlossyTransport> glossy_;  // where the scene has glossy surfaces
    std::vector<float> lightSpread_;         // its spread over the element (W/m^2)
    std::vector<std::array<Color, 2>> radiosity_;
    std::vector<std::vector<Link>> links_;
    ClusterHierarchy clusters_;
    // After each refinement (indexClusterLinks), in the order of their receivers, which
    // clusterLinksAt reads: those of element e are clusterLinks_[elementReceives_[e],
    // elementReceives_[e + 1]), of cluster c [clusterReceives_[c], clusterReceives_[c + 1]).
    std::vector<ClusterLink> clusterLinks_;
    std::vector<std::uint32_t> elementReceives_, clusterReceives_;
    // What clusterLinksAt reads of each, in that order and one array per number: its source's
    // centre and its receiver's squared distance to it (linkDistance2).
    struct ReceivedLinks {
        std::vector<float> x, y, z, distance2;
    };
    ReceivedLinks received_;
    // The root elements' radiosities in the clusters' member order, and radiosity 1 in its place.
    ClusterHierarchy::MemberRadiosities memberRadiosities_, unitRadiosities_;
    std::vector<double> clusterPower_;  // per cluster, sourcePower(), refreshed with them
    // What each brings to its receiver's centre, in that order (from radiosity 1 between
    // resolveAtLeaves and the next iteration).
    ColorArrays clusterTransfers_;
    std::vector<std::array<Color, 2>> fromClusters_;  // per leaf: what they all bring it
    std::vector<std::array<Color, 2>> gathered_;      // through the element's own links
    // What each leaf gathers: every link of the leaf and of its ancestors, with the form factor
    // from the leaf itself (its centroid, or three points of it for a source seen large), and
    // those form factors added up per side.
    struct LeafTerm {
        std::uint32_t source;
        Side receiverSide, sourceSide;
        Color formFactor;  // visibility included
    };
    // In one array (one allocation, handed back whole when freed): leaf e's are
    // leafTerms_[leafTermsFirst_[e], leafTermsEnd_[e]), room made for one per link it gathers.
    std::vector<LeafTerm> leafTerms_;
    std::vector<std::uint32_t> leafTermsFirst_, leafTermsEnd_;
    std::vector<std::array<float, 2>> coverage_;
    // The part of each leaf's coverage from partly visible links (their unoccluded form factors).
    std::vector<std::array<float, 2>> coverageSampled_;
    bool full_ = false;        // checkSize's verdict
    double initialPower_ = 0;  // emitted, and reflected from the lights' light
    double epsilon_ = 0;
    double residual_ = 0;  // the last iteration's change in power
    std::uint64_t rays_ = 0;
    std::uint64_t iterations_ = 0;
    const std::atomic<bool>* cancel_ = nullptr;
};

}  // namespace lancer
