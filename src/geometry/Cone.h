#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "geometry/Disk.h"
#include "geometry/Shape.h"
#include "util/Parameters.h"

namespace lancer {

// A truncated cone (POV-Ray's cone) from a circle of radius r0 about `base` to one of radius r1
// about `top`, both square to the axis base -> top; closed by flat caps (a solid, normals out)
// unless open. A cylinder is the cone with r0 = r1.
//
// Primitives: 0 is the side, then the caps that exist (base first; none when open, and none of
// radius 0). On the side u = phi / 2 pi, the angle about the axis from the first tangent of the
// frame lancer builds about it (counter-clockwise seen from the top), and v = z / height, 0 at the
// base and 1 at the top, so that dpdu x dpdv points out; each cap has the uv of a disk.
class Cone : public Shape {
public:
    Cone(const Vec3& base, float baseRadius, const Vec3& top, float topRadius, bool open,
         const Material* material);
    // The scene file's "cone": base, base_radius (>= 0), top, top_radius (>= 0, not both 0),
    // open (default false).
    static std::vector<std::string> keys() {
        return {"base", "base_radius", "top", "top_radius", "open"};
    }
    static std::unique_ptr<Shape> create(const Parameters& parameters, const Material* material);

    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    // From the side's point: its (x, y) in the frame of the tangent and bitangent, and its v.
    Vec2 uvAt(const Vec3& local) const override;
    Bounds3 bounds() const override;
    // Closed, it is a solid.
    bool isSolid() const override { return !caps_.empty(); }
    void crossLine(const Ray& ray, LineCrossings& crossings) const override;
    void crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const override;
    // A closed cone gives light to its outside only; an open one is a two-sided surface.
    bool emitsOnBothSides() const override { return caps_.empty(); }
    std::uint32_t primitiveCount() const override {
        return 1 + static_cast<std::uint32_t>(caps_.size());
    }
    float area(std::uint32_t primitive) const override;
    std::optional<ShapeSample> sample(std::uint32_t primitive, const Vec2& u) const override;
    // The side as rows of quads and the caps as rings, sharing the vertices of their rims.
    Tessellation tessellate(const TessellationRequest& request) const override;

protected:
    // Checks the keys a cone and a cylinder share: distinct base and top.
    static void checkAxis(const Parameters& parameters, const Vec3& base, const Vec3& top);

private:
    // Where the ray's whole line crosses the side, in increasing t, entering or leaving.
    struct SideCrossings {
        std::array<LineCrossing, 2> crossings;
        int count = 0;
    };
    SideCrossings sideCrossings(const Ray& ray) const;
    // The side's point at angle phi about the axis and height z above the base.
    Vec3 sidePoint(float phi, float z) const;
    float radiusAt(float z) const { return baseRadius_ + (topRadius_ - baseRadius_) * z / height_; }

    Vec3 base_, axis_;
    Vec3 tangent_, bitangent_;  // with axis_, a right-handed frame
    float height_, baseRadius_, topRadius_;
    std::vector<std::unique_ptr<Disk>> caps_;
};

}  // namespace lancer
