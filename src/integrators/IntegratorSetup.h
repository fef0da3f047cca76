#pragma once

#include <functional>
#include <optional>
#include "radiosity/RadiositySolution.h"

namespace lancer {

class RadiositySolver;

// What an integrator may need from the program beyond the scene.
struct IntegratorSetup {
    // Gives the radiosity integrator its solution, from the solver made for the scene: solved
    // (with progress shown, and stoppable), or loaded from a file. Nothing: stopped before the
    // end. When empty, the solver solves without reporting.
    std::function<std::optional<RadiositySolution>(RadiositySolver&)> radiositySolution;
};

}  // namespace lancer
