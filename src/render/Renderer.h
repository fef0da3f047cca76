#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "image/Image.h"
#include "render/PixelEstimator.h"
#include "render/RenderCounters.h"

namespace lancer {

class Integrator;
class Scene;

// A rectangle of pixels, x0 <= x < x1, y0 <= y < y1.
struct PixelWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
};

// A tile just finished, as reported to RenderOptions::onTileDone.
struct FinishedTile {
    const Image& film;  // holds the tile's pixels; read them during the call only
    PixelWindow tile;
    bool preview;       // a coarse pass's stand-in pixels (in a film of their own), not the image's
    int tilesDone = 0;  // the image's tiles finished so far (previews not counted)
    int tilesTotal = 0;  // the image's tiles
};

struct RenderOptions {
    int threads = 0;                            // 0: all cores
    std::uint64_t seed = 0;                     // selects the sample patterns
    std::optional<PixelWindow> crop;            // render only these pixels
    const std::atomic<bool>* cancel = nullptr;  // set to stop the workers early
    // Coarse passes before the image, for a live view: a pass of block size k traces one ray
    // through the centre of each k x k block and fills the block with it. None by default; they
    // never change the image.
    std::vector<int> previewBlockSizes;
    // Render the preview passes only, none of the image's tiles (a live view's quick look at
    // something that will change, such as a radiosity solution while it is solved).
    bool previewOnly = false;
    // Called under a lock after each tile, preview tiles included, in the order they finish;
    // every tile of a pass is reported before any of the next pass.
    std::function<void(const FinishedTile&)> onTileDone;
};

struct RenderResult {
    Image film;
    bool interrupted = false;   // cancelled: only the tiles finished before are in the film
    RenderCounters counters{};  // rays traced, samples taken, NaN or infinite samples dropped
    double seconds = 0;
    int threads = 0;
};

// Renders a scene: the image is cut into tiles that oneTBB's threads take one at a time. A
// pixel's value depends only on (seed, pixel), never on which thread rendered it or when, so the
// image is the same bit for bit whatever the thread count.
class Renderer {
public:
    Renderer(const Scene& scene, const Integrator& integrator);

    RenderResult render(const RenderOptions& options) const;

    static constexpr int kTileSize = 16;

private:
    // The preview's one ray for a block of pixels.
    Color previewSample(const PixelWindow& block, std::uint64_t seed,
                        std::uint64_t& rayCount) const;

    const Scene& scene_;
    const Integrator& integrator_;
    PixelEstimator pixelEstimator_;  // the image's pixels
};

}  // namespace lancer
