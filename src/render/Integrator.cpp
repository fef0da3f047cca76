#include "render/Integrator.h"

#include <stdexcept>

#include "radiosity/RadiosityIntegrator.h"
#include "radiosity/RadiositySolver.h"
#include "render/PathIntegrator.h"
#include "render/WhittedIntegrator.h"
#include "scene/Scene.h"

namespace lancer {

std::unique_ptr<Integrator> Integrator::create(const Scene& scene) {
    const RenderSettings& settings = scene.settings();
    if (settings.integrator == "whitted")
        return std::make_unique<WhittedIntegrator>(scene, settings.maxDepth);
    if (settings.integrator == "path")
        return std::make_unique<PathIntegrator>(scene, settings.maxDepth);
    if (settings.integrator == "radiosity")
        return std::make_unique<RadiosityIntegrator>(
            scene, settings.maxDepth,
            std::make_shared<const RadiositySolution>(RadiositySolver(scene).solve()));
    throw std::invalid_argument("integrator \"" + settings.integrator + "\" is not available yet");
}

}  // namespace lancer
