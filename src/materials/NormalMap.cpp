#include "materials/NormalMap.h"

#include <utility>

#include "geometry/Hit.h"

namespace lancer {

NormalMap::NormalMap(std::shared_ptr<const Texture> texels) : texels_(std::move(texels)) {}

bool NormalMap::readsFootprint() const {
    return texels_->readsFootprint();
}

Vec3 NormalMap::normal(const Hit& hit) const {
    const Color c = texels_->evaluate(hit);
    const Vec3 tangentSpace(2 * c.r - 1, 2 * c.g - 1, 2 * c.b - 1);
    const Vec3& n = hit.ns;
    Vec3 t = hit.dpdu - n * dot(n, hit.dpdu);
    Vec3 b;
    if (lengthSquared(t) > 0) {
        t = normalize(t);
        b = cross(n, t);
        if (dot(b, hit.dpdv) < 0) b = -b;
    } else {
        // No u direction (a sphere's pole): any frame about n; the map's tilt there is arbitrary.
        coordinateSystem(n, t, b);
    }
    const Vec3 mapped = tangentSpace.x * t + tangentSpace.y * b + tangentSpace.z * n;
    return lengthSquared(mapped) > 0 ? normalize(mapped) : n;
}

}  // namespace lancer
