#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/Shape.h"
#include "util/Parameters.h"

namespace lancer {

// A torus: the points at distance r from the circle of radius R > r about `axis` through
// `center`; a closed solid, normals out. In the frame (t1, t2, axis) that lancer builds about the
// axis, p = center + (R + r cos theta) (cos phi t1 + sin phi t2) + r sin theta axis, with
// u = phi / 2 pi (counter-clockwise seen from the axis' tip) and v = theta / 2 pi (0 on the outer
// equator, 1/4 on the top circle, 1/2 on the inner equator), so that dpdu x dpdv points out.
class Torus final : public Shape {
public:
    Torus(const Vec3& center, const Vec3& axis, float majorRadius, float minorRadius,
          const Material* material);
    // The scene file's "torus": major_radius (> 0), minor_radius (in (0, major_radius)), center
    // (default the origin), axis (non-zero, default [0, 1, 0]).
    static std::vector<std::string> keys() {
        return {"major_radius", "minor_radius", "center", "axis"};
    }
    static std::unique_ptr<Shape> create(const Parameters& parameters, const Material* material);

    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    Bounds3 bounds() const override;
    bool isSolid() const override { return true; }
    void crossLine(const Ray& ray, LineCrossings& crossings) const override;
    void crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const override;
    // A solid gives light to its outside only.
    bool emitsOnBothSides() const override { return false; }
    float area(std::uint32_t primitive) const override;
    std::optional<ShapeSample> sample(std::uint32_t primitive, const Vec2& u) const override;
    // A grid of quads in (phi, theta), fine enough that the probes that move points onto the
    // surface never reach across the tube or the hole.
    Tessellation tessellate(const TessellationRequest& request) const override;

private:
    // Calls visit(t, entering) on each crossing with tFrom < t < tTo, in increasing t, until it
    // returns true.
    template <typename Visit>
    void visitCrossings(const Ray& ray, double tFrom, double tTo, Visit&& visit) const;
    // The surface point at angles (phi, theta) and its outward normal, in double.
    Vec3d pointAt(double phi, double theta) const;
    Vec3d normalAt(double phi, double theta) const;
    // The fewest segments of a circle of the radius whose chords' ends stray no further than
    // depth from the circle's tangent at their middle: radius (1 - cos(2 pi / n)) <= depth.
    static int segmentsWithin(double radius, double depth);

    Vec3d center_, tangent_, bitangent_, axis_;  // a right-handed orthonormal frame, in double
    float majorRadius_, minorRadius_;
};

}  // namespace lancer
