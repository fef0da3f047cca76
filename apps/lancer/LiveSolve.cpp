#include "LiveSolve.h"

#include "ProgressBar.h"

#include <cstdio>
#include <exception>
#include <memory>
#include <thread>

#include "Viewer.h"
#include "integrators/RadiosityIntegrator.h"
#include "radiosity/RadiositySolver.h"
#include "render/Renderer.h"
#include "scene/Scene.h"

namespace lancer {

namespace {

// How often the window shows the solution as it stands; each preview costs one ray per 4 x 4
// block, and the next one waits this long after it ends, so the previews take at most about
// half of the solve's time even when they are slow.
constexpr std::chrono::milliseconds kPreviewInterval{250};
constexpr int kPreviewBlockSize = 4;
// How long the window waits for the user before updating the title.
constexpr std::chrono::milliseconds kFrameTime{16};

}  // namespace

LiveSolve::LiveSolve(Viewer& viewer, const Scene& scene, RadiositySolver& solver, int threads)
    : viewer_(viewer), scene_(scene), solver_(solver), threads_(threads) {}

std::optional<RadiositySolution> LiveSolve::run(const std::atomic<bool>& cancel) {
    const auto start = std::chrono::steady_clock::now();
    nextPreview_ = start;
    std::optional<RadiositySolution> solution;
    std::atomic<bool> finished{false};
    std::exception_ptr failure;  // what the solve threw, thrown again here
    std::thread solving([&] {
        try {
            solution = solver_.solve([this](const RadiosityProgress& p) { onProgress(p); }, &stop_);
        } catch (...) {
            failure = std::current_exception();
        }
        finished = true;
    });
    while (!finished) {
        for (const ViewerEvent& event : viewer_.poll(kFrameTime))
            if (event.kind == ViewerEvent::Kind::Close) stop_ = true;
        if (cancel) stop_ = true;
        // The solver reports between shots only: the time goes on in between.
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        char time[32];
        std::snprintf(time, sizeof time, "  %.1f s", elapsed.count());
        viewer_.setStatus(describe() + time);
    }
    solving.join();
    if (failure) std::rethrow_exception(failure);
    return stop_ ? std::nullopt : std::move(solution);
}

void LiveSolve::onProgress(const RadiosityProgress& progress) {
    {
        std::lock_guard lock(mutex_);
        progress_ = progress;
    }
    if (std::chrono::steady_clock::now() < nextPreview_) return;
    showPreview();
    nextPreview_ = std::chrono::steady_clock::now() + kPreviewInterval;
}

void LiveSolve::showPreview() {
    const RadiosityIntegrator integrator(
        scene_, scene_.settings().maxDepth,
        std::make_shared<const RadiositySolution>(solver_.snapshot()));
    RenderOptions options;
    options.threads = threads_;
    options.cancel = &stop_;
    options.previewBlockSizes = {kPreviewBlockSize};
    options.previewOnly = true;
    options.onTileDone = [this](const FinishedTile& tile) {
        viewer_.showTile(tile.film, tile.tile);
    };
    Renderer(scene_, integrator).render(options);
}

std::string LiveSolve::describe() const {
    std::lock_guard lock(mutex_);
    if (!progress_) return "radiosity: preparing";
    return ProgressBar::describe(*progress_);
}

}  // namespace lancer
