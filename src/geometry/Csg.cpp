#include "geometry/Csg.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace lancer {

namespace {

// Crossings of different children closer than this, relative to the distances involved, are
// one event: the rounding of where a face shared by two children lies, seen from each.
constexpr double kCoincident = 2e-6;

// How many times a facet across the edge of the result's surface is halved (into four) before
// its centre decides.
constexpr int kEdgeRefinement = 3;

// What a sweep along a line needs, kept from ray to ray by each thread: one set per level of
// nesting, since a child that is a CSG sweeps while its parent's sweep is under way.
struct Sweep {
    LineCrossings events;
    std::vector<int> depth;
    std::vector<bool> inside;
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

// Whether the ray's line passes through the box (in double; the box already padded) somewhere
// with tLow < t < tHigh.
bool lineMeetsBox(const Ray& ray, const Bounds3& box, double tLow, double tHigh) {
    double tEnter = tLow, tExit = tHigh;
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis], d = ray.direction[axis];
        const double lo = box.min[axis], hi = box.max[axis];
        if (d == 0) {
            if (o < lo || o > hi) return false;
            continue;
        }
        const double t0 = (lo - o) / d, t1 = (hi - o) / d;
        tEnter = std::max(tEnter, std::min(t0, t1));
        tExit = std::min(tExit, std::max(t0, t1));
    }
    return tEnter <= tExit;
}

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
        childBounds_.push_back({b.min - pad, b.max + pad});
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

bool Csg::inResult(const std::vector<bool>& insideChild) const {
    switch (operation_) {
        case Operation::kUnion:
            return std::find(insideChild.begin(), insideChild.end(), true) != insideChild.end();
        case Operation::kIntersection:
            return std::find(insideChild.begin(), insideChild.end(), false) == insideChild.end();
        case Operation::kDifference:
            return insideChild.front() &&
                   std::find(insideChild.begin() + 1, insideChild.end(), true) == insideChild.end();
    }
    return false;
}

bool Csg::onResultSurface(std::size_t k, const Vec3& p) const {
    // (Asked for every light sample: the thread's buffer, not a new vector.)
    const SweepLease lease;
    std::vector<bool>& inside = (*lease).inside;
    inside.assign(children_.size(), false);
    for (std::size_t i = 0; i < children_.size(); ++i)
        if (i != k) inside[i] = children_[i]->contains(p);
    inside[k] = true;
    const bool withK = inResult(inside);
    inside[k] = false;
    return withK != inResult(inside);
}

void Csg::resultCrossings(const Ray& ray, double tFrom, double tTo, bool firstOnly,
                          LineCrossings& crossings) const {
    const SweepLease lease;
    Sweep& sweep = *lease;
    // The children's crossings, numbered as the result's primitives (which tells their child).
    LineCrossings& events = sweep.events;
    events.clear();
    for (std::size_t k = 0; k < children_.size(); ++k) {
        const std::size_t first = events.size();
        // A child the line meets only before tFrom or after tTo is outside all along the
        // window: its crossings change nothing there.
        if (lineMeetsBox(ray, childBounds_[k], tFrom, tTo)) children_[k]->crossLine(ray, events);
        // Nothing of an intersection, or of a difference, lies off its first child.
        if (events.size() == first && (operation_ == Operation::kIntersection ||
                                       (operation_ == Operation::kDifference && k == 0)))
            return;
        for (std::size_t i = first; i < events.size(); ++i)
            events[i].crossing.primitive += firstPrimitive_[k];
    }
    // In order of t; at equal t, in the children's order.
    std::sort(events.begin(), events.end(), [](const LineCrossing& a, const LineCrossing& b) {
        return a.crossing.t < b.crossing.t ||
               (a.crossing.t == b.crossing.t && a.crossing.primitive < b.crossing.primitive);
    });

    // The rounding of a crossing's t grows with the distances from the origin it was found from.
    const double speed = length(Vec3d(ray.direction));
    const double reach =
        (static_cast<double>(maxComponent(abs(ray.origin))) + length(bounds_.diagonal())) /
        (speed > 0 ? speed : 1);
    sweep.depth.assign(children_.size(), 0);
    sweep.inside.assign(children_.size(), false);
    bool inBefore = false;  // at t = -infinity, outside every child
    for (std::size_t first = 0; first < events.size();) {
        const double t0 = events[first].crossing.t;
        const double tolerance = kCoincident * (std::abs(t0) + reach);
        std::size_t end = first;
        for (; end < events.size() && events[end].crossing.t - t0 <= tolerance; ++end) {
            const std::size_t k = childOf(events[end].crossing.primitive);
            sweep.depth[k] += events[end].entering ? 1 : -1;
            sweep.inside[k] = sweep.depth[k] > 0;
        }
        const bool inAfter = inResult(sweep.inside);
        if (inAfter != inBefore) {
            // The surface is that of a child whose own step goes the result's way (of those in
            // the event: coincident faces of the same side give the same point).
            std::size_t chosen = first;
            for (std::size_t i = first; i < end; ++i)
                if ((events[i].entering != isCarving(childOf(events[i].crossing.primitive))) ==
                    inAfter) {
                    chosen = i;
                    break;
                }
            crossings.push_back({events[chosen].crossing, inAfter});
            if (firstOnly && events[chosen].crossing.t > tFrom) return;
            inBefore = inAfter;
        }
        first = end;
    }
}

std::optional<SurfaceCrossing> Csg::cross(const Ray& ray, float tMax) const {
    thread_local LineCrossings crossings;
    crossings.clear();
    resultCrossings(ray, 0, tMax, true, crossings);
    if (crossings.empty()) return std::nullopt;
    const SurfaceCrossing& last = crossings.back().crossing;
    if (last.t > 0 && last.t < tMax) return last;
    return std::nullopt;
}

void Csg::crossLine(const Ray& ray, LineCrossings& crossings) const {
    constexpr double kWholeLine = std::numeric_limits<double>::infinity();
    resultCrossings(ray, -kWholeLine, kWholeLine, false, crossings);
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
