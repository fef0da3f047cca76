#include "integrators/IntegratorRegistry.h"

#include <stdexcept>

#include "integrators/PathIntegrator.h"
#include "integrators/RadiosityIntegrator.h"
#include "integrators/WhittedIntegrator.h"
#include "scene/Scene.h"
#include "util/DidYouMean.h"

namespace lancer {

const Registry<IntegratorEntry>& IntegratorRegistry::table() {
    static const Registry<IntegratorEntry> integrators{
        {"whitted", "Whitted ray tracing with Blinn-Phong shading", &WhittedIntegrator::create},
        {"path", "path tracing with next-event estimation and MIS", &PathIntegrator::create},
        {"radiosity", "classic radiosity, shown through the ray tracer",
         &RadiosityIntegrator::create},
    };
    return integrators;
}

std::unique_ptr<Integrator> IntegratorRegistry::create(const Scene& scene,
                                                       const IntegratorSetup& setup) {
    const std::string& name = scene.settings().integrator;
    const IntegratorEntry* entry = table().find(name);
    if (!entry) throw std::invalid_argument(unknownName("integrator", name, table().names()));
    return entry->create(scene, setup);
}

}  // namespace lancer
