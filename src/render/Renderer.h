#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>

#include "render/Film.h"

namespace lancer {

class Integrator;
class Scene;

// A rectangle of pixels, x0 <= x < x1, y0 <= y < y1.
struct PixelWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
};

struct RenderOptions {
    int threads = 0;                                                // 0: all cores
    std::uint64_t seed = 0;                                         // selects the sample patterns
    std::optional<PixelWindow> crop;                                // render only these pixels
    const std::atomic<bool>* cancel = nullptr;                      // set to stop the workers early
    std::function<void(int tilesDone, int tilesTotal)> onTileDone;  // called under a lock
};

struct RenderResult {
    Film film;
    bool interrupted = false;  // cancelled: only the tiles finished before are in the film
    std::uint64_t rays = 0;    // every ray traced: camera, shadow and secondary
    double seconds = 0;
    int threads = 0;
};

// Renders a scene: the image is cut into tiles that a pool of threads takes one at a time. A
// pixel's value depends only on (seed, pixel), never on which thread rendered it or when, so the
// image is the same bit for bit whatever the thread count.
class Renderer {
public:
    Renderer(const Scene& scene, const Integrator& integrator);

    RenderResult render(const RenderOptions& options) const;

    static constexpr int kTileSize = 16;

private:
    Color renderPixel(int x, int y, std::uint64_t seed, std::uint64_t& rayCount) const;

    const Scene& scene_;
    const Integrator& integrator_;
};

}  // namespace lancer
