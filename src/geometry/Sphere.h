#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "geometry/Shape.h"
#include "util/Parameters.h"

namespace lancer {

// A sphere, two-sided. uv: u the longitude from +x towards -z (counter-clockwise seen from +y),
// v the latitude from the south pole (0) to the north pole (1). Seen as a light from outside,
// it is sampled uniformly within the cone it subtends; from inside (or on it), by area.
class Sphere final : public Shape {
public:
    Sphere(const Vec3& center, float radius, const Material* material);
    // The scene file's "sphere": center, radius (> 0).
    static std::vector<std::string> keys() { return {"center", "radius"}; }
    static std::unique_ptr<Shape> create(const Parameters& parameters, const Material* material);

    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    // From the unit normal in the sphere's frame.
    Vec2 uvAt(const Vec3& n) const override;
    Bounds3 bounds() const override;
    bool isSolid() const override { return true; }
    void crossLine(const Ray& ray, LineCrossings& crossings) const override;
    void crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const override;

    float area(std::uint32_t primitive) const override;
    std::optional<ShapeSample> sample(std::uint32_t primitive, const Vec2& u) const override;
    std::optional<DirectionSample> sample(std::uint32_t primitive, const Vec3& reference,
                                          const Vec2& u) const override;
    float pdf(std::uint32_t primitive, const Vec3& reference, const Vec3& wi,
              const Hit& onSurface) const override;
    // A latitude-longitude grid of chords, as fine as the patch size asks.
    Tessellation tessellate(const TessellationRequest& request) const override;

    const Vec3& center() const { return center_; }
    float radius() const { return radius_; }

private:
    // Which roots of the ray's line a caller needs.
    enum class Roots { all, ahead };
    // Where the ray's line meets the sphere, in increasing order (equal where it touches). With
    // Roots::ahead, nothing either when both are known to lie behind the origin before solving.
    std::optional<std::pair<double, double>> lineRoots(const Ray& ray, Roots wanted) const;
    // Whether p is inside the sphere or within rounding error of its surface (hit points on the
    // sphere itself, from inside or out): from there the whole sphere is seen, which area
    // sampling covers, while the cone would shrink to the point itself.
    bool containsOrTouches(const Vec3& p) const;
    // 1 - cos(theta_max) of the cone the sphere subtends from p, where p is outside it.
    double oneMinusCosConeAngle(const Vec3& p) const;
    // The density of directions sampled uniformly within that cone: 1 / (2 pi (1 - cos)).
    float coneDensity(const Vec3& p) const;

    Vec3 center_;
    float radius_;
};

}  // namespace lancer
