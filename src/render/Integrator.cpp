#include "render/Integrator.h"

#include <stdexcept>

#include "render/WhittedIntegrator.h"
#include "scene/Scene.h"

namespace lancer {

std::unique_ptr<Integrator> Integrator::create(const Scene& scene) {
    const RenderSettings& settings = scene.settings();
    if (settings.integrator == "whitted")
        return std::make_unique<WhittedIntegrator>(scene, settings.maxDepth);
    throw std::invalid_argument("integrator \"" + settings.integrator + "\" is not available yet");
}

}  // namespace lancer
