#include "materials/BlinnPhongMaterial.h"

#include <algorithm>
#include <utility>

#include "materials/BlinnPhongLobe.h"
#include "materials/Bsdf.h"
#include "materials/ConductorLobe.h"
#include "materials/DielectricLobe.h"
#include "materials/LambertianLobe.h"
#include "materials/MirrorLobe.h"
#include "materials/RoughConductorLobe.h"
#include "materials/RoughDielectricLobe.h"
#include "math/Float.h"

namespace lancer {

BlinnPhongMaterial::BlinnPhongMaterial(Parameters parameters) : parameters_(std::move(parameters)) {
    const Parameters& p = parameters_;
    bool read = false;
    for (const auto& texture :
         {p.diffuse, p.ambient, p.specularMap, p.reflectionMap, p.roughnessMap, p.emissionMap})
        read = read || (texture && texture->readsFootprint());
    setTexturesReadFootprint(read);
}

// The RGB complex indices of refraction that Mitsuba 3.9.1 (scalar_rgb) makes from its measured
// spectra (resources/data/ior, after Palik's handbook), integrated against the CIE 1931 matching
// functions into linear sRGB; tests/cli/data/rough/metal_table.py prints them.
const std::vector<BlinnPhongMaterial::Metal>& BlinnPhongMaterial::metals() {
    static const std::vector<Metal> table{
        {"gold", {{0.1430f, 0.3753f, 1.4420f}, {3.9830f, 2.3856f, 1.6034f}}},
        {"silver", {{0.1553f, 0.1167f, 0.1384f}, {4.8284f, 3.1222f, 2.1469f}}},
        {"copper", {{0.2010f, 0.9237f, 1.1022f}, {3.9133f, 2.4530f, 2.1421f}}},
        {"aluminium", {{1.6575f, 0.8804f, 0.5212f}, {9.2238f, 6.2695f, 4.8370f}}},
        {"chromium", {{4.3697f, 2.9165f, 1.6549f}, {5.2065f, 4.2313f, 3.7547f}}},
    };
    return table;
}

namespace {

// The conductor's index of `metal` or `conductor`, if the material has one.
std::optional<ConductorIor> readConductor(const MaterialParameters& keys) {
    if (keys.has("metal") && keys.has("conductor"))
        keys.fail("conductor", "\"metal\" and \"conductor\" together: give one of them");
    if (keys.has("metal")) {
        const auto& metals = BlinnPhongMaterial::metals();
        std::vector<std::string> names;
        for (const auto& metal : metals)
            names.emplace_back(metal.name);
        return metals[keys.choice("metal", names)].ior;
    }
    if (!keys.has("conductor")) return std::nullopt;
    const std::unique_ptr<Parameters> ior = keys.object("conductor", {"eta", "k"});
    ConductorIor conductor{ior->color("eta"), ior->color("k")};
    const float smallestEta = std::min(conductor.eta.r, std::min(conductor.eta.g, conductor.eta.b));
    if (!(smallestEta > 0)) ior->fail("eta", "\"eta\" must be greater than 0 in every channel");
    return conductor;
}

// A colour key that may be a texture: a colour is the factor, a texture the map (factor 1).
void readFactorOrMap(const MaterialParameters& keys, const std::string& key, Color& factor,
                     std::shared_ptr<const Texture>& map) {
    if (!keys.has(key)) return;
    if (keys.isTexture(key)) {
        factor = Color(1);
        map = keys.texture(key);
    } else {
        factor = keys.color(key);
    }
}

// The factor times the map at the hit, if there is one.
Color atHit(const Color& factor, const std::shared_ptr<const Texture>& map, const Hit& hit) {
    return map ? factor * map->evaluate(hit) : factor;
}

}  // namespace

std::unique_ptr<Material> BlinnPhongMaterial::create(const MaterialParameters& keys) {
    Parameters m;
    m.conductor = readConductor(keys);
    if (m.conductor) {
        m.diffuse = std::make_shared<ConstantTexture>(Color(0));
        m.reflection = Color(1);
    }
    if (keys.has("diffuse")) m.diffuse = keys.texture("diffuse");
    m.ambient = keys.has("ambient") ? keys.texture("ambient") : m.diffuse;
    readFactorOrMap(keys, "specular", m.specular, m.specularMap);
    if (keys.has("shininess")) m.shininess = keys.numberAbove("shininess", 0, true);
    readFactorOrMap(keys, "reflection", m.reflection, m.reflectionMap);
    if (keys.has("transmission")) m.transmission = keys.color("transmission");
    if (keys.has("ior")) m.ior = keys.numberAbove("ior", 0, false);
    readFactorOrMap(keys, "emission", m.emission, m.emissionMap);
    if (keys.has("roughness") && keys.isTexture("roughness")) {
        m.roughness = 1;
        m.roughnessMap = keys.dataTexture("roughness");
    } else if (keys.has("roughness")) {
        m.roughness = keys.numberAbove("roughness", 0, true);
        if (m.roughness > 1) keys.fail("roughness", "\"roughness\" must be at most 1");
    }
    return std::make_unique<BlinnPhongMaterial>(std::move(m));
}

void BlinnPhongMaterial::addLobes(const Hit& hit, Bsdf& bsdf) const {
    // In the order of the scene format's equation: Whitted's sums keep its rounding.
    bsdf.add<LambertianLobe>(diffuseReflectance(hit));
    bsdf.add<BlinnPhongLobe>(atHit(parameters_.specular, parameters_.specularMap, hit),
                             parameters_.shininess);
    const Color reflection = atHit(parameters_.reflection, parameters_.reflectionMap, hit);
    const float alpha =
        parameters_.roughnessMap
            ? clamp(parameters_.roughness * parameters_.roughnessMap->evaluate(hit).average(), 0.0f,
                    1.0f)
            : parameters_.roughness;
    if (alpha > 0) {
        bsdf.add<RoughConductorLobe>(reflection, alpha, parameters_.conductor);
        bsdf.add<RoughDielectricLobe>(parameters_.transmission, parameters_.ior, alpha);
        return;
    }
    if (parameters_.conductor)
        bsdf.add<ConductorLobe>(reflection, *parameters_.conductor);
    else
        bsdf.add<MirrorLobe>(reflection);
    bsdf.add<DielectricLobe>(parameters_.transmission, parameters_.ior);
}

Color BlinnPhongMaterial::emission(const Hit& hit) const {
    return atHit(parameters_.emission, parameters_.emissionMap, hit);
}

Color BlinnPhongMaterial::emission() const {
    return parameters_.emissionMap ? parameters_.emission * parameters_.emissionMap->average()
                                   : parameters_.emission;
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
