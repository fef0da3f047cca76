#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>

#include "radiosity/RadiosityProgress.h"
#include "radiosity/RadiositySolution.h"

namespace lancer {

// A way of solving the radiosity equation over a scene's diffuse surfaces (the scene's
// "radiosity" "method"): RadiositySolver runs the one the scene names.
class RadiosityMethod {
public:
    virtual ~RadiosityMethod() = default;

    // A hash of what the solution depends on (the surfaces, the lights, the settings, the
    // method). Saved solutions are checked against it.
    virtual std::uint64_t fingerprint() const = 0;

    // The solve, reporting to `onProgress` (if any) on the solving thread between its steps; the
    // solution is the same with or without it (it may call snapshot(), which changes nothing).
    // Once `cancel` (if any) is set, the solve stops soon and returns nothing; the method is then
    // not to be used again.
    virtual std::optional<RadiositySolution> solve(
        const std::function<void(const RadiosityProgress&)>& onProgress,
        const std::atomic<bool>* cancel) = 0;

    // The solution as it stands, for a preview during the solve (from onProgress).
    virtual RadiositySolution snapshot() const = 0;
};

}  // namespace lancer
