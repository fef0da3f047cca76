#include "materials/BlinnPhongMaterial.h"

#include <utility>

#include "materials/BlinnPhongLobe.h"
#include "materials/Bsdf.h"
#include "materials/DielectricLobe.h"
#include "materials/LambertianLobe.h"
#include "materials/MirrorLobe.h"

namespace lancer {

BlinnPhongMaterial::BlinnPhongMaterial(Parameters parameters)
    : parameters_(std::move(parameters)) {}

void BlinnPhongMaterial::addLobes(const Hit& hit, Bsdf& bsdf) const {
    // In the order of the scene format's equation: Whitted's sums keep its rounding.
    bsdf.add<LambertianLobe>(diffuseReflectance(hit));
    bsdf.add<BlinnPhongLobe>(parameters_.specular, parameters_.shininess);
    bsdf.add<MirrorLobe>(parameters_.reflection);
    bsdf.add<DielectricLobe>(parameters_.transmission, parameters_.ior);
}

Color BlinnPhongMaterial::diffuseReflectance(const Hit& hit) const {
    return parameters_.diffuse->evaluate(hit);
}

bool BlinnPhongMaterial::reflectsDiffusely() const {
    return !parameters_.diffuse->isBlack();
}

Color BlinnPhongMaterial::ambientReflectance(const Hit& hit) const {
    return parameters_.ambient->evaluate(hit);
}

}  // namespace lancer
