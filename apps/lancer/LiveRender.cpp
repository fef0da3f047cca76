#include "LiveRender.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "ProgressBar.h"
#include "Viewer.h"
#include "io/ImageWriter.h"
#include "math/Float.h"
#include "scene/Scene.h"

namespace lancer {

namespace {

// The coarse passes: blocks of 8 x 8 pixels, then 2 x 2; together about a quarter of a ray
// per pixel.
const std::vector<int> kPreviewBlockSizes{8, 2};
// Dragging across the whole window turns the camera half a turn around look_at, or tilts it a
// quarter of a turn; a notch of the wheel moves it 10% nearer or farther.
constexpr float kYawPerWidth = kPi, kPitchPerHeight = kPi / 2, kZoomPerStep = 0.9f;
// How long the window waits for the user before drawing what the renderer did meanwhile.
constexpr std::chrono::milliseconds kFrameTime{16};

}  // namespace

LiveRender::LiveRender(Viewer& viewer, Scene& scene, const Integrator& integrator,
                       const RenderOptions& options, std::filesystem::path output, bool quiet)
    : viewer_(viewer),
      scene_(scene),
      integrator_(integrator),
      options_(options),
      output_(std::move(output)),
      quiet_(quiet),
      orbit_(scene.camera()) {}

LiveRender::~LiveRender() {
    if (thread_.joinable()) stop();
}

void LiveRender::start() {
    RenderOptions options = options_;
    // Only the render that goes to the output writes auxiliary outputs; the views after it
    // would compute them for nothing. A resumed render is of the scene's camera only (the views
    // after the first render are all of a moved camera).
    if (status_) options.aovs.clear();
    if (moved_) options.resumeFrom = nullptr;
    options.cancel = &cancel_;
    options.previewBlockSizes = kPreviewBlockSizes;
    options.onTileDone = [this](const FinishedTile& tile) {
        viewer_.showTile(tile.film, tile.tile);
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - started_;
        viewer_.setStatus(ProgressBar::describe(tile.tilesDone, tile.tilesTotal, elapsed.count()));
    };
    cancel_ = false;
    finished_ = false;
    started_ = std::chrono::steady_clock::now();
    thread_ = std::thread([this, options] {
        result_.emplace(Renderer(scene_, integrator_).render(options));
        finished_ = true;
    });
}

RenderResult LiveRender::stop() {
    cancel_ = true;
    thread_.join();
    RenderResult result = std::move(*result_);
    result_.reset();
    return result;
}

int LiveRender::run(const std::function<int(RenderResult&, bool)>& deliver) {
    start();
    for (;;) {
        bool close = options_.cancel && options_.cancel->load();
        bool moved = false;
        for (const ViewerEvent& event : viewer_.poll(kFrameTime)) {
            switch (event.kind) {
                case ViewerEvent::Kind::Close:
                    close = true;
                    break;
                case ViewerEvent::Kind::Save:
                    saveSnapshot();
                    break;
                case ViewerEvent::Kind::Drag:
                    orbit_.rotate(-event.dx * kYawPerWidth, event.dy * kPitchPerHeight);
                    moved = true;
                    break;
                case ViewerEvent::Kind::Zoom:
                    orbit_.zoom(std::pow(kZoomPerStep, static_cast<float>(event.steps)));
                    moved = true;
                    break;
            }
        }
        if (finished_ && thread_.joinable()) {
            RenderResult result = stop();
            if (!status_) status_ = deliver(result, !moved_);
            // Once the output is written: a title saying "done" means the file is there.
            char done[96];
            std::snprintf(done, sizeof done, "done in %.2f s  (S: save, Esc: close)",
                          result.seconds);
            viewer_.setStatus(done);
        }
        // While no render has completed one runs, so there is something to deliver.
        if (close) {
            if (thread_.joinable()) {
                RenderResult result = stop();
                if (!status_) status_ = deliver(result, !moved_);
            }
            return *status_;
        }
        if (moved) {
            if (thread_.joinable()) stop();
            moved_ = true;
            scene_.setCamera(orbit_.camera());
            start();
        }
    }
}

void LiveRender::saveSnapshot() {
    std::filesystem::path path;
    do
        path = output_.parent_path() /
               (output_.stem().string() + "-snapshot-" + std::to_string(++snapshotCount_) +
                output_.extension().string());
    while (std::filesystem::exists(path));
    try {
        Image image = viewer_.image();
        viewer_.toneMapper().mapForOutput(image, ImageWriter::storesLinear(path));
        ImageWriter::write(image, path);
        if (!quiet_) std::cerr << "lancer: snapshot written to " << path.string() << '\n';
    } catch (const std::exception& e) {
        std::cerr << "lancer: error: " << e.what() << '\n';
    }
}

}  // namespace lancer
