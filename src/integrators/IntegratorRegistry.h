#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "radiosity/RadiositySolution.h"
#include "render/Integrator.h"
#include "util/Registry.h"

namespace lancer {

class RadiositySolver;
class Scene;

// What an integrator may need from the program beyond the scene.
struct IntegratorSetup {
    // Gives the radiosity integrator its solution, from the solver made for the scene: solved
    // (with progress shown, and stoppable), or loaded from a file. Nothing: stopped before the
    // end. When empty, the solver solves without reporting.
    std::function<std::optional<RadiositySolution>(RadiositySolver&)> radiositySolution;
};

// An integrator the scene's "integrator" key and --integrator can name.
struct IntegratorEntry {
    const char* name;
    const char* description;  // for --help and the documentation
    // Null when the setup stopped it (an interrupted radiosity solve).
    std::unique_ptr<Integrator> (*create)(const Scene& scene, const IntegratorSetup& setup);
};

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
