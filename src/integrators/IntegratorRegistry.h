#pragma once

#include <memory>

#include "integrators/IntegratorEntry.h"
#include "integrators/IntegratorSetup.h"
#include "render/Integrator.h"
#include "util/Registry.h"

namespace lancer {

class Scene;

// The integrators, by name: one registration line each.
class IntegratorRegistry {
public:
    static const Registry<IntegratorEntry>& table();

    // The integrator the scene's settings name, rendering that scene; null when the setup
    // stopped it. Throws std::invalid_argument for a name that is not in the table.
    static std::unique_ptr<Integrator> create(const Scene& scene,
                                              const IntegratorSetup& setup = {});
};

}  // namespace lancer
