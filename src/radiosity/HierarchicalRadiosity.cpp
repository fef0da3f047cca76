#include "radiosity/HierarchicalRadiosity.h"
#include "geometry/Shape.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>

#include "math/ColorLanes.h"
#include "radiosity/LightIrradiance.h"
#include "radiosity/PatchMesher.h"
#include "radiosity/RadiosityReporter.h"
#include "radiosity/SplitIrradiance.h"
#include "radiosity/SurfaceProbe.h"
#include "radiosity/TriangleQuadrature.h"
#include "radiosity/VertexSmoothing.h"
#include "sampling/Sampling.h"
#include "sampling/StratifiedPoint.h"
#include "scene/Scene.h"
#include "scene/ShadowRays.h"
#include "util/FreedMemory.h"
#include "util/ParallelFor.h"

namespace lancer {

namespace {

// Light samples per area light at each of an element's three points (more if the light asks for
// more), and at each vertex in the final gather.
constexpr int kAreaLightSamplesPerPoint = 8;
constexpr int kAreaLightSamples = 16;

// A link whose source sends at least this fraction of the power put in traces all its visibility
// rays in the final gather, the others one.
constexpr double kStrongLink = 1e-3;

// How far an element's corners are pulled towards its centroid where its form factors' spread is
// probed (on the corner itself, a neighbour's form factor is singular).
constexpr float kCornerInset = 0.05f;

// In the final gather, a source whose form factor from the vertex is above this is gathered from
// its children.
constexpr double kNearField = 0.02;

// A leaf's form factor to a source is the mean of its three points' above this, its centroid's
// below (where it hardly varies over the leaf).
constexpr double kLeafNearField = 1e-3;

// A source sending at least this fraction of the power put in (a lamp) has its links' visibility
// traced with four times the rays (a shadow may cross a large link between the rays), and is
// never clustered.
constexpr double kBrightSource = 1e-2;

// How far a leaf's form factors may add up beyond 1 before the excess is taken for an error and
// scaled back (coverageScale), where visibility sampled over the links' ends has a part in them:
// a leaf takes the visibility its ancestors' links found between larger elements, more than it
// sees of the source here and less there, so that near 1 about half of the sums come out above
// it; scaling all of those back to 1 took light from every room with something standing in it
// (a box floating in a closed furnace lost 0.9% of the power).
constexpr float kCoverageSlack = 0.05f;

// Memory bounds (a link takes 32 bytes, a leaf term 20): once the hierarchy holds this many
// elements or links, nothing more is split; the last round resolved at the leaves is skipped
// beyond this many terms.
constexpr std::size_t kMostElements = std::size_t{1} << 23;
constexpr std::size_t kMostLinks = std::size_t{1} << 25;
constexpr std::size_t kMostLeafTerms = std::size_t{1} << 26;

// How many candidate links are decided at a time (a decision takes about 100 bytes).
constexpr std::size_t kDecisionSlice = std::size_t{1} << 20;

// A link with a cluster at an end joins ends whose bounding spheres are apart. Its relative error
// is estimated as twice the sum of their radii over their distance where that distance is at
// least kClusterSeparation times the sum (the point-to-point transfer's error falls with the
// square of that ratio), and as kNearSpread where it is less: such a link is made only where what
// it brings is small, since cluster links are not resolved again at the leaves as element links
// are, and the many small ones a leaf gathers near it would add up. 24 rather than 64: a model's
// dim near field (a knot's strands, a bunny's ears) is linked as clusters, not element to element
// (the 200k-triangle knot: 58.7 million links -> 32.2 million, 128 s -> 81 s; its image and the
// bunny's within 1-2% of the old error against path); at 16 the closed box's furnace with clusters
// is 1.5% off (1% allowed), at 24 and 64 0.63% (docs/BENCHMARKS.md).
constexpr float kClusterSeparation = 3;
constexpr float kNearSpread = 24;

// The refinement passes: the first refines for the light put in, the second for the light of the
// first solution, the third for what the second's links changed; each takes a round of
// iterations over all the links to find the next pass's candidates (1.6 s of the bunny's 30 s).
// A fourth finds a few hundred links to refine in millions; stopping at three took 2 s off the
// bunny (its error against a path-traced reference did not grow) and moved the Cornell box's
// RMSE from 0.00270 to 0.00272 (docs/BENCHMARKS.md). A pass with fewer candidates than the
// links over kFewCandidates is the last as well.
constexpr int kMaxRefinementPasses = 3;
constexpr std::size_t kFewCandidates = 1000;

// A cluster link's relative error (see kClusterSeparation) between ends whose bounding spheres'
// centres are `distance` apart and whose radii add up to `radii`.
float spreadBetween(float distance, float radii) {
    return distance >= kClusterSeparation * radii ? 2 * radii / distance : kNearSpread;
}

double square(float x) {
    return static_cast<double>(x) * x;
}

// receivedShare() from (tx, ty, tz), the vector from the element's centroid to the source's
// centre, and the element's normal n: 0 at the centre itself (see ClusterHierarchy::toward;
// clusterLinksAt runs this in SIMD lanes).
struct Share {
    float fraction;
    bool front;
};
Share shareToward(float tx, float ty, float tz, const Vec3& n, float linkDistance2) {
    const ClusterHierarchy::Toward t = ClusterHierarchy::toward(tx, ty, tz, n.x, n.y, n.z);
    return {std::abs(t.cosine) * linkDistance2 / t.distance2, t.cosine > 0};
}

}  // namespace

HierarchicalRadiosity::HierarchicalRadiosity(const Scene& scene)
    : scene_(scene), settings_(scene.settings().radiosity), formFactor_(scene) {
    // The patches are the hierarchies' roots: meshed with elements as large as the patches.
    const PatchMesher sizes(scene, settings_);
    patchSize_ = sizes.patchSize();
    smallestEdge_ = sizes.elementSize() / static_cast<float>(1 << settings_.subdivisionLevels);
    RadiositySettings roots = settings_;
    roots.patchSize = roots.elementSize = patchSize_;
    mesh_ = PatchMesher(scene, roots).mesh();
    fingerprint_ = hashValues(mesh_.fingerprint(scene, settings_), 0x4852u,  // "HR"
                              std::bit_cast<std::uint32_t>(settings_.refinementTolerance),
                              settings_.clusters, settings_.refinedVisibilityRays);
    if (scene.hasGlossyMaterial() && settings_.glossySamples > 0)
        glossy_.emplace(scene, settings_.glossySamples);
    for (const Patch& p : mesh_.patches)
        for (std::uint32_t e = p.firstElement; e < p.firstElement + p.elementCount; ++e)
            roots_.push_back(e);
    if (settings_.clusters) {
        clusters_ = ClusterHierarchy(mesh_, roots_);
        clusters_.fillMemberRadiosities(unitRadiosities_,
                                        [](std::uint32_t, Side) { return Color(1); });
    }
}

std::size_t HierarchicalRadiosity::linkCount() const {
    std::size_t count = 0;
    for (const auto& l : links_)
        count += l.size();
    return count + clusterLinks_.size();
}

void HierarchicalRadiosity::grow() {
    const std::size_t n = mesh_.elements.size(), old = radiosity_.size();
    parent_.resize(n, Element::kNone);
    emitted_.resize(n);
    fromLights_.resize(n);
    fromGlossy_.resize(n);
    lightSpread_.resize(n);
    radiosity_.resize(n);
    gathered_.resize(n);
    links_.resize(n);
    fromClusters_.resize(n);
    for (std::size_t e = old; e < n; ++e) {
        const Patch& patch = mesh_.patches[mesh_.elements[e].patch];
        for (std::size_t side = 0; side < 2; ++side)
            emitted_[e][side] = kPi * patch.emission[side];
        radiosity_[e] = parent_[e] == Element::kNone ? emitted_[e] : radiosity_[parent_[e]];
    }
}

std::uint32_t HierarchicalRadiosity::split(std::uint32_t element) {
    if (!mesh_.elements[element].isLeaf()) return mesh_.elements[element].firstChild;
    const std::uint32_t first = mesh_.split(element);
    parent_.resize(mesh_.elements.size(), Element::kNone);
    for (std::uint32_t c = first; c < first + 4; ++c)
        parent_[c] = element;
    grow();
    return first;
}

bool HierarchicalRadiosity::splittable(std::uint32_t element) const {
    return splittableAt(mesh_.elements[element].longestEdge);
}

std::uint32_t HierarchicalRadiosity::splitChoice(std::uint32_t receiver,
                                                 std::uint32_t source) const {
    // The longer of the two, not the larger: a sliver along a contact line (small, but long
    // enough to cross a shadow) came last, the lamp split before it into pieces whose links each
    // carried too little to split it, and it stayed whole, its light interpolated from its lit
    // end across the shadow.
    const float r = mesh_.elements[receiver].longestEdge;
    const float s = mesh_.elements[source].longestEdge;
    if (splittableAt(r) && splittableAt(s)) return r >= s ? receiver : source;
    return splittableAt(r) ? receiver : splittableAt(s) ? source : Element::kNone;
}

void HierarchicalRadiosity::prepareElements(std::size_t first) {
    const std::size_t count = mesh_.elements.size() - first;
    rays_ += parallelForCounting(count, 8, cancel_, [&](std::size_t i, std::uint64_t& rays) {
        const auto e = static_cast<std::uint32_t>(first + i);
        Element& element = mesh_.elements[e];
        const Patch& patch = mesh_.patches[element.patch];
        const std::array<Vec3, 3> corners = element.corners;
        SurfaceProbe::place(patch, corners, element);
        fromLights_[e] = {};
        lightSpread_[e] = 0;
        if (scene_.lights().empty()) return;
        const std::array<Vec3, 3> points = triangleQuadraturePoints(corners);
        for (Side side : kBothSides) {
            const Vec3 n = side == Side::Front ? element.normal : -element.normal;
            float least = kInfinity, most = 0;
            Color sum;
            for (std::size_t k = 0; k < 3; ++k) {
                Vec3 p = points[k], ng = element.normal;
                if (patch.curved)
                    if (const std::optional<Hit> hit = SurfaceProbe::at(patch, p)) {
                        p = hit->p;
                        ng = hit->ng;
                    }
                const Color E = LightIrradiance::at(scene_, p, ng, n, kAreaLightSamplesPerPoint,
                                                    hashValues(e, sideIndex(side), k), rays);
                sum += E;
                least = std::min(least, E.average());
                most = std::max(most, E.average());
            }
            fromLights_[e][sideIndex(side)] = sum / 3.0f;
            lightSpread_[e] = std::max(lightSpread_[e], most - least);
        }
    });
}

double HierarchicalRadiosity::linkError(std::uint32_t receiver, const Link& link) const {
    const double reflected = static_cast<double>(mesh_.elements[receiver].reflectance.average()) *
                             radiosity_[link.source][sideIndex(link.sourceSide)].average();
    return reflected * (link.spread + (link.partlyVisible() ? link.unoccluded : 0.0f));
}

HierarchicalRadiosity::Decision HierarchicalRadiosity::decide(const Candidate& c,
                                                              std::uint64_t& rayCount) const {
    if (ClusterHierarchy::isCluster(c.receiver) || ClusterHierarchy::isCluster(c.source))
        return decideWithCluster(c, rayCount);
    Decision d;
    const Element& receiver = mesh_.elements[c.receiver];
    const Element& source = mesh_.elements[c.source];
    if (receiver.patch == source.patch) return d;  // flat: it cannot see itself
    const Patch& sourcePatch = mesh_.patches[source.patch];
    const std::array<Vec3, 3> sourceCorners = source.corners;
    const std::array<Vec3, 3> receiverCorners = receiver.corners;
    // The source's side that faces the receiver's centroid; receiver points behind it see none
    // of it.
    const float height = dot(source.normal, receiver.centroid - sourceCorners[0]);
    if (height == 0 || !std::isfinite(height)) return d;
    const Side sourceSide = height > 0 ? Side::Front : Side::Back;
    const std::array<Vec3, 3> points = triangleQuadraturePoints(receiverCorners);
    const double sourceEdge2 = square(source.longestEdge);
    // Links from strong sources (the lamps) trace more rays: their shadows are what shows.
    const bool brightSource = radiosity_[c.source][sideIndex(sourceSide)].average() * source.area >=
                              kBrightSource * initialPower_;
    const std::uint32_t choice = splitChoice(c.receiver, c.source);
    const double reflected = static_cast<double>(receiver.reflectance.average()) *
                             radiosity_[c.source][sideIndex(sourceSide)].average();
    // The spread is taken over the corners too (pulled in a little): the form factor to a
    // neighbour across an edge rises steeply towards that edge, between the quadrature points.
    std::array<Vec3, 6> probes;
    for (std::size_t k = 0; k < 3; ++k) {
        probes[k] = points[k];
        probes[3 + k] =
            receiverCorners[k] + kCornerInset * (receiver.centroid - receiverCorners[k]);
    }
    for (Side side : kBothSides) {
        const Vec3 n = side == Side::Front ? receiver.normal : -receiver.normal;
        double sum = 0, least = kInfinity, most = 0;
        for (std::size_t k = 0; k < probes.size(); ++k) {
            const double F = FormFactor::pointToSideOfTriangleApprox(
                Vec3d(probes[k]), Vec3d(n), sourceCorners, source.normal, sourceSide, source.area,
                sourceEdge2);
            if (k < 3) sum += F;
            least = std::min(least, F);
            most = std::max(most, F);
            // The spread only grows with more probes: once it is enough to split the pair
            // (below), the others need not be evaluated.
            if (choice != Element::kNone &&
                reflected * static_cast<float>(most - least) > epsilon_) {
                d.split = choice;
                return d;
            }
        }
        if (!(most > 0)) continue;
        Link link;
        link.source = c.source;
        link.receiverSide = side;
        link.sourceSide = sourceSide;
        // Reciprocity bounds what the receiver takes: A_r F_rs = A_s F_sr <= A_s.
        link.unoccluded =
            static_cast<float>(std::min(sum / 3, static_cast<double>(source.area / receiver.area)));
        link.spread = static_cast<float>(most - least);
        if (choice != Element::kNone && reflected * link.spread > epsilon_) {
            d.split = choice;
            return d;
        }
        const int rays = brightSource                           ? 4 * settings_.visibilityRays
                         : (c.seenWhole >> sideIndex(side)) & 1 ? settings_.refinedVisibilityRays
                                                                : settings_.visibilityRays;
        link.visibility = formFactor_.areaVisibility(
            receiver, receiverCorners, mesh_.patches[receiver.patch].curved, side, sourceCorners,
            sourcePatch, sourceSide, rays, hashValues(c.receiver, c.source, sideIndex(side)),
            rayCount);
        if (choice != Element::kNone && linkError(c.receiver, link) > epsilon_) {
            d.split = choice;
            return d;
        }
        if (link.visibility.isBlack()) continue;
        d.links[static_cast<std::size_t>(d.linkCount++)] = link;
    }
    return d;
}

std::uint32_t HierarchicalRadiosity::clusterSplitChoice(std::uint32_t receiver,
                                                        std::uint32_t source) const {
    const auto splits = [&](std::uint32_t node) {
        return ClusterHierarchy::isCluster(node) || splittable(node);
    };
    if (!splits(receiver)) return source;
    if (!splits(source)) return receiver;
    return clusters_.extent(mesh_, receiver).radius >= clusters_.extent(mesh_, source).radius
               ? receiver
               : source;
}

double HierarchicalRadiosity::sourcePower(std::uint32_t node) const {
    if (ClusterHierarchy::isCluster(node)) return clusterPower_[ClusterHierarchy::indexOf(node)];
    return static_cast<double>((radiosity_[node][0] + radiosity_[node][1]).average()) *
           mesh_.elements[node].area;
}

Color HierarchicalRadiosity::deliveredAt(std::uint32_t node, const Vec3& at, bool unit) const {
    if (ClusterHierarchy::isCluster(node))
        return clusters_.irradianceAt(node, at, unit ? unitRadiosities_ : memberRadiosities_);
    return ClusterHierarchy::irradianceAt(
        mesh_.elements[node], at,
        unit ? std::array<Color, 2>{Color(1), Color(1)} : radiosity_[node]);
}

void HierarchicalRadiosity::refreshMemberRadiosities() {
    if (clusters_.empty()) return;
    clusters_.fillMemberRadiosities(memberRadiosities_, [&](std::uint32_t e, Side side) {
        return radiosity_[e][sideIndex(side)];
    });
    // Each cluster's power from its two children's (which come after it).
    const std::vector<ClusterHierarchy::Cluster>& all = clusters_.clusters();
    clusterPower_.resize(all.size());
    for (std::size_t k = all.size(); k-- > 0;) {
        double sum = 0;
        for (std::uint32_t child : all[k].children)
            sum += sourcePower(child);
        clusterPower_[k] = sum;
    }
}

Color HierarchicalRadiosity::clusterTransfer(const ClusterLink& link) const {
    return link.visibility *
           deliveredAt(link.source, clusters_.center(mesh_, link.receiver), false);
}

float HierarchicalRadiosity::clusterSpread(std::uint32_t receiver, std::uint32_t source) const {
    const ClusterHierarchy::Extent r = clusters_.extent(mesh_, receiver);
    const ClusterHierarchy::Extent s = clusters_.extent(mesh_, source);
    return spreadBetween(length(s.center - r.center), r.radius + s.radius);
}

double HierarchicalRadiosity::clusterLinkError(const ClusterLink& link) const {
    return clusterLinkError(link,
                            deliveredAt(link.source, clusters_.center(mesh_, link.receiver), false),
                            clusterSpread(link.receiver, link.source));
}

double HierarchicalRadiosity::clusterLinkError(const ClusterLink& link, const Color& unoccluded,
                                               float spread) const {
    const float reflectance = ClusterHierarchy::isCluster(link.receiver)
                                  ? clusters_.cluster(link.receiver).reflectance
                                  : mesh_.elements[link.receiver].reflectance.average();
    return static_cast<double>(reflectance) * unoccluded.average() *
           (spread + (link.partlyVisible() ? 1.0f : 0.0f));
}

float HierarchicalRadiosity::linkDistance2(std::uint32_t receiver, std::uint32_t source) const {
    // The distance squared, not the dot product: the numbers decideWithCluster judged by.
    const float distance =
        length(clusters_.center(mesh_, source) - clusters_.center(mesh_, receiver));
    return distance * distance;
}

HierarchicalRadiosity::ReceivedShare HierarchicalRadiosity::receivedShare(
    const Element& element, const ClusterLink& link) const {
    const Vec3 t = clusters_.center(mesh_, link.source) - element.centroid;
    const Share share =
        shareToward(t.x, t.y, t.z, element.normal, linkDistance2(link.receiver, link.source));
    return {share.fraction, share.front ? Side::Front : Side::Back};
}

Color HierarchicalRadiosity::clusterLinkPower(const ClusterLink& link) const {
    const Color transfer = clusterTransfer(link);
    const auto power = [&](std::uint32_t e) {
        return mesh_.elements[e].area *
               (receivedShare(mesh_.elements[e], link).fraction * transfer);
    };
    if (!ClusterHierarchy::isCluster(link.receiver)) return power(link.receiver);
    Color sum;
    for (std::uint32_t e : clusters_.members(clusters_.cluster(link.receiver)))
        sum += power(e);
    return sum;
}

Color HierarchicalRadiosity::clusterVisibility(std::uint32_t receiver, std::uint32_t source,
                                               int rays, std::uint64_t seed,
                                               std::uint64_t& rayCount) const {
    const Vec3 receiverCenter = clusters_.center(mesh_, receiver);
    const Vec3 sourceCenter = clusters_.center(mesh_, source);
    // On a curved surface, a chord's point moves onto the surface and a little off it towards
    // the other end (as FormFactor's targets do).
    const auto onSurface = [](ClusterHierarchy::SurfacePoint& s) {
        if (s.patch->curved)
            s.p = SurfaceProbe::onSurface(*s.patch, s.p) + (1e-4f * std::sqrt(s.patch->area)) * s.n;
    };
    Color visible;
    int counted = 0;
    for (int k = 0; k < rays; ++k) {
        ClusterHierarchy::SurfacePoint from = clusters_.sample(
            mesh_, receiver, sourceCenter, stratifiedPoint(0, 1, hashValues(seed, k, 1)));
        ClusterHierarchy::SurfacePoint to =
            clusters_.sample(mesh_, source, receiverCenter, stratifiedPoint(k, rays, seed));
        onSurface(from);
        onSurface(to);
        // Points that face away from each other exchange nothing.
        if (!(dot(from.n, to.p - from.p) > 0) || !(dot(to.n, from.p - to.p) > 0)) continue;
        Hit at;
        at.p = from.p;
        at.ng = from.n;
        at.pError = gamma(16) * abs(at.p);
        LightSample towards;
        towards.position = to.p;
        towards.wi = normalize(to.p - from.p);
        visible += ShadowRays::transmittance(scene_, at, towards, rayCount);
        ++counted;
    }
    // No pair of points facing each other found: nothing tells of an obstacle.
    return counted == 0 ? Color(1) : visible / static_cast<float>(counted);
}

HierarchicalRadiosity::Decision HierarchicalRadiosity::decideWithCluster(
    const Candidate& c, std::uint64_t& rayCount) const {
    Decision d;
    d.split = clusterSplitChoice(c.receiver, c.source);
    if (c.receiver == c.source) return d;  // a cluster and itself: its children's pairs
    // A bright source's light (a lamp's) goes through element links only: their visibility is
    // traced with more rays, and again at the vertices, so that its shadows show.
    if (sourcePower(c.source) >= kBrightSource * initialPower_) return d;
    const ClusterHierarchy::Extent receiver = clusters_.extent(mesh_, c.receiver);
    const ClusterHierarchy::Extent source = clusters_.extent(mesh_, c.source);
    const float distance = length(source.center - receiver.center);
    const float radii = receiver.radius + source.radius;
    if (!(distance > radii)) return d;  // the two overlap
    ClusterLink link;
    link.receiver = c.receiver;
    link.source = c.source;
    link.visibility = Color(1);
    const float spread = spreadBetween(distance, radii);
    // What the source brings without occlusion: summed once over its members for both errors.
    const Color unoccluded = deliveredAt(c.source, receiver.center, false);
    if (clusterLinkError(link, unoccluded, spread) > epsilon_) return d;
    d.split = Element::kNone;
    // Nothing of the source faces the receiver (one plane): nothing to link.
    if (unoccluded.isBlack() && deliveredAt(c.source, receiver.center, true).isBlack()) return d;
    link.visibility = clusterVisibility(
        c.receiver, c.source,
        c.seenWhole != 0 ? settings_.refinedVisibilityRays : settings_.visibilityRays,
        hashValues(c.receiver, c.source), rayCount);
    if (clusterLinkError(link, unoccluded, spread) > epsilon_) {
        d.split = clusterSplitChoice(c.receiver, c.source);
        return d;
    }
    if (!link.visibility.isBlack()) d.clusterLink = link;
    return d;
}

LANCER_ALWAYS_INLINE std::array<Color, 2> HierarchicalRadiosity::linkSums(
    const Element& at, std::uint32_t leaf, const ColorArrays& perLink) const {
    // receivedShare() for each link the leaf takes, in SIMD lanes: the links of one receiver are
    // one range of arrays. Each term goes to the front's sum or the back's.
    const ReceivedLinks& links = received_;
    const Vec3& c = at.centroid;
    const Vec3& n = at.normal;
    ColorLanes front, back;
    const auto take = [&](std::uint32_t first, std::uint32_t last) {
        ColorLanes::forEach(first, last, [&](std::uint32_t lane, std::uint32_t l, bool inRange) {
            const Share share = shareToward(links.x[l] - c.x, links.y[l] - c.y, links.z[l] - c.z, n,
                                            links.distance2[l]);
            ColorLanes::addToOne(inRange, share.front, front, back, lane, share.fraction,
                                 perLink.r[l], perLink.g[l], perLink.b[l]);
        });
    };
    std::uint32_t root = leaf;
    for (std::uint32_t e = leaf; e != Element::kNone; e = parent_[e]) {
        take(elementReceives_[e], elementReceives_[e + 1]);
        root = e;
    }
    for (std::uint32_t k = clusters_.parentOf(root); k != Element::kNone;
         k = clusters_.clusters()[k].parent)
        take(clusterReceives_[k], clusterReceives_[k + 1]);
    std::array<Color, 2> E;
    E[sideIndex(Side::Front)] = front.total();
    E[sideIndex(Side::Back)] = back.total();
    return E;
}

#if LANCER_HAS_AVX2_TARGET
std::array<Color, 2> HierarchicalRadiosity::linkSumsAvx2(const Element& at, std::uint32_t leaf,
                                                         const ColorArrays& perLink) const {
    return linkSums(at, leaf, perLink);
}
#endif

std::array<Color, 2> HierarchicalRadiosity::clusterLinksAt(const Element& at, std::uint32_t leaf,
                                                           const ColorArrays& perLink) const {
#if LANCER_HAS_AVX2_TARGET
    if (CpuFeatures::avx2()) return linkSumsAvx2(at, leaf, perLink);
#endif
    return linkSums(at, leaf, perLink);
}

std::vector<std::array<Color, 2>> HierarchicalRadiosity::gatherThroughClusters(
    const ColorArrays& perLink) const {
    std::vector<std::array<Color, 2>> gathered(mesh_.elements.size());
    if (clusters_.empty()) return gathered;
    // The leaves of one root one after the other, the roots in the clusters' order: neighbours
    // in this order share most of the links they walk, which then stay in cache.
    std::vector<std::uint32_t> leaves, stack;
    leaves.reserve(mesh_.elements.size());
    for (std::uint32_t root : clusters_.members(clusters_.cluster(clusters_.top()))) {
        stack.push_back(root);
        while (!stack.empty()) {
            const std::uint32_t index = stack.back();
            stack.pop_back();
            const Element& e = mesh_.elements[index];
            if (e.isLeaf())
                leaves.push_back(index);
            else
                for (std::uint32_t c = e.firstChild; c < e.firstChild + 4; ++c)
                    stack.push_back(c);
        }
    }
    parallelFor(leaves.size(), 64, [&](std::size_t i) {
        gathered[leaves[i]] = clusterLinksAt(mesh_.elements[leaves[i]], leaves[i], perLink);
    });
    return gathered;
}

void HierarchicalRadiosity::updateClusterTransfers() {
    if (clusters_.empty()) return;
    clusterTransfers_.resize(clusterLinks_.size() + ColorLanes::kPadding);
    parallelFor(clusterLinks_.size(), 64, [&](std::size_t i) {
        clusterTransfers_.set(i, clusterTransfer(clusterLinks_[i]));
    });
}

void HierarchicalRadiosity::updateFromClusters() {
    if (clusters_.empty()) return;
    updateClusterTransfers();
    fromClusters_ = gatherThroughClusters(clusterTransfers_);
}

void HierarchicalRadiosity::apply(const Candidate& c, const Decision& d,
                                  std::vector<Candidate>& next) {
    if (d.split == Element::kNone) {
        for (int k = 0; k < d.linkCount; ++k)
            links_[c.receiver].push_back(d.links[static_cast<std::size_t>(k)]);
        if (d.clusterLink) clusterLinks_.push_back(*d.clusterLink);
        return;
    }
    if (ClusterHierarchy::isCluster(d.split)) {
        const std::array<std::uint32_t, 2>& children = clusters_.cluster(d.split).children;
        for (std::uint32_t child : children) {
            if (c.receiver == c.source)
                for (std::uint32_t other : children)
                    next.push_back({child, other});
            else
                next.push_back(d.split == c.receiver ? Candidate{child, c.source, c.seenWhole}
                                                     : Candidate{c.receiver, child, c.seenWhole});
        }
        return;
    }
    const std::uint32_t first = split(d.split);
    for (std::uint32_t child = first; child < first + 4; ++child)
        next.push_back(d.split == c.receiver ? Candidate{child, c.source, c.seenWhole}
                                             : Candidate{c.receiver, child, c.seenWhole});
}

void HierarchicalRadiosity::refine(std::vector<Candidate> candidates) {
    std::size_t prepared = mesh_.elements.size();
    // Kept from round to round: fresh vectors of millions of decisions had the kernel clear
    // their pages every round.
    std::vector<Decision> decisions;
    std::vector<Candidate> next;
    while (!candidates.empty() && !cancelled()) {
        checkSize(4 * candidates.size());  // as many as splitting them all would make
        next.clear();
        // A slice at a time, each applied before the next is decided: the decisions of a round
        // of tens of millions of candidates took gigabytes. The same decisions as all at once:
        // a split only adds elements, and no decision of the round reads those.
        for (std::size_t begin = 0; begin < candidates.size() && !cancelled();
             begin += kDecisionSlice) {
            const std::size_t count = std::min(kDecisionSlice, candidates.size() - begin);
            decisions.assign(count, Decision{});
            rays_ +=
                parallelForCounting(count, 64, cancel_, [&](std::size_t i, std::uint64_t& rays) {
                    decisions[i] = decide(candidates[begin + i], rays);
                });
            if (cancelled()) break;
            // In candidate order, whatever the threads: the same hierarchy every time.
            for (std::size_t i = 0; i < count; ++i)
                apply(candidates[begin + i], decisions[i], next);
        }
        if (cancelled()) break;
        prepareElements(prepared);
        prepared = mesh_.elements.size();
        std::swap(candidates, next);
    }
    // Their memory makes room for indexClusterLinks' copy of the links.
    std::vector<Decision>().swap(decisions);
    std::vector<Candidate>().swap(candidates);
    std::vector<Candidate>().swap(next);
    // The lights' shadows and highlights: leaves whose light varies too much are split.
    for (bool again = true; again && !cancelled();) {
        checkSize(0);
        const std::size_t before = mesh_.elements.size();
        for (std::uint32_t e = 0; e < before; ++e) {
            const Element& element = mesh_.elements[e];
            if (!element.isLeaf() || !splittable(e)) continue;
            // Weighted by the element's area (unlike the links' error): the bound the links use,
            // applied to radiosity, splits shadowed floors into far too many leaves (issue 12).
            const double error =
                static_cast<double>(element.reflectance.average()) * lightSpread_[e] * element.area;
            if (error > epsilon_) split(e);
        }
        prepareElements(before);
        again = mesh_.elements.size() > before;
    }
    // The lists grew by doubling as the links were made: a third of their memory was spare, and
    // the blocks they left stay resident unless handed back. (Not the cluster links: one array
    // of hundreds of megabytes, whose spare room was never written and takes no memory, where a
    // copy of it would take as much again for a moment.)
    parallelFor(links_.size(), 256, [&](std::size_t e) { links_[e].shrink_to_fit(); });
    returnFreedMemory();
    indexClusterLinks();
}

void HierarchicalRadiosity::indexClusterLinks() {
    // A counting sort by receiver, each receiver's links in the order they were made: slots of
    // the elements, then of the clusters.
    const std::size_t elements = mesh_.elements.size(), count = clusterLinks_.size();
    const auto slot = [&](std::uint32_t node) {
        return ClusterHierarchy::isCluster(node) ? elements + ClusterHierarchy::indexOf(node)
                                                 : std::size_t{node};
    };
    std::vector<std::uint32_t> next(elements + clusters_.clusters().size() + 1, 0);
    for (const ClusterLink& link : clusterLinks_)
        ++next[slot(link.receiver) + 1];
    std::partial_sum(next.begin(), next.end(), next.begin());
    elementReceives_.assign(next.begin(), next.begin() + static_cast<std::ptrdiff_t>(elements) + 1);
    clusterReceives_.assign(next.begin() + static_cast<std::ptrdiff_t>(elements), next.end());
    // The links themselves moved into that order: the sums over them (every iteration's
    // transfers) then read each receiver's centre and write each result in a row, where in the
    // order they were made each link cost three cache misses (the 200k knot's transfers took
    // twice the time).
    std::vector<ClusterLink> ordered(count);
    for (const ClusterLink& link : clusterLinks_)
        ordered[next[slot(link.receiver)]++] = link;
    clusterLinks_ = std::move(ordered);
    // What the gathers read of each, filled in parallel: each reads its source's centre, here
    // and there in memory.
    for (std::vector<float>* v : {&received_.x, &received_.y, &received_.z, &received_.distance2})
        v->resize(count + ColorLanes::kPadding);
    parallelFor(count, 1024, [&](std::size_t i) {
        const ClusterLink& link = clusterLinks_[i];
        const Vec3 sourceCenter = clusters_.center(mesh_, link.source);
        received_.x[i] = sourceCenter.x;
        received_.y[i] = sourceCenter.y;
        received_.z[i] = sourceCenter.z;
        received_.distance2[i] = linkDistance2(link.receiver, link.source);
    });
}

void HierarchicalRadiosity::checkSize(std::size_t candidates) {
    // Each candidate may become a link (or two, one per side).
    full_ = mesh_.elements.size() >= kMostElements || linkCount() + 2 * candidates >= kMostLinks;
}

std::vector<HierarchicalRadiosity::Candidate> HierarchicalRadiosity::relink() {
    checkSize(0);
    std::vector<Candidate> candidates;
    for (std::uint32_t r = 0; r < links_.size(); ++r) {
        // A link that now carries too much is taken apart: its candidates are the children of
        // the end the refinement would split. The others are kept in place, in their order
        // (copies of every list had the kernel clear hundreds of megabytes of pages per pass).
        std::vector<Link>& links = links_[r];
        std::size_t kept = 0;
        std::uint32_t previousSource = Element::kNone;
        for (const Link& link : links) {
            const std::uint32_t choice = splitChoice(r, link.source);
            if (choice == Element::kNone || linkError(r, link) <= epsilon_) {
                links[kept++] = link;
                continue;
            }
            // Both sides of one pair make one candidate.
            const auto seenWhole = static_cast<std::uint8_t>(
                link.visibility == Color(1) ? 1 << sideIndex(link.receiverSide) : 0);
            if (link.source == previousSource) {
                candidates.back().seenWhole |= seenWhole;
                continue;
            }
            previousSource = link.source;
            candidates.push_back({r, link.source, seenWhole});
        }
        links.resize(kept);
    }
    // A pair whose link on one side stayed would be linked twice on that side: drop those links.
    for (const Candidate& c : candidates)
        std::erase_if(links_[c.receiver], [&](const Link& l) { return l.source == c.source; });
    if (!full_) {
        // Judged in parallel (each sums its source's members), taken apart in order.
        std::vector<char> tooMuch(clusterLinks_.size());
        parallelFor(clusterLinks_.size(), 1024, [&](std::size_t i) {
            tooMuch[i] = clusterLinkError(clusterLinks_[i]) > epsilon_;
        });
        std::size_t i = 0;
        std::erase_if(clusterLinks_, [&](const ClusterLink& link) {
            if (!tooMuch[i++]) return false;
            candidates.push_back(
                {link.receiver, link.source,
                 link.visibility == Color(1) ? kSeenWholeBothSides : std::uint8_t{0}});
            return true;
        });
    }
    return candidates;
}

void HierarchicalRadiosity::resolveAtLeaves(bool resolved) {
    std::vector<std::uint32_t> leaves = mesh_.leaves();
    if (resolved) {
        leafTermsFirst_.assign(mesh_.elements.size(), 0);
        std::uint32_t terms = 0;
        for (std::uint32_t leaf : leaves) {
            leafTermsFirst_[leaf] = terms;
            terms += static_cast<std::uint32_t>(linksGatheredBy(leaf));
        }
        leafTermsEnd_ = leafTermsFirst_;
        leafTerms_.resize(terms);
    }
    coverage_.assign(mesh_.elements.size(), {0, 0});
    coverageSampled_.assign(mesh_.elements.size(), {0, 0});
    // The cluster links' form factors: what they would bring from sources of radiosity 1. Kept
    // where their transfers are (the next iteration makes those anew), not in arrays of their own
    // beside the leaf terms: the 200k knot's largest moment.
    ColorArrays& unit = clusterTransfers_;
    unit.resize(clusterLinks_.size() + ColorLanes::kPadding);
    parallelFor(clusterLinks_.size(), 64, [&](std::size_t i) {
        const ClusterLink& link = clusterLinks_[i];
        unit.set(i, link.visibility *
                        deliveredAt(link.source, clusters_.center(mesh_, link.receiver), true));
    });
    const std::vector<std::array<Color, 2>> clusterCoverage = gatherThroughClusters(unit);
    parallelFor(leaves.size(), 8, [&](std::size_t i) {
        const std::uint32_t leaf = leaves[i];
        const Element& element = mesh_.elements[leaf];
        const std::array<Vec3, 3> points = triangleQuadraturePoints(element.corners);
        for (std::size_t side = 0; side < 2; ++side)
            coverage_[leaf][side] += clusterCoverage[leaf][side].average();
        for (std::uint32_t e = leaf; e != Element::kNone; e = parent_[e]) {
            for (const Link& link : links_[e]) {
                const std::size_t side = sideIndex(link.receiverSide);
                if (!resolved) {
                    coverage_[leaf][side] += link.formFactor().average();
                    if (link.partlyVisible()) coverageSampled_[leaf][side] += link.unoccluded;
                    continue;
                }
                const Element& source = mesh_.elements[link.source];
                const std::array<Vec3, 3> corners = source.corners;
                const Vec3d n(link.receiverSide == Side::Front ? element.normal : -element.normal);
                const double edge2 = square(source.longestEdge);
                const auto F = [&](const Vec3& p) {
                    return FormFactor::pointToSideOfTriangleApprox(
                        Vec3d(p), n, corners, source.normal, link.sourceSide, source.area, edge2);
                };
                // The centroid's form factor, or the three points' mean where the source is seen
                // large enough for it to vary over the leaf.
                double unoccluded = F(element.centroid);
                if (unoccluded > kLeafNearField)
                    unoccluded = (F(points[0]) + F(points[1]) + F(points[2])) / 3;
                unoccluded = std::min(unoccluded, static_cast<double>(source.area / element.area));
                if (!(unoccluded > 0)) continue;
                const Color FV = static_cast<float>(unoccluded) * link.visibility;
                leafTerms_[leafTermsEnd_[leaf]++] = {link.source, link.receiverSide,
                                                     link.sourceSide, FV};
                coverage_[leaf][side] += FV.average();
                if (link.partlyVisible())
                    coverageSampled_[leaf][side] += static_cast<float>(unoccluded);
            }
        }
    });
}

double HierarchicalRadiosity::iteration(bool resolved) {
    // Jacobi: every element gathers from the radiosities of the last iteration.
    updateFromClusters();
    if (!resolved)
        parallelFor(links_.size(), 64, [&](std::size_t r) {
            std::array<Color, 2> E;
            for (const Link& link : links_[r])
                E[sideIndex(link.receiverSide)] +=
                    link.formFactor() * radiosity_[link.source][sideIndex(link.sourceSide)];
            gathered_[r] = E;
        });
    const std::vector<std::uint32_t> leaves = mesh_.leaves();
    std::vector<std::array<Color, 2>> B(leaves.size());
    parallelFor(leaves.size(), 64, [&](std::size_t i) {
        const std::uint32_t leaf = leaves[i];
        std::array<Color, 2> E;
        if (resolved) {
            for (std::uint32_t k = leafTermsFirst_[leaf]; k < leafTermsEnd_[leaf]; ++k) {
                const LeafTerm& t = leafTerms_[k];
                E[sideIndex(t.receiverSide)] +=
                    t.formFactor * radiosity_[t.source][sideIndex(t.sourceSide)];
            }
        } else {
            // Push: what the leaf's ancestors gathered reaches it too.
            for (std::uint32_t e = leaf; e != Element::kNone; e = parent_[e])
                for (std::size_t side = 0; side < 2; ++side)
                    E[side] += gathered_[e][side];
        }
        for (std::size_t side = 0; side < 2; ++side)
            E[side] += fromClusters_[leaf][side];
        Element& element = mesh_.elements[leaf];
        for (std::size_t side = 0; side < 2; ++side) {
            const Color total = coverageScale(leaf, side) * E[side] + fromLights_[leaf][side] +
                                fromGlossy_[leaf][side];
            element.irradiance[side] = total;
            B[i][side] = emitted_[leaf][side] + element.reflectance * total;
        }
    });
    double change = 0;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        const std::uint32_t leaf = leaves[i];
        for (std::size_t side = 0; side < 2; ++side)
            change += std::abs(static_cast<double>(B[i][side].average()) -
                               radiosity_[leaf][side].average()) *
                      mesh_.elements[leaf].area;
        radiosity_[leaf] = B[i];
    }
    // Pull: an element's radiosity is its children's, area-weighted (children come after their
    // parent, so from the last element back every child is done before its parent).
    for (std::size_t k = mesh_.elements.size(); k-- > 0;) {
        const Element& element = mesh_.elements[k];
        if (element.isLeaf()) continue;
        std::array<Color, 2> sum;
        for (std::uint32_t c = element.firstChild; c < element.firstChild + 4; ++c)
            for (std::size_t side = 0; side < 2; ++side)
                sum[side] += (mesh_.elements[c].area / element.area) * radiosity_[c][side];
        radiosity_[k] = sum;
    }
    refreshMemberRadiosities();
    ++iterations_;
    return change;
}

bool HierarchicalRadiosity::iterate(bool resolved, const std::function<bool()>& carryOn) {
    double previous = 0;
    for (int k = 0; iterations_ < static_cast<std::uint64_t>(settings_.maxShots); ++k) {
        residual_ = iteration(resolved);
        if (!carryOn()) return false;
        // An emission so large that the power overflows never converges: stop at once.
        if (!std::isfinite(residual_)) break;
        // The power still to come, if each iteration changes it by the same ratio as the last.
        const double ratio = k > 0 && previous > 0 ? std::min(residual_ / previous, 0.99) : 0.99;
        previous = residual_;
        if (residual_ * ratio / (1 - ratio) <= settings_.threshold * initialPower_) break;
    }
    return true;
}

HierarchicalRadiosity::Brought HierarchicalRadiosity::gatherFrom(const Element& at,
                                                                 const Link& link,
                                                                 std::uint32_t source,
                                                                 std::uint64_t key,
                                                                 std::uint64_t& rayCount) const {
    const Element& element = mesh_.elements[source];
    const std::array<Vec3, 3> corners = element.corners;
    const Vec3 n = link.receiverSide == Side::Front ? at.normal : -at.normal;
    const double unoccluded = FormFactor::pointToSideOfTriangleApprox(
        Vec3d(at.centroid), Vec3d(n), corners, element.normal, link.sourceSide, element.area,
        square(element.longestEdge));
    if (!(unoccluded > 0)) return {};
    // A source seen large is gathered from its children: its radiosity varies over it (darker
    // towards the corners), which its average would not show.
    if (!element.isLeaf() && unoccluded > kNearField) {
        Brought sum;
        for (std::uint32_t c = element.firstChild; c < element.firstChild + 4; ++c) {
            const Brought child = gatherFrom(at, link, c, key, rayCount);
            sum.total += child.total;
            sum.direct += child.direct;
        }
        return sum;
    }
    const Color& B = radiosity_[source][sideIndex(link.sourceSide)];
    // Visibility traced again from the vertex for every link, not taken from the link: the few
    // rays of a large link, from points of its receiver, may all get through where an obstacle
    // hides the source from the vertex (beside the foot of a wall or a block standing on the
    // floor, which came out too bright). One ray for the weak sources: a third more solve time on
    // the Cornell box, and the vertices' errors average out over their many links.
    const bool strong = B.average() * element.area >= kStrongLink * initialPower_;
    const Color formFactor = formFactor_.elementToTriangle(
        at, link.receiverSide, corners, mesh_.patches[element.patch], link.sourceSide,
        strong ? settings_.visibilityRays : 1, hashValues(key, source), rayCount);
    return {B * formFactor, emittedDirectly(source, link.sourceSide) * formFactor};
}

Color HierarchicalRadiosity::emittedDirectly(std::uint32_t element, Side side) const {
    const Patch& patch = mesh_.patches[mesh_.elements[element].patch];
    return patch.surface->isBounded() ? emitted_[element][sideIndex(side)] : Color(0);
}

void HierarchicalRadiosity::gatherThroughGlossy(int round) {
    const std::vector<std::uint32_t> leaves = mesh_.leaves();
    const std::vector<std::array<Color, 2>> E =
        glossy_->atElements(mesh_, leaves, snapshot(), round, cancel_, rays_);
    for (std::size_t i = 0; i < leaves.size(); ++i)
        fromGlossy_[leaves[i]] = E[i];
}

void HierarchicalRadiosity::gatherAtVertices(VertexSmoothing& smoothing) {
    // What the cluster links bring of the sampled emitters' light alone.
    ColorArrays directTransfers;
    if (!clusters_.empty()) {
        ClusterHierarchy::MemberRadiosities emitted;
        clusters_.fillMemberRadiosities(
            emitted, [&](std::uint32_t e, Side side) { return emittedDirectly(e, side); });
        const auto emits = [&](std::uint32_t e) {
            return !(emittedDirectly(e, Side::Front) + emittedDirectly(e, Side::Back)).isBlack();
        };
        // Only the links from a source with an emitter in it bring anything here (a lamp is in
        // a few of the clusters, its ancestors): the others' sums are skipped.
        const std::vector<char> emitting = clusters_.clustersHolding(emits);
        directTransfers.resize(clusterLinks_.size() + ColorLanes::kPadding);
        parallelFor(clusterLinks_.size(), 64, [&](std::size_t i) {
            const ClusterLink& link = clusterLinks_[i];
            if (ClusterHierarchy::isCluster(link.source)
                    ? !emitting[ClusterHierarchy::indexOf(link.source)]
                    : !emits(link.source))
                return;
            const Vec3 centre = clusters_.center(mesh_, link.receiver);
            const Color delivered =
                ClusterHierarchy::isCluster(link.source)
                    ? clusters_.irradianceAt(link.source, centre, emitted)
                    : ClusterHierarchy::irradianceAt(mesh_.elements[link.source], centre,
                                                     {emittedDirectly(link.source, Side::Front),
                                                      emittedDirectly(link.source, Side::Back)});
            directTransfers.set(i, link.visibility * delivered);
        });
    }
    const std::optional<RadiositySolution> current =
        glossy_ ? std::optional<RadiositySolution>(snapshot()) : std::nullopt;
    const std::size_t count = smoothing.vertexIrradiance.size();
    rays_ += parallelForCounting(count, 16, cancel_, [&](std::size_t v, std::uint64_t& rays) {
        const Element at = smoothing.gatherSite(scene_, v, rays);
        SplitIrradiance E;
        if (glossy_) E.total = glossy_->atVertex(at, v, *current, rays);
        if (!scene_.lights().empty())
            for (Side side : kBothSides)
                E.direct[sideIndex(side)] = LightIrradiance::at(
                    scene_, at.surfacePoint, at.surfaceNormal, at.surfaceSideNormal(side),
                    kAreaLightSamples, hashValues(v, sideIndex(side), 0x76u), rays);
        for (std::size_t side = 0; side < 2; ++side)
            E.total[side] += E.direct[side];
        for (std::uint32_t e = smoothing.siteLeaf(v); e != Element::kNone; e = parent_[e])
            for (const Link& link : links_[e]) {
                const std::size_t side = sideIndex(link.receiverSide);
                const Brought brought =
                    gatherFrom(at, link, link.source, hashValues(v, side), rays);
                E.total[side] += brought.total;
                E.direct[side] += brought.direct;
            }
        if (!clusters_.empty()) {
            const std::uint32_t leaf = smoothing.siteLeaf(v);
            E += {clusterLinksAt(at, leaf, clusterTransfers_),
                  clusterLinksAt(at, leaf, directTransfers)};
        }
        smoothing.vertexIrradiance[v] = E.total;
        smoothing.vertexDirect[v] = E.direct;
    });
}

float HierarchicalRadiosity::coverageScale(std::uint32_t leaf, std::size_t side) const {
    // A receiver sees at most its hemisphere: where its form factors add up to more, what they
    // bring is scaled back, beyond a slack where partly visible links have a part in the sum. The
    // limit keeps reflectance x coverage below 1 (halfway from the reflectance to 1), so that no
    // leaf gains power and the iterations converge, even where nearly everything is reflected.
    const float slack = std::min(kCoverageSlack, coverageSampled_[leaf][side]);
    const float reflectance = mesh_.elements[leaf].reflectance.maxComponent();
    const float limit = std::max(
        1.0f, reflectance > 0 ? std::min(1 + slack, 0.5f * (1 + 1 / reflectance)) : 1 + slack);
    const float coverage = coverage_[leaf][side];
    return coverage > limit ? limit / coverage : 1.0f;
}

RadiosityStatistics HierarchicalRadiosity::statistics(std::size_t leaves) const {
    RadiosityStatistics s;
    s.patches = mesh_.patches.size();
    s.elements = leaves;
    s.links = linkCount();
    s.shots = iterations_;
    s.initialPower = initialPower_;
    s.residualPower = residual_;
    s.rays = rays_;
    return s;
}

std::optional<RadiositySolution> HierarchicalRadiosity::solve(
    const std::function<void(const RadiosityProgress&)>& onProgress,
    const std::atomic<bool>* cancel) {
    cancel_ = cancel;
    const RadiosityReporter reporter(onProgress, cancel);
    RadiosityProgress::Phase phase = RadiosityProgress::Phase::Refining;
    const auto carryOn = [&]() {
        return reporter.carryOn(phase, iterations_, residual_, initialPower_);
    };

    grow();
    prepareElements(0);
    // The power put in: emitted, and reflected from the lights' light.
    for (std::uint32_t root : roots_) {
        const Element& e = mesh_.elements[root];
        for (std::size_t side = 0; side < 2; ++side) {
            radiosity_[root][side] = emitted_[root][side] + e.reflectance * fromLights_[root][side];
            initialPower_ += static_cast<double>(radiosity_[root][side].average()) * e.area;
        }
    }
    refreshMemberRadiosities();
    residual_ = initialPower_;
    double area = 0;
    for (std::uint32_t root : roots_)
        area += mesh_.elements[root].area;
    epsilon_ = static_cast<double>(settings_.refinementTolerance) * initialPower_ / area;
    if (!carryOn()) return std::nullopt;

    std::vector<Candidate> candidates = firstCandidates();
    for (int pass = 1; initialPower_ > 0; ++pass) {
        // The last pass refines what the one before left, and is not examined again: every
        // pass's candidates are taken apart into links, none dropped.
        const bool last = pass == kMaxRefinementPasses ||
                          (pass > 1 && candidates.size() * kFewCandidates < linkCount());
        phase = RadiosityProgress::Phase::Refining;
        refine(std::move(candidates));
        if (!carryOn()) return std::nullopt;
        // The round resolved at the leaves below iterates to convergence over the new links.
        if (last && leafTermCount() <= kMostLeafTerms) break;
        resolveAtLeaves(false);
        phase = RadiosityProgress::Phase::Iterating;
        if (!iterate(false, carryOn)) return std::nullopt;
        if (last) break;
        candidates = relink();
        if (candidates.empty()) break;
    }

    // The leaves' radiosities once more, from their own form factors to the links' sources
    // (unless the terms would take too much memory).
    const bool resolved = leafTermCount() <= kMostLeafTerms;
    phase = RadiosityProgress::Phase::Iterating;
    if (resolved) {
        resolveAtLeaves(true);
        if (!iterate(true, carryOn)) return std::nullopt;
    }
    // The light through glossy reflections, from the solution as it stands, then iterated with
    // the rest; twice, so that it is itself reflected by the glossy surfaces.
    if (glossy_)
        for (int round = 0; round < GlossyTransport::kRounds; ++round) {
            gatherThroughGlossy(round);
            if (cancelled() || !iterate(resolved, carryOn)) return std::nullopt;
        }

    phase = RadiosityProgress::Phase::Gathering;
    if (!carryOn()) return std::nullopt;
    // The gather below does not read the leaves' terms: their memory (300 MB for the 200k
    // knot) makes room for its own.
    // (Swapped out: assigning {} would keep the capacity.)
    std::vector<LeafTerm>().swap(leafTerms_);
    std::vector<std::uint32_t>().swap(leafTermsFirst_);
    std::vector<std::uint32_t>().swap(leafTermsEnd_);
    updateClusterTransfers();
    VertexSmoothing smoothing(mesh_, mesh_.leaves(), 1e-5 * patchSize_);
    gatherAtVertices(smoothing);
    if (cancelled()) return std::nullopt;
    RadiosityStatistics s = statistics(mesh_.leaves().size());
    s.seconds = reporter.seconds();
    return std::move(smoothing).solution(mesh_.lookupDistance(patchSize_), fingerprint_, s);
}

std::size_t HierarchicalRadiosity::linksGatheredBy(std::uint32_t leaf) const {
    std::size_t links = 0;
    for (std::uint32_t e = leaf; e != Element::kNone; e = parent_[e])
        links += links_[e].size();
    return links;
}

std::size_t HierarchicalRadiosity::leafTermCount() const {
    std::size_t terms = 0;
    for (std::uint32_t leaf : mesh_.leaves())
        terms += linksGatheredBy(leaf);
    return terms;
}

std::vector<HierarchicalRadiosity::Candidate> HierarchicalRadiosity::firstCandidates() const {
    if (!clusters_.empty()) return {{clusters_.top(), clusters_.top()}};
    std::vector<Candidate> candidates;
    candidates.reserve(roots_.size() * roots_.size());
    for (std::uint32_t r : roots_)
        for (std::uint32_t s : roots_)
            if (r != s) candidates.push_back({r, s});
    return candidates;
}

RadiositySolution HierarchicalRadiosity::snapshot() const {
    std::vector<std::uint32_t> leaves = mesh_.leaves();
    const std::size_t count = leaves.size();
    return VertexSmoothing(mesh_, std::move(leaves), 1e-5 * patchSize_)
        .solution(mesh_.lookupDistance(patchSize_), fingerprint_, statistics(count));
}

}  // namespace lancer
