#include "radiosity/SurfaceProbe.h"

#include "geometry/Shape.h"
#include "materials/Bsdf.h"
#include "materials/Material.h"
#include "radiosity/TriangleQuadrature.h"

namespace lancer {

std::optional<Hit> SurfaceProbe::at(const Patch& patch, const Vec3& point) {
    const Ray ray{point + patch.probeDistance * patch.normal, -patch.normal};
    std::optional<Hit> hit = patch.surface->intersect(ray, 2 * patch.probeDistance);
    if (hit && !hit->material) hit->material = patch.material;
    return hit;
}

Vec3 SurfaceProbe::onSurface(const Patch& patch, const Vec3& point) {
    if (!patch.curved) return point;
    const std::optional<Hit> hit = at(patch, point);
    return hit ? hit->p : point;
}

void SurfaceProbe::place(const Patch& patch, const std::array<Vec3, 3>& corners, Element& element) {
    element.reflectance = reflectance(patch, corners);
    if (!patch.curved) return;
    if (const std::optional<Hit> hit = at(patch, element.centroid)) {
        element.surfacePoint = hit->p;
        element.surfaceNormal = hit->ng;
    }
}

template <typename OfHit>
Color SurfaceProbe::average(const Patch& patch, const std::array<Vec3, 3>& corners, OfHit ofHit) {
    const std::array<Vec3, 3> quadrature = triangleQuadraturePoints(corners);
    const std::array<Vec3, 4> points{(corners[0] + corners[1] + corners[2]) / 3.0f, quadrature[0],
                                     quadrature[1], quadrature[2]};
    Color sum;
    for (const Vec3& p : points) {
        std::optional<Hit> hit = at(patch, p);
        if (!hit) {
            hit.emplace();  // uv (0, 0): only textures see the difference
            hit->p = p;
            hit->material = patch.material;
        }
        // A cut-away point reflects and emits nothing: the share of the surface that is there.
        if (!hit->material->isCutAway(*hit)) sum += ofHit(*hit);
    }
    return sum / 4.0f;
}

Color SurfaceProbe::reflectance(const Patch& patch, const std::array<Vec3, 3>& corners) {
    // kd as the radiosity integrator shades with it: scaled with the other lobes, as the path
    // tracer scales them, where they sum to more than 1.
    return average(patch, corners, [&](const Hit& hit) {
        return Bsdf(*hit.material, hit, patch.normal, Bsdf::Weights::EnergyConserving)
            .diffuseReflectance();
    });
}

Color SurfaceProbe::emission(const Patch& patch, const std::array<Vec3, 3>& corners) {
    return average(patch, corners, [](const Hit& hit) { return hit.material->emission(hit); });
}

}  // namespace lancer
