#include "materials/Material.h"

#include "materials/ConstantTexture.h"

namespace lancer {

Material::Material() : diffuse(std::make_shared<ConstantTexture>(Color(0.8f))), ambient(diffuse) {}

}  // namespace lancer
