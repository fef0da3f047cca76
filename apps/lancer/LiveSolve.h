#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <string>

#include "radiosity/RadiosityProgress.h"
#include "radiosity/RadiositySolution.h"

namespace lancer {

class RadiositySolver;
class Scene;
class Viewer;

// lancer --window during a radiosity solve: the solver runs on a thread of its own while the
// window stays responsive and shows the solve's progress in its title (phase, shots, unshot
// power left, time) and, about every quarter of a second, a coarse render (one ray per 4 x 4
// block) of the solution as it stands. Closing the window, Esc or `cancel` (Ctrl-C) stop it.
class LiveSolve {
public:
    // `threads` bounds the previews' render threads (0: all cores) as --threads does.
    LiveSolve(Viewer& viewer, const Scene& scene, RadiositySolver& solver, int threads);

    // Solves; nothing when stopped before the end.
    std::optional<RadiositySolution> run(const std::atomic<bool>& cancel);

private:
    // On the solving thread, between the solver's steps.
    void onProgress(const RadiosityProgress& progress);
    void showPreview();
    std::string describe() const;

    Viewer& viewer_;
    const Scene& scene_;
    RadiositySolver& solver_;
    int threads_;
    std::atomic<bool> stop_{false};
    std::chrono::steady_clock::time_point nextPreview_;  // the solving thread's

    mutable std::mutex mutex_;  // guards progress_
    std::optional<RadiosityProgress> progress_;
};

}  // namespace lancer
