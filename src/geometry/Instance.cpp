#include "geometry/Instance.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lancer {

Instance::Instance(std::shared_ptr<const Shape> shape, const Transform& objectToWorld,
                   const Material* materialOverride)
    : Shape(materialOverride),
      shape_(std::move(shape)),
      objectToWorld_(objectToWorld),
      worldToObject_(objectToWorld.inverse()) {
    const auto& m = objectToWorld.matrix();
    determinant_ = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                   m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                   m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    flipsOrientation_ = determinant_ < 0;
    identity_ = objectToWorld.isIdentity();
}

const Material* Instance::primitiveMaterial(std::uint32_t primitive) const {
    return material() ? material() : shape_->primitiveMaterial(primitive);
}

Bounds3 Instance::bounds() const {
    return objectToWorld_.applyBounds(shape_->bounds());
}

Ray Instance::toObject(const Ray& ray, float& shift) const {
    shift = 0;
    if (identity_) return ray;
    // The transformed origin carries rounding error; moving it forward to the edge of that error
    // along the ray keeps it from starting behind the surface it left (pbrt 6.8.6). The ray's
    // parameter is unchanged by an affine map, up to this shift.
    Vec3 originError;
    Vec3 origin = worldToObject_.applyPoint(ray.origin, Vec3(0), originError);
    const Vec3 direction = worldToObject_.applyVector(ray.direction);
    if (const float lengthSq = lengthSquared(direction); lengthSq > 0) {
        shift = dot(abs(direction), originError) / lengthSq;
        origin += direction * shift;
    }
    return {origin, direction};
}

bool Instance::occluded(const Ray& ray, float tMax) const {
    float shift;
    const Ray local = toObject(ray, shift);
    return shape_->occluded(local, tMax - shift);
}

std::optional<SurfaceCrossing> Instance::cross(const Ray& ray, float tMax) const {
    float shift;
    const Ray local = toObject(ray, shift);
    std::optional<SurfaceCrossing> crossing = shape_->cross(local, tMax - shift);
    // In float, as the record's t is (record() adds the same shift to it).
    if (crossing) crossing->t = static_cast<float>(crossing->t) + shift;
    return crossing;
}

void Instance::crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const {
    float shift;
    const Ray local = toObject(ray, shift);
    const std::size_t first = crossings.size();
    shape_->crossSegment(local, tMax - shift, crossings);
    // In float, as cross() gives it.
    for (std::size_t i = first; i < crossings.size(); ++i)
        crossings[i].t = static_cast<float>(crossings[i].t) + shift;
}

void Instance::crossLine(const Ray& ray, LineCrossings& crossings) const {
    float shift;
    const Ray local = toObject(ray, shift);
    const std::size_t first = crossings.size();
    shape_->crossLine(local, crossings);
    for (std::size_t i = first; i < crossings.size(); ++i) {
        double& t = crossings[i].crossing.t;
        t = static_cast<float>(t) + shift;
    }
}

Hit Instance::record(const Ray& ray, const SurfaceCrossing& crossing) const {
    float shift;
    const Ray local = toObject(ray, shift);
    Hit hit = shape_->record(local, crossing);
    if (material()) hit.material = material();
    hit.shape = this;
    if (identity_) return hit;

    hit.t += shift;
    Vec3 pError;
    hit.p = objectToWorld_.applyPoint(hit.p, hit.pError, pError);
    hit.pError = pError;
    hit.ng = normalize(objectToWorld_.applyNormal(hit.ng));
    hit.ns = normalize(objectToWorld_.applyNormal(hit.ns));
    hit.dpdu = objectToWorld_.applyVector(hit.dpdu);
    hit.dpdv = objectToWorld_.applyVector(hit.dpdv);
    return hit;
}

float Instance::areaStretch(const Vec3& n) const {
    // An area element with normal n becomes |det M| |M^-T n| times as large.
    return std::abs(determinant_) * length(objectToWorld_.applyNormal(n));
}

float Instance::largestStretch() const {
    float stretch = 0;
    for (int axis = 0; axis < 3; ++axis) {
        Vec3 unit;
        unit[axis] = 1;
        stretch = std::max(stretch, length(objectToWorld_.applyVector(unit)));
    }
    return stretch;
}

float Instance::area(std::uint32_t primitive) const {
    const std::optional<ShapeSample> s = shape_->sample(primitive, Vec2(0.5f, 0.5f));
    return s ? shape_->area(primitive) * areaStretch(s->n) : shape_->area(primitive);
}

std::optional<ShapeSample> Instance::sample(std::uint32_t primitive, const Vec2& u) const {
    std::optional<ShapeSample> s = shape_->sample(primitive, u);
    if (!s) return std::nullopt;
    s->pdf /= areaStretch(s->n);
    s->p = objectToWorld_.applyPoint(s->p);
    s->n = normalize(objectToWorld_.applyNormal(s->n));
    return s;
}

float Instance::areaPdf(std::uint32_t primitive, const Hit& onSurface) const {
    const Vec3 n = normalize(worldToObject_.applyNormal(onSurface.ng));
    Hit local = onSurface;
    local.p = worldToObject_.applyPoint(onSurface.p);
    local.ng = n;
    return shape_->areaPdf(primitive, local) / areaStretch(n);
}

Tessellation Instance::tessellate(const TessellationRequest& request) const {
    const float stretch = largestStretch();
    const Bounds3 clipBox = worldToObject_.applyBounds(request.clipBox);
    Tessellation tessellation = shape_->tessellate({request.patchSize / stretch, clipBox});
    tessellation.probeDistance *= stretch;
    for (Tessellation::Facet& facet : tessellation.facets) {
        for (Vec3& p : facet.corners)
            p = objectToWorld_.applyPoint(p);
        // Keep the front on the side the transformed normal is.
        if (flipsOrientation_) std::swap(facet.corners[1], facet.corners[2]);
    }
    return tessellation;
}

}  // namespace lancer
