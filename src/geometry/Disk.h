#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/PlaneCrossing.h"
#include "geometry/Shape.h"
#include "util/Parameters.h"

namespace lancer {

// A flat, two-sided disk of radius R about `center`, facing `normal`, with a hole of radius
// Ri < R (an annulus) when Ri > 0. uv: u = phi / 2 pi, the angle about the normal from the
// frame's first tangent, v = (R - r) / (R - Ri), 0 on the rim and 1 on the inner edge (pbrt's
// convention).
class Disk final : public Shape {
public:
    Disk(const Vec3& center, const Vec3& normal, float radius, float innerRadius,
         const Material* material);
    // The scene file's "disk": center, normal (non-zero), radius (> 0), inner_radius (in
    // [0, radius), default 0).
    static std::vector<std::string> keys() {
        return {"center", "normal", "radius", "inner_radius"};
    }
    static std::unique_ptr<Shape> create(const Parameters& parameters, const Material* material);

    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    // From the point's (x, y) in the frame of the tangent and bitangent, and its v.
    Vec2 uvAt(const Vec3& local) const override;
    // Where the ray's whole line crosses the disk (t of either sign), as cross() would find it.
    std::optional<SurfaceCrossing> lineCrossing(const Ray& ray) const;
    const Vec3& normal() const { return normal_; }
    Bounds3 bounds() const override;
    float area(std::uint32_t primitive) const override;
    std::optional<ShapeSample> sample(std::uint32_t primitive, const Vec2& u) const override;
    // Rings of quads (a fan of triangles about the centre without a hole), as fine as the patch
    // size asks; the polygon is inscribed in the circles.
    Tessellation tessellate(const TessellationRequest& request) const override;

private:
    bool withinRing(const PlaneCrossing& crossing) const;
    // The point at polar coordinates (r, phi) in the disk's plane.
    Vec3 pointAt(float r, float phi) const;

    Vec3 center_, normal_;
    Vec3 tangent_, bitangent_;  // with normal_, a right-handed frame: tangent x bitangent = normal
    float radius_, innerRadius_;
};

}  // namespace lancer
