#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <thread>

#include "render/Renderer.h"
#include "scene/CameraOrbit.h"

namespace lancer {

class Integrator;
class Scene;
class Viewer;

// lancer --window: renders a scene in the background while a Viewer shows it (coarse passes
// first, then the tiles as they finish, progress and ETA in the title), and lets the user look
// around: dragging orbits the camera around its look_at point, the wheel moves it nearer or
// farther, and either starts the view's render again at once. S saves what the window shows
// next to the output as NAME-snapshot-N.EXT.
class LiveRender {
public:
    // `options` as for a render without a window; options.cancel (Ctrl-C) acts as closing the
    // window. `output` names the snapshots.
    LiveRender(Viewer& viewer, Scene& scene, const Integrator& integrator,
               const RenderOptions& options, std::filesystem::path output, bool quiet);
    ~LiveRender();  // stops the render if one still runs
    LiveRender(const LiveRender&) = delete;
    LiveRender& operator=(const LiveRender&) = delete;

    // Runs until the window is closed. The first render that completes (the scene's camera,
    // unless the user moved it before) goes to `deliver` at once, and the window stays open; if
    // the window is closed before, the unfinished render goes to `deliver` then (which may
    // change it: the window keeps its own copy). `deliver` is told whether the render is of the
    // scene's own camera (not moved by the user), and so may be resumed. Returns what `deliver`
    // returned.
    int run(const std::function<int(RenderResult&, bool sceneCamera)>& deliver);

private:
    // Starts rendering the scene's camera in the background.
    void start();
    // Stops the background render (at once if unfinished) and returns what it did.
    RenderResult stop();
    void saveSnapshot();

    Viewer& viewer_;
    Scene& scene_;
    const Integrator& integrator_;
    RenderOptions options_;
    std::filesystem::path output_;
    bool quiet_;
    CameraOrbit orbit_;
    int snapshotCount_ = 0;
    std::optional<int> status_;  // what deliver returned, once it was called
    bool moved_ = false;         // the user has moved the camera

    std::thread thread_;
    std::atomic<bool> cancel_{false};
    std::atomic<bool> finished_{false};
    std::optional<RenderResult> result_;  // the render thread's, read once it is joined
    std::chrono::steady_clock::time_point started_;
};

}  // namespace lancer
