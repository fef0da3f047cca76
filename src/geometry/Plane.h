#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/Shape.h"
#include "util/Parameters.h"

namespace lancer {

// An infinite, two-sided plane through `point` with unit normal `normal`.
class Plane final : public Shape {
public:
    Plane(const Vec3& point, const Vec3& normal, const Material* material);
    // The scene file's "plane": point, normal (non-zero).
    static std::vector<std::string> keys() { return {"point", "normal"}; }
    static std::unique_ptr<Shape> create(const Parameters& parameters, const Material* material);

    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    Bounds3 bounds() const override;
    bool isBounded() const override { return false; }
    // Infinite: a plane cannot be sampled as a light (only rays that hit it find its light).
    float area(std::uint32_t) const override { return kInfinity; }
    std::optional<ShapeSample> sample(std::uint32_t, const Vec2&) const override {
        return std::nullopt;
    }
    // The part inside the request's box, as a fan of facets.
    Tessellation tessellate(const TessellationRequest& request) const override;

    const Vec3& normal() const { return normal_; }

private:
    Vec3 point_;
    Vec3 normal_;
    int uAxis_, vAxis_;  // the world axes used as texture coordinates
    Vec3 dpdu_, dpdv_;   // steps along the plane that change u (or v) by one and keep v (or u)
};

}  // namespace lancer
