#include "geometry/Quad.h"

#include "geometry/PlaneCrossing.h"

namespace lancer {

Quad::Quad(const Vec3& corner, const Vec3& edge1, const Vec3& edge2, const Material* material)
    : Shape(material), corner_(corner), edge1_(edge1), edge2_(edge2) {
    const Vec3d n = lancer::cross(Vec3d(edge1), Vec3d(edge2));
    normal_ = Vec3(normalize(n));
    area_ = static_cast<float>(length(n));
}

Bounds3 Quad::bounds() const {
    const Bounds3 box = merge(merge(Bounds3(corner_, corner_ + edge1_), corner_ + edge2_),
                              corner_ + edge1_ + edge2_);
    // The corners were rounded to float; the surface the intersection finds (in double) may
    // reach a few ulps beyond them.
    const Vec3 slack = gamma(3) * max(abs(box.min), abs(box.max));
    return {box.min - slack, box.max + slack};
}

std::optional<SurfaceCrossing> Quad::cross(const Ray& ray, float tMax) const {
    // In double precision (PlaneCrossing), and so are the edge tests: they must not let rays slip
    // between two quads sharing an edge.
    const Vec3d e1(edge1_), e2(edge2_);
    const Vec3d n = lancer::cross(e1, e2);
    const std::optional<PlaneCrossing> crossing = PlaneCrossing::find(ray, Vec3d(corner_), n, tMax);
    if (!crossing) return std::nullopt;
    // The point's coordinates along the edges: q = u e1 + v e2 gives q x e2 = u n, e1 x q = v n.
    const Vec3d& q = crossing->offset;
    const double nn = dot(n, n);
    const double u = dot(lancer::cross(q, e2), n) / nn;
    const double v = dot(lancer::cross(e1, q), n) / nn;
    if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1)) return std::nullopt;
    return SurfaceCrossing{crossing->t, crossing->t, 0, static_cast<float>(u),
                           static_cast<float>(v)};
}

Hit Quad::record(const Ray& ray, const SurfaceCrossing& crossing) const {
    const Vec3d c(corner_);
    const double t = crossing.tShape;
    const Vec3 p(c +
                 PlaneCrossing::at(ray, c, lancer::cross(Vec3d(edge1_), Vec3d(edge2_)), t).offset);
    Hit hit = Hit::atRoundedPoint(t, p, normal_);
    hit.dpdu = edge1_;
    hit.dpdv = edge2_;
    hit.setUv({crossing.b0, crossing.b1});
    hit.shape = this;
    hit.primitive = 0;
    hit.material = material();
    return hit;
}

std::optional<ShapeSample> Quad::sample(std::uint32_t, const Vec2& u) const {
    return ShapeSample{pointAt(u), normal_, 1 / area_};
}

Tessellation Quad::tessellate(const TessellationRequest&) const {
    const Vec3 a = corner_, b = a + edge1_, c = b + edge2_, d = a + edge2_;
    Tessellation tessellation;
    tessellation.facets = {{{a, b, c}, 0}, {{a, c, d}, 0}};
    return tessellation;
}

}  // namespace lancer
