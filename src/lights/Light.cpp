#include "lights/Light.h"

namespace lancer {

float Light::pdf(const Vec3&, const Vec3&, const Hit&) const {
    return 0;
}

}  // namespace lancer
