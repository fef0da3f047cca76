#pragma once

#include <memory>
#include "render/Integrator.h"

namespace lancer {

class Scene;
struct IntegratorSetup;

// An integrator the scene's "integrator" key and --integrator can name.
struct IntegratorEntry {
    const char* name;
    const char* description;  // for --help and the documentation
    // Null when the setup stopped it (an interrupted radiosity solve).
    std::unique_ptr<Integrator> (*create)(const Scene& scene, const IntegratorSetup& setup);
};

}  // namespace lancer
