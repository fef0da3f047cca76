#include "materials/BumpMap.h"

#include <cmath>
#include <utility>

#include "geometry/Hit.h"

namespace lancer {

namespace {

// The uv step without a footprint (the path tracer's hits): pbrt's, a fraction of a texel of
// maps up to 2000 texels wide, so the difference follows the filtered heights closely.
constexpr float kStepWithoutFootprint = 0.0005f;

float step(float dx, float dy) {
    const float half = 0.5f * (std::abs(dx) + std::abs(dy));
    return half > 0 ? half : kStepWithoutFootprint;
}

}  // namespace

BumpMap::BumpMap(std::shared_ptr<const Texture> heights, float scale)
    : heights_(std::move(heights)), scale_(scale) {}

float BumpMap::height(const Hit& hit, float u, float v) const {
    Hit shifted = hit;
    shifted.setUv(Vec2(u, v));
    return heights_->evaluate(shifted).r;
}

Vec3 BumpMap::normal(const Hit& hit) const {
    const Vec3& n = hit.ns;
    // The bump leaves the normal's component along n as cross(dpdu, dpdv) has it, so the side of
    // n follows from the orientation of uv alone; without one (a pole), there is nothing to bump.
    const float orientation = dot(cross(hit.dpdu, hit.dpdv), n);
    if (!(orientation != 0)) return n;
    const float du = step(hit.dudx, hit.dudy), dv = step(hit.dvdx, hit.dvdy);
    const Vec2 uv = hit.uv();
    const float u = uv.x, v = uv.y;
    const float dhdu = scale_ * (height(hit, u + du, v) - height(hit, u - du, v)) / (2 * du);
    const float dhdv = scale_ * (height(hit, u, v + dv) - height(hit, u, v - dv)) / (2 * dv);
    const Vec3 bumped = cross(hit.dpdu + dhdu * n, hit.dpdv + dhdv * n);
    return orientation < 0 ? -normalize(bumped) : normalize(bumped);
}

}  // namespace lancer
