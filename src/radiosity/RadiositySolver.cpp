#include "radiosity/RadiositySolver.h"

#include <stdexcept>

#include "radiosity/RadiosityMethodRegistry.h"
#include "scene/Scene.h"

namespace lancer {

RadiositySolver::RadiositySolver(const Scene& scene) {
    const std::string& name = scene.settings().radiosity.method;
    const RadiosityMethodEntry* entry = RadiosityMethodRegistry::table().find(name);
    if (!entry) throw std::invalid_argument("unknown radiosity method \"" + name + "\"");
    method_ = entry->create(scene);
}

}  // namespace lancer
