#include "radiosity/ClusterHierarchy.h"

#include <algorithm>

#include "math/Bounds3.h"

namespace lancer {

namespace {

// A point of the triangle from one of the unit square, uniform over the triangle when the
// square's point is.
Vec3 uniformPointOn(const std::array<Vec3, 3>& t, const Vec2& uv) {
    const float su = std::sqrt(uv.x);
    return (1 - su) * t[0] + su * (1 - uv.y) * t[1] + su * uv.y * t[2];
}

// A point of an element (its corners, normal and patch) for ClusterHierarchy::sample.
ClusterHierarchy::SurfacePoint pointOn(const std::array<Vec3, 3>& corners, const Vec3& normal,
                                       const Patch& patch, const Vec3& towards, const Vec2& u) {
    ClusterHierarchy::SurfacePoint s;
    s.p = uniformPointOn(corners, u);
    s.n = dot(normal, towards - s.p) >= 0 ? normal : -normal;
    s.patch = &patch;
    return s;
}

// How many members after the one drawn a cluster's sample looks through for one facing the
// other end.
constexpr std::uint32_t kFacingSearch = 8;

}  // namespace

ClusterHierarchy::ClusterHierarchy(const RadiosityMesh& mesh, std::vector<std::uint32_t> roots)
    : members_(std::move(roots)) {
    if (members_.size() < 2) {
        members_.clear();
        return;
    }
    clusters_.reserve(members_.size() - 1);
    build(mesh, 0, static_cast<std::uint32_t>(members_.size()), Element::kNone);
    areaBefore_.resize(members_.size() + 1, 0);
    memberShapes_.assign(blockCount(), ShapeBlock{});
    memberCorners_.reserve(members_.size());
    for (std::size_t i = 0; i < members_.size(); ++i) {
        const Element& e = mesh.elements[members_[i]];
        areaBefore_[i + 1] = areaBefore_[i] + e.area;
        memberCorners_.push_back(e.corners);
        ShapeBlock& block = memberShapes_[i / ColorLanes::kLanes];
        const std::size_t lane = i % ColorLanes::kLanes;
        block.x[lane] = e.centroid.x;
        block.y[lane] = e.centroid.y;
        block.z[lane] = e.centroid.z;
        block.nx[lane] = e.normal.x;
        block.ny[lane] = e.normal.y;
        block.nz[lane] = e.normal.z;
        block.area[lane] = e.area;
        block.patch[lane] = e.patch;
    }
}

std::uint32_t ClusterHierarchy::build(const RadiosityMesh& mesh, std::uint32_t first,
                                      std::uint32_t count, std::uint32_t parent) {
    if (count == 1) {
        const std::uint32_t element = members_[first];
        if (rootParent_.size() <= element) rootParent_.resize(element + 1, Element::kNone);
        rootParent_[element] = parent;
        return element;
    }
    const auto index = static_cast<std::uint32_t>(clusters_.size());
    clusters_.emplace_back();
    Bounds3 box, centroids;
    float area = 0, reflectance = 0;
    for (std::uint32_t i = first; i < first + count; ++i) {
        const Element& e = mesh.elements[members_[i]];
        for (const Vec3& corner : e.corners)
            box = merge(box, corner);
        centroids = merge(centroids, e.centroid);
        area += e.area;
        reflectance = std::max(reflectance, e.reflectance.average());
    }
    // The median along the centroids' longest axis (ties broken by element: the same tree on
    // every run).
    const int axis = centroids.maxExtentAxis();
    const std::uint32_t half = count / 2;
    const auto begin = members_.begin() + first;
    std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t a, std::uint32_t b) {
        const float ca = mesh.elements[a].centroid[axis], cb = mesh.elements[b].centroid[axis];
        return ca < cb || (ca == cb && a < b);
    });
    const std::uint32_t left = build(mesh, first, half, index);
    const std::uint32_t right = build(mesh, first + half, count - half, index);
    Cluster& c = clusters_[index];
    c.center = box.centroid();
    c.radius = 0.5f * length(box.diagonal());
    c.area = area;
    c.reflectance = reflectance;
    c.children = {left, right};
    c.parent = parent;
    c.firstMember = first;
    c.memberCount = count;
    return nodeOf(index);
}

ClusterHierarchy::Extent ClusterHierarchy::extent(const RadiosityMesh& mesh,
                                                  std::uint32_t node) const {
    if (isCluster(node)) return {cluster(node).center, cluster(node).radius};
    const Element& e = mesh.elements[node];
    return {e.centroid, e.radius};
}

LANCER_ALWAYS_INLINE Color ClusterHierarchy::memberSum(std::uint32_t node, const Vec3& at,
                                                       const MemberRadiosities& radiosities) const {
    const Cluster& c = cluster(node);
    ColorLanes sum;
    ColorLanes::forEachBlock(
        c.firstMember, c.firstMember + c.memberCount,
        [&](std::uint32_t block, std::uint32_t lane, bool inRange) {
            const ShapeBlock& m = memberShapes_[block];
            const RadiosityBlock& B = radiosities[block];
            const Term t = term(at.x - m.x[lane], at.y - m.y[lane], at.z - m.z[lane], m.nx[lane],
                                m.ny[lane], m.nz[lane], m.area[lane]);
            // Both sides read, then one chosen: no branch in the lanes.
            const std::size_t front = sideIndex(Side::Front), back = sideIndex(Side::Back);
            const float fr = B.r[front][lane], fg = B.g[front][lane], fb = B.b[front][lane];
            const float br = B.r[back][lane], bg = B.g[back][lane], bb = B.b[back][lane];
            sum.addIf(inRange, lane, t.weight, t.front ? fr : br, t.front ? fg : bg,
                      t.front ? fb : bb);
        });
    return sum.total();
}

#if LANCER_HAS_AVX2_TARGET
Color ClusterHierarchy::memberSumAvx2(std::uint32_t node, const Vec3& at,
                                      const MemberRadiosities& radiosities) const {
    return memberSum(node, at, radiosities);
}
#endif

Color ClusterHierarchy::irradianceAt(std::uint32_t node, const Vec3& at,
                                     const MemberRadiosities& radiosities) const {
#if LANCER_HAS_AVX2_TARGET
    if (CpuFeatures::avx2()) return memberSumAvx2(node, at, radiosities);
#endif
    return memberSum(node, at, radiosities);
}

Color ClusterHierarchy::irradianceAt(const Element& e, const Vec3& at,
                                     const std::array<Color, 2>& radiosity) {
    const Vec3 toward = at - e.centroid;
    const Term t = term(toward.x, toward.y, toward.z, e.normal.x, e.normal.y, e.normal.z, e.area);
    return radiosity[sideIndex(t.front ? Side::Front : Side::Back)] * t.weight;
}

ClusterHierarchy::SurfacePoint ClusterHierarchy::sample(const RadiosityMesh& mesh,
                                                        std::uint32_t node, const Vec3& towards,
                                                        Vec2 u) const {
    if (!isCluster(node)) {
        const Element& e = mesh.elements[node];
        return pointOn(e.corners, e.normal, mesh.patches[e.patch], towards, u);
    }
    // The member under u.x along the members' areas laid end to end, u.x then rescaled within it.
    const Cluster& c = cluster(node);
    const double start = areaBefore_[c.firstMember];
    const double target = start + u.x * (areaBefore_[c.firstMember + c.memberCount] - start);
    const auto from = areaBefore_.begin() + c.firstMember + 1;
    const auto found = std::upper_bound(from, from + c.memberCount - 1, target);
    auto i = static_cast<std::uint32_t>(found - areaBefore_.begin()) - 1;
    const double width = areaBefore_[i + 1] - areaBefore_[i];
    u.x = width > 0
              ? std::clamp(static_cast<float>((target - areaBefore_[i]) / width), 0.0f, 0.99999994f)
              : 0.5f;
    const auto shapeOf = [&](std::uint32_t j) -> std::pair<const ShapeBlock&, std::size_t> {
        return {memberShapes_[j / ColorLanes::kLanes], j % ColorLanes::kLanes};
    };
    for (std::uint32_t k = 0; k < std::min(kFacingSearch, c.memberCount); ++k) {
        const std::uint32_t j = c.firstMember + (i - c.firstMember + k) % c.memberCount;
        const auto [m, lane] = shapeOf(j);
        if (dot(Vec3(m.nx[lane], m.ny[lane], m.nz[lane]),
                towards - Vec3(m.x[lane], m.y[lane], m.z[lane])) > 0) {
            i = j;
            break;
        }
    }
    // The member's corners, normal and patch from the members' arrays, not from its Element:
    // those are near what the search read, where the Element is a cache miss of its own.
    const auto [m, lane] = shapeOf(i);
    return pointOn(memberCorners_[i], Vec3(m.nx[lane], m.ny[lane], m.nz[lane]),
                   mesh.patches[m.patch[lane]], towards, u);
}

}  // namespace lancer
