#pragma once

#include <memory>

#include "radiosity/RadiosityMethod.h"

namespace lancer {

class Scene;

// Solves a scene's radiosity by the method its "radiosity" settings name
// (RadiosityMethodRegistry): what the renderer and the live window use.
class RadiositySolver {
public:
    // Throws std::invalid_argument for a method that is not in the registry (the scene loader
    // refuses those first).
    explicit RadiositySolver(const Scene& scene);

    std::uint64_t fingerprint() const { return method_->fingerprint(); }
    RadiositySolution solve() { return *method_->solve({}, nullptr); }
    std::optional<RadiositySolution> solve(
        const std::function<void(const RadiosityProgress&)>& onProgress,
        const std::atomic<bool>* cancel) {
        return method_->solve(onProgress, cancel);
    }
    RadiositySolution snapshot() const { return method_->snapshot(); }

private:
    std::unique_ptr<RadiosityMethod> method_;
};

}  // namespace lancer
