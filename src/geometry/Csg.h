#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/Shape.h"

namespace lancer {

// Constructive solid geometry (POV-Ray's union, intersection and difference) of solids, which
// may be CSGs themselves. A ray's line is followed through the children's crossings in order of
// t, each child in or out, and the crossings where the result goes in or out are its surface.
// Crossings of different children closer than rounding error (coincident faces) count as one
// event, so that a box minus a box sharing a face shows no speckled seam.
//
// Primitives: the children's, one after the other. A point of the result's surface keeps its
// child's material, uv and derivatives; its normals point out of the result, so the surface a
// subtracted child carves faces into that child. Sampled as a light by the children's own area
// sampling, a sample that falls on a hidden part of a child giving nothing.
class Csg final : public Shape {
public:
    enum class Operation { kUnion, kIntersection, kDifference };

    Csg(Operation operation, std::vector<std::unique_ptr<Shape>> children,
        const Material* material);
    static const std::vector<std::string>& operationNames();

    // The boxes of four children, a little larger than theirs: corners[0] the smaller corners,
    // corners[1] the larger, by axis and child (an empty box where there is no child).
    struct BoxGroup {
        alignas(16) float corners[2][3][4] = {{{kInfinity, kInfinity, kInfinity, kInfinity},
                                               {kInfinity, kInfinity, kInfinity, kInfinity},
                                               {kInfinity, kInfinity, kInfinity, kInfinity}},
                                              {{-kInfinity, -kInfinity, -kInfinity, -kInfinity},
                                               {-kInfinity, -kInfinity, -kInfinity, -kInfinity},
                                               {-kInfinity, -kInfinity, -kInfinity, -kInfinity}}};
    };

    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    Bounds3 bounds() const override { return bounds_; }
    bool isSolid() const override { return true; }
    void crossLine(const Ray& ray, LineCrossings& crossings) const override;
    void crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const override;
    // A solid gives light to its outside only.
    bool emitsOnBothSides() const override { return false; }
    std::uint32_t primitiveCount() const override { return firstPrimitive_.back(); }
    const Material* primitiveMaterial(std::uint32_t primitive) const override;
    // The whole of the child's primitive, the hidden part included: what sample() draws from.
    float area(std::uint32_t primitive) const override;
    std::optional<ShapeSample> sample(std::uint32_t primitive, const Vec2& u) const override;
    float areaPdf(std::uint32_t primitive, const Hit& onSurface) const override;
    // The children's facets that lie on the result's surface, those across its edge cut finer.
    Tessellation tessellate(const TessellationRequest& request) const override;

private:
    // The child holding a primitive of the result, and the primitive's number in that child.
    std::size_t childOf(std::uint32_t primitive) const;
    // Whether a point is in the result, given how many children it is in and whether the first
    // is one of them.
    bool inResult(std::size_t insideCount, bool insideFirst) const;
    // Whether a point on child k's surface is on the result's surface: the result changes with
    // k's inside, the other children's taken at the point.
    bool onResultSurface(std::size_t k, const Vec3& p) const;
    // Whether the result's outward normal is opposite the child's on the child's surface.
    bool isCarving(std::size_t k) const { return operation_ == Operation::kDifference && k > 0; }
    // Adds the parts of child k's facet that lie on the result's surface.
    void addVisibleParts(std::size_t k, const Tessellation::Facet& facet, int refinements,
                         std::vector<Tessellation::Facet>& facets) const;
    // Visits the result's crossings along the ray's line that the children met within
    // tFrom < t < tTo make (those met only outside it are left out, which changes nothing within
    // it), in order, each numbered by the result's primitive: visit(crossing, entering) returns
    // whether to stop there.
    template <typename Visit>
    void sweepLine(const Ray& ray, double tFrom, double tTo, Visit&& visit) const;

    Operation operation_;
    std::vector<std::unique_ptr<Shape>> children_;
    std::vector<std::uint32_t> firstPrimitive_;  // per child, and the total at the end
    std::vector<BoxGroup> childBoxes_;           // children 4k to 4k + 3 in group k
    Bounds3 bounds_;
    float diagonalLength_;  // of bounds_, which the rounding of crossings' t grows with
};

}  // namespace lancer
