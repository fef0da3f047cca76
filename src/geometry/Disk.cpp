#include "geometry/Disk.h"

#include <algorithm>
#include <cmath>

#include "geometry/FlatRings.h"
#include "geometry/PlaneCrossing.h"
#include "geometry/RevolutionUv.h"

namespace lancer {

Disk::Disk(const Vec3& center, const Vec3& normal, float radius, float innerRadius,
           const Material* material)
    : Shape(material),
      center_(center),
      normal_(normalize(normal)),
      radius_(radius),
      innerRadius_(innerRadius) {
    coordinateSystem(normal_, tangent_, bitangent_);
    if (dot(lancer::cross(tangent_, bitangent_), normal_) < 0) std::swap(tangent_, bitangent_);
}

std::unique_ptr<Shape> Disk::create(const Parameters& parameters, const Material* material) {
    const float radius = parameters.numberAbove("radius", 0, false);
    float innerRadius = 0;
    if (parameters.has("inner_radius")) {
        innerRadius = parameters.numberAbove("inner_radius", 0, true);
        if (!(innerRadius < radius))
            parameters.fail("inner_radius", "\"inner_radius\" must be less than \"radius\"");
    }
    return std::make_unique<Disk>(parameters.point("center"), parameters.direction("normal"),
                                  radius, innerRadius, material);
}

Bounds3 Disk::bounds() const {
    // Along each axis the rim reaches R sqrt(1 - n_axis^2) from the centre.
    Vec3 reach;
    for (int axis = 0; axis < 3; ++axis)
        reach[axis] = radius_ * std::sqrt(std::max(0.0f, 1 - normal_[axis] * normal_[axis]));
    const Bounds3 box(center_ - reach, center_ + reach);
    // The intersection works in double: the surface it finds may lie a few ulps outside.
    const Vec3 slack = gamma(3) * max(abs(box.min), abs(box.max)) + gamma(3) * reach;
    return {box.min - slack, box.max + slack};
}

std::optional<SurfaceCrossing> Disk::cross(const Ray& ray, float tMax) const {
    const std::optional<PlaneCrossing> crossing =
        PlaneCrossing::find(ray, Vec3d(center_), Vec3d(normal_), tMax);
    if (!crossing || !withinRing(*crossing)) return std::nullopt;
    return SurfaceCrossing{crossing->t, crossing->t};
}

std::optional<SurfaceCrossing> Disk::lineCrossing(const Ray& ray) const {
    const Vec3d c(center_), n(normal_);
    const std::optional<double> t = PlaneCrossing::lineParameter(ray, c, n);
    if (!t || !withinRing(PlaneCrossing::at(ray, c, n, *t))) return std::nullopt;
    return SurfaceCrossing{*t, *t};
}

bool Disk::withinRing(const PlaneCrossing& crossing) const {
    const double r2 = dot(crossing.offset, crossing.offset);
    const double R = radius_, Ri = innerRadius_;
    return r2 <= R * R && r2 >= Ri * Ri;
}

Hit Disk::record(const Ray& ray, const SurfaceCrossing& crossing) const {
    const Vec3d c(center_);
    const double t = crossing.tShape;
    const Vec3d q = PlaneCrossing::at(ray, c, Vec3d(normal_), t).offset;
    const double r2 = dot(q, q);
    const double R = radius_, Ri = innerRadius_;

    const double r = std::sqrt(r2);
    const double x = dot(q, Vec3d(tangent_)), y = dot(q, Vec3d(bitangent_));
    const Vec3 p(c + q);
    Hit hit = Hit::atRoundedPoint(t, p, normal_);
    hit.deferUv(this, Vec3(Vec3d(x, y, (R - r) / (R - Ri))));
    // p = c + r (cos phi t + sin phi b), phi = 2 pi u, r = R - (R - Ri) v; cos phi and sin phi
    // are x / r and y / r (phi = 0 at the centre).
    const auto cosPhi = r > 0 ? static_cast<float>(x / r) : 1.0f,
               sinPhi = r > 0 ? static_cast<float>(y / r) : 0.0f;
    const Vec3 radial = cosPhi * tangent_ + sinPhi * bitangent_;
    const Vec3 around = -sinPhi * tangent_ + cosPhi * bitangent_;
    hit.dpdu = (2 * kPi * static_cast<float>(r)) * around;
    hit.dpdv = -(radius_ - innerRadius_) * radial;
    hit.shape = this;
    hit.primitive = 0;
    hit.material = material();
    return hit;
}

Vec2 Disk::uvAt(const Vec3& local) const {
    return revolutionUv(local);
}

float Disk::area(std::uint32_t) const {
    return kPi * (radius_ * radius_ - innerRadius_ * innerRadius_);
}

Vec3 Disk::pointAt(float r, float phi) const {
    return center_ + r * (std::cos(phi) * tangent_ + std::sin(phi) * bitangent_);
}

std::optional<ShapeSample> Disk::sample(std::uint32_t primitive, const Vec2& u) const {
    // r^2 uniform between Ri^2 and R^2: uniform by area.
    const float r2 =
        innerRadius_ * innerRadius_ + u.x * (radius_ * radius_ - innerRadius_ * innerRadius_);
    return ShapeSample{pointAt(std::sqrt(r2), 2 * kPi * u.y), normal_, 1 / area(primitive)};
}

Tessellation Disk::tessellate(const TessellationRequest& request) const {
    const auto piecesFor = [&](float length) {
        return std::clamp(static_cast<int>(std::ceil(length / request.patchSize)), 1, 4096);
    };
    const int segments = std::max(16, piecesFor(2 * kPi * radius_));
    Tessellation tessellation;
    addFlatRings(
        center_, radius_, innerRadius_, segments, piecesFor(radius_ - innerRadius_),
        [&](int segment) {
            const float phi = 2 * kPi * static_cast<float>(segment) / static_cast<float>(segments);
            return std::cos(phi) * tangent_ + std::sin(phi) * bitangent_;
        },
        0, tessellation.facets);
    return tessellation;
}

}  // namespace lancer
