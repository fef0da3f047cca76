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

std::unique_ptr<Material> BlinnPhongMaterial::create(const MaterialParameters& keys) {
    Parameters m;
    if (keys.has("diffuse")) m.diffuse = keys.texture("diffuse");
    m.ambient = keys.has("ambient") ? keys.texture("ambient") : m.diffuse;
    if (keys.has("specular")) m.specular = keys.color("specular");
    if (keys.has("shininess")) m.shininess = keys.numberAbove("shininess", 0, true);
    if (keys.has("reflection")) m.reflection = keys.color("reflection");
    if (keys.has("transmission")) m.transmission = keys.color("transmission");
    if (keys.has("ior")) m.ior = keys.numberAbove("ior", 0, false);
    if (keys.has("emission")) m.emission = keys.color("emission");
    return std::make_unique<BlinnPhongMaterial>(std::move(m));
}

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
