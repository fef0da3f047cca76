#include "geometry/Plane.h"

#include <utility>
#include <vector>

#include "geometry/ConvexPolygon.h"
#include "geometry/PlaneCrossing.h"

namespace lancer {

Plane::Plane(const Vec3& point, const Vec3& normal, const Material* material)
    : Shape(material), point_(point), normal_(normalize(normal)) {
    // uv are world coordinates: (x, z) for a plane facing y, (x, y) facing z, (y, z) facing x.
    const int normalAxis = maxDimension(normal_);
    uAxis_ = normalAxis == 0 ? 1 : 0;
    vAxis_ = normalAxis == 2 ? 1 : 2;
    // Moving by one along the u axis, the point must also move along the normal's main axis to
    // stay on the plane; likewise for v.
    dpdu_[uAxis_] = 1;
    dpdu_[normalAxis] = -normal_[uAxis_] / normal_[normalAxis];
    dpdv_[vAxis_] = 1;
    dpdv_[normalAxis] = -normal_[vAxis_] / normal_[normalAxis];
}

std::unique_ptr<Shape> Plane::create(const Parameters& parameters, const Material* material) {
    return std::make_unique<Plane>(parameters.point("point"), parameters.direction("normal"),
                                   material);
}

Bounds3 Plane::bounds() const {
    return {Vec3(-kInfinity), Vec3(kInfinity)};
}

std::optional<SurfaceCrossing> Plane::cross(const Ray& ray, float tMax) const {
    const std::optional<PlaneCrossing> crossing =
        PlaneCrossing::find(ray, Vec3d(point_), Vec3d(normal_), tMax);
    if (!crossing) return std::nullopt;
    return SurfaceCrossing{crossing->t, crossing->t};
}

Hit Plane::record(const Ray& ray, const SurfaceCrossing& at) const {
    const Vec3d p0(point_);
    const PlaneCrossing crossing = PlaneCrossing::at(ray, p0, Vec3d(normal_), at.tShape);
    const double t = crossing.t;
    const Vec3 p(p0 + crossing.offset);

    Hit hit = Hit::atRoundedPoint(t, p, normal_);
    hit.dpdu = dpdu_;
    hit.dpdv = dpdv_;
    hit.setUv({p[uAxis_], p[vAxis_]});
    hit.shape = this;
    hit.primitive = 0;
    hit.material = material();
    return hit;
}

Tessellation Plane::tessellate(const TessellationRequest& request) const {
    const Bounds3& box = request.clipBox;
    // A square around the box's centre, large enough to cover the box, clipped to it.
    Vec3 a, b;
    coordinateSystem(normal_, a, b);
    const Vec3 centre = box.centroid();
    const Vec3 onPlane = centre - dot(centre - point_, normal_) * normal_;
    const float half = length(box.diagonal());
    std::vector<Vec3d> polygon;
    for (const auto& [s, t] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
        polygon.emplace_back(onPlane +
                             half * (static_cast<float>(s) * a + static_cast<float>(t) * b));
    for (int axis = 0; axis < 3 && !polygon.empty(); ++axis) {
        Vec3d n;
        n[axis] = 1;
        polygon = clipPolygon(polygon, n, box.min[axis]);
        if (!polygon.empty()) polygon = clipPolygon(polygon, -n, -box.max[axis]);
    }
    Tessellation tessellation;
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
        std::array<Vec3, 3> t{Vec3(polygon[0]), Vec3(polygon[i]), Vec3(polygon[i + 1])};
        // The plane's normal is its front.
        if (dot(lancer::cross(t[1] - t[0], t[2] - t[0]), normal_) < 0) std::swap(t[1], t[2]);
        tessellation.facets.push_back({t, 0});
    }
    return tessellation;
}

}  // namespace lancer
