#include "geometry/Csg.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "math/Float4.h"

namespace lancer {

namespace {

// Crossings of different children closer than this, relative to the distances involved, are
// one event: the rounding of where a face shared by two children lies, seen from each.
constexpr double kCoincident = 2e-6;

// How many times a facet across the edge of the result's surface is halved (into four) before
// its centre decides.
constexpr int kEdgeRefinement = 3;

// A child's crossing as the sweep orders it: a key of the sort, and what the sweep reads.
struct SweepEvent {
    double t;
    std::uint32_t primitive;  // the result's
    std::uint32_t child;
    std::uint32_t index;  // of the crossing in Sweep::events
    bool entering;
};

// What a sweep along a line needs, kept from ray to ray by each thread: one set per level of
// nesting, since a child that is a CSG sweeps while its parent's sweep is under way.
struct Sweep {
    LineCrossings events;
    std::vector<SweepEvent> order;
    std::vector<int> depth;
};

class SweepLease {
public:
    SweepLease() {
        if (level_ == pool_.size()) pool_.push_back(std::make_unique<Sweep>());
        sweep_ = pool_[level_++].get();
    }
    ~SweepLease() { --level_; }
    SweepLease(const SweepLease&) = delete;
    SweepLease& operator=(const SweepLease&) = delete;
    Sweep& operator*() const { return *sweep_; }

private:
    static thread_local std::vector<std::unique_ptr<Sweep>> pool_;
    static thread_local std::size_t level_;
    Sweep* sweep_;
};

thread_local std::vector<std::unique_ptr<Sweep>> SweepLease::pool_;
thread_local std::size_t SweepLease::level_ = 0;

// The part tLow < t < tHigh of a ray's line, tested against the children's boxes four at a time
// by the BVH's slab test (the boxes are padded far beyond its rounding). The reciprocal of the
// direction, and which side of a box the line enters by, are found once for all the children of
// a query.
class LineWindow {
public:
    LineWindow(const Ray& ray, double tLow, double tHigh)
        : tLow_(static_cast<float>(tLow)), tHigh_(static_cast<float>(tHigh)) {
        for (int axis = 0; axis < 3; ++axis) {
            origin_[axis] = Float4(ray.origin[axis]);
            // A zero component gives an infinite reciprocal of the zero's sign.
            const float inverse = 1.0f / ray.direction[axis];
            inverse_[axis] = Float4(inverse);
            entrySide_[axis] = inverse < 0 ? 1 : 0;
        }
    }

    // Bit i: whether the line passes through the group's box i somewhere in the window.
    int meets(const Csg::BoxGroup& boxes) const {
        Float4 tEnter = tLow_, tExit = tHigh_;
        for (int axis = 0; axis < 3; ++axis) {
            // Indexed, not chosen by a branch: the sides change from ray to ray.
            const float* entry = boxes.corners[entrySide_[axis]][axis];
            const float* exit = boxes.corners[1 - entrySide_[axis]][axis];
            // NaN (0 * infinity: the line in a slab's plane) leaves the window unchanged, as
            // max and min keep their first operand then.
            tEnter = max(tEnter, (Float4::load(entry) - origin_[axis]) * inverse_[axis]);
            tExit = min(tExit, (Float4::load(exit) - origin_[axis]) * inverse_[axis]);
        }
        return le(tEnter, tExit);
    }

private:
    Float4 origin_[3], inverse_[3];
    int entrySide_[3];  // of the boxes: 1 where the line enters by the larger corner
    Float4 tLow_, tHigh_;
};

}  // namespace

Csg::Csg(Operation operation, std::vector<std::unique_ptr<Shape>> children,
         const Material* material)
    : Shape(material), operation_(operation), children_(std::move(children)) {
    firstPrimitive_.push_back(0);
    for (const auto& child : children_) {
        firstPrimitive_.push_back(firstPrimitive_.back() + child->primitiveCount());
        // Padded by far more than the rounding of the children's own tests, so that a line the
        // box test turns away never had a crossing to give.
        const Bounds3 b = child->bounds();
        const Vec3 pad = 1e-5f * (b.max - b.min) + 1e-6f * max(abs(b.min), abs(b.max));
        const std::size_t k = &child - children_.data();
        if (k % 4 == 0) childBoxes_.emplace_back();  // its empty boxes meet no line
        for (int axis = 0; axis < 3; ++axis) {
            childBoxes_.back().corners[0][axis][k % 4] = b.min[axis] - pad[axis];
            childBoxes_.back().corners[1][axis][k % 4] = b.max[axis] + pad[axis];
        }
    }
    bounds_ = children_.front()->bounds();
    for (std::size_t k = 1; k < children_.size(); ++k) {
        const Bounds3 b = children_[k]->bounds();
        if (operation_ == Operation::kUnion) bounds_ = merge(bounds_, b);
        if (operation_ == Operation::kIntersection)
            bounds_ = {max(bounds_.min, b.min), min(bounds_.max, b.max)};
    }
    // An empty intersection hits nothing; any box will do.
    if (bounds_.isEmpty()) bounds_ = children_.front()->bounds();
    diagonalLength_ = length(bounds_.diagonal());
}

const std::vector<std::string>& Csg::operationNames() {
    // In the order of Operation.
    static const std::vector<std::string> names{"union", "intersection", "difference"};
    return names;
}

std::size_t Csg::childOf(std::uint32_t primitive) const {
    const auto after = std::upper_bound(firstPrimitive_.begin(), firstPrimitive_.end(), primitive);
    return static_cast<std::size_t>(after - firstPrimitive_.begin()) - 1;
}

bool Csg::inResult(std::size_t insideCount, bool insideFirst) const {
    switch (operation_) {
        case Operation::kUnion:
            return insideCount > 0;
        case Operation::kIntersection:
            return insideCount == children_.size();
        case Operation::kDifference:
            return insideFirst && insideCount == 1;
    }
    return false;
}

bool Csg::onResultSurface(std::size_t k, const Vec3& p) const {
    std::size_t othersInside = 0;
    bool firstInside = false;
    for (std::size_t i = 0; i < children_.size(); ++i)
        if (i != k && children_[i]->contains(p)) {
            ++othersInside;
            firstInside = firstInside || i == 0;
        }
    return inResult(othersInside + 1, firstInside || k == 0) != inResult(othersInside, firstInside);
}

template <typename Visit>
void Csg::sweepLine(const Ray& ray, double tFrom, double tTo, Visit&& visit) const {
    const SweepLease lease;
    Sweep& sweep = *lease;
    // The children's crossings, numbered as the result's primitives.
    LineCrossings& events = sweep.events;
    std::vector<SweepEvent>& order = sweep.order;
    events.clear();
    order.clear();
    const LineWindow window(ray, tFrom, tTo);
    int meets = 0;
    for (std::size_t k = 0; k < children_.size(); ++k) {
        if (k % 4 == 0) meets = window.meets(childBoxes_[k / 4]);
        const std::size_t first = events.size();
        // A child the line meets only before tFrom or after tTo is outside all along the
        // window: its crossings change nothing there.
        if (meets >> (k % 4) & 1) children_[k]->crossLine(ray, events);
        // Nothing of an intersection, or of a difference, lies off its first child.
        if (events.size() == first && (operation_ == Operation::kIntersection ||
                                       (operation_ == Operation::kDifference && k == 0)))
            return;
        for (std::size_t i = first; i < events.size(); ++i) {
            SurfaceCrossing& c = events[i].crossing;
            c.primitive += firstPrimitive_[k];
            order.push_back({c.t, c.primitive, static_cast<std::uint32_t>(k),
                             static_cast<std::uint32_t>(i), events[i].entering});
        }
    }
    // In order of t; at equal t, in the children's order. By insertion: there are few, and each
    // child's come in order already.
    for (std::size_t i = 1; i < order.size(); ++i) {
        const SweepEvent event = order[i];
        std::size_t j = i;
        for (; j > 0 && (event.t < order[j - 1].t ||
                         (event.t == order[j - 1].t && event.primitive < order[j - 1].primitive));
             --j)
            order[j] = order[j - 1];
        order[j] = event;
    }

    // The rounding of a crossing's t grows with the distances from the origin it was found from.
    const double speed = length(Vec3d(ray.direction));
    const double reach = (static_cast<double>(maxComponent(abs(ray.origin))) + diagonalLength_) /
                         (speed > 0 ? speed : 1);
    // Each child's depth, and how many children the line is in (at t = -infinity, none).
    sweep.depth.assign(children_.size(), 0);
    std::size_t insideCount = 0;
    bool inBefore = false;
    for (std::size_t first = 0; first < order.size();) {
        const double t0 = order[first].t;
        const double tolerance = kCoincident * (std::abs(t0) + reach);
        std::size_t end = first;
        for (; end < order.size() && order[end].t - t0 <= tolerance; ++end) {
            int& depth = sweep.depth[order[end].child];
            const bool wasInside = depth > 0;
            depth += order[end].entering ? 1 : -1;
            if (wasInside != (depth > 0)) insideCount += wasInside ? -1 : 1;
        }
        const bool inAfter = inResult(insideCount, sweep.depth.front() > 0);
        if (inAfter != inBefore) {
            // The surface is that of a child whose own step goes the result's way (of those in
            // the event: coincident faces of the same side give the same point).
            std::size_t chosen = first;
            for (std::size_t i = first; i < end; ++i)
                if ((order[i].entering != isCarving(order[i].child)) == inAfter) {
                    chosen = i;
                    break;
                }
            if (visit(events[order[chosen].index].crossing, inAfter)) return;
            inBefore = inAfter;
        }
        first = end;
    }
}

std::optional<SurfaceCrossing> Csg::cross(const Ray& ray, float tMax) const {
    std::optional<SurfaceCrossing> nearest;
    sweepLine(ray, 0, tMax, [&](const SurfaceCrossing& surface, bool) {
        if (surface.t <= 0) return false;  // behind the origin: on to the next
        if (surface.t < tMax) nearest = surface;
        return true;
    });
    return nearest;
}

void Csg::crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const {
    sweepLine(ray, 0, tMax, [&](const SurfaceCrossing& surface, bool) {
        if (surface.t <= 0) return false;  // behind the origin: on to the next
        if (surface.t >= tMax) return true;
        crossings.push_back(surface);
        return false;
    });
}

void Csg::crossLine(const Ray& ray, LineCrossings& crossings) const {
    constexpr double kWholeLine = std::numeric_limits<double>::infinity();
    sweepLine(ray, -kWholeLine, kWholeLine, [&](const SurfaceCrossing& surface, bool entering) {
        crossings.push_back({surface, entering});
        return false;
    });
}

Hit Csg::record(const Ray& ray, const SurfaceCrossing& crossing) const {
    const std::size_t k = childOf(crossing.primitive);
    SurfaceCrossing own = crossing;
    own.primitive -= firstPrimitive_[k];
    Hit hit = children_[k]->record(ray, own);
    if (isCarving(k)) {
        hit.ng = -hit.ng;
        hit.ns = -hit.ns;
    }
    hit.shape = this;
    hit.primitive = crossing.primitive;
    if (!hit.material) hit.material = material();
    return hit;
}

const Material* Csg::primitiveMaterial(std::uint32_t primitive) const {
    const std::size_t k = childOf(primitive);
    const Material* own = children_[k]->primitiveMaterial(primitive - firstPrimitive_[k]);
    return own ? own : material();
}

float Csg::area(std::uint32_t primitive) const {
    const std::size_t k = childOf(primitive);
    return children_[k]->area(primitive - firstPrimitive_[k]);
}

std::optional<ShapeSample> Csg::sample(std::uint32_t primitive, const Vec2& u) const {
    const std::size_t k = childOf(primitive);
    std::optional<ShapeSample> s = children_[k]->sample(primitive - firstPrimitive_[k], u);
    if (!s || !onResultSurface(k, s->p)) return std::nullopt;
    if (isCarving(k)) s->n = -s->n;
    return s;
}

float Csg::areaPdf(std::uint32_t primitive, const Hit& onSurface) const {
    const std::size_t k = childOf(primitive);
    return children_[k]->areaPdf(primitive - firstPrimitive_[k], onSurface);
}

void Csg::addVisibleParts(std::size_t k, const Tessellation::Facet& facet, int refinements,
                          std::vector<Tessellation::Facet>& facets) const {
    const auto& [a, b, c] = facet.corners;
    const bool centreVisible = onResultSurface(k, (a + b + c) / 3.0f);
    const int visibleCorners =
        onResultSurface(k, a) + onResultSurface(k, b) + onResultSurface(k, c);
    const bool across = visibleCorners != (centreVisible ? 3 : 0);
    if (!across || refinements == 0) {
        if (centreVisible) facets.push_back(facet);
        return;
    }
    const Vec3 ab = 0.5f * (a + b), bc = 0.5f * (b + c), ca = 0.5f * (c + a);
    for (const std::array<Vec3, 3>& corners : {std::array{a, ab, ca}, std::array{ab, b, bc},
                                               std::array{ca, bc, c}, std::array{ab, bc, ca}})
        addVisibleParts(k, {corners, facet.primitive}, refinements - 1, facets);
}

Tessellation Csg::tessellate(const TessellationRequest& request) const {
    Tessellation result;
    for (std::size_t k = 0; k < children_.size(); ++k) {
        Tessellation piece = children_[k]->tessellate(request);
        result.curved = result.curved || piece.curved;
        result.probeDistance = std::max(result.probeDistance, piece.probeDistance);
        for (Tessellation::Facet& facet : piece.facets) {
            facet.primitive += firstPrimitive_[k];
            // A carved surface's front faces into the child that carves it.
            if (isCarving(k)) std::swap(facet.corners[1], facet.corners[2]);
            addVisibleParts(k, facet, kEdgeRefinement, result.facets);
        }
    }
    return result;
}

}  // namespace lancer
