#include "lights/Light.h"

#include <cmath>

namespace lancer {

float Light::pdf(const Vec3&, const Vec3&, const Hit&) const {
    return 0;
}

float Light::areaToSolidAngleDensity(float area, float distanceSquared, float cosLight) {
    const float projectedArea = area * std::abs(cosLight);
    return projectedArea > 0 ? distanceSquared / projectedArea : 0;
}

}  // namespace lancer
