#include "lights/QuadLight.h"

#include "geometry/Hit.h"
#include "math/Float.h"

namespace lancer {

QuadLight::QuadLight(const Quad& surface, const Color& radiance)
    : surface_(surface), radiance_(radiance) {}

LightSample QuadLight::sample(const Vec3& p, const Vec2& u) const {
    LightSample s;
    s.position = surface_.pointAt(u);
    const Vec3 toLight = s.position - p;
    const float distanceSquared = lengthSquared(toLight);
    if (!(distanceSquared > 0)) return s;  // p on the light itself: no direction, no light
    s.wi = toLight / std::sqrt(distanceSquared);
    const float cosLight = -dot(surface_.normal(), s.wi);
    s.pdf = areaToSolidAngleDensity(surface_.area(), distanceSquared, cosLight);
    // One-sided: a point behind the quad's plane sees its dark back.
    if (cosLight > 0 && s.pdf > 0) s.irradiance = radiance_ / s.pdf;
    return s;
}

float QuadLight::pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const {
    return areaToSolidAngleDensity(surface_.area(), lengthSquared(onLight.p - p),
                                   dot(surface_.normal(), wi));
}

// Every point of a Lambertian emitter sends pi L per unit area, from one side.
Color QuadLight::power(float) const {
    return kPi * surface_.area() * radiance_;
}

}  // namespace lancer
