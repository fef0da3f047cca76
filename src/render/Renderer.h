#pragma once

#include <vector>

#include "render/LightEdgeProbe.h"
#include "render/PixelEstimator.h"
#include "render/PixelWindow.h"
#include "render/RenderOptions.h"
#include "render/RenderResult.h"

namespace lancer {

class Integrator;
class Scene;

// Renders a scene: the image is cut into tiles that oneTBB's threads take one at a time. A
// pixel's value depends only on (seed, pixel), never on which thread rendered it or when, so the
// image is the same bit for bit whatever the thread count.
class Renderer {
public:
    Renderer(const Scene& scene, const Integrator& integrator);

    RenderResult render(const RenderOptions& options) const;

    static constexpr int kTileSize = 16;
    // The tiles a window is rendered in, row by row: what RenderResult::finishedTiles counts.
    static std::vector<PixelWindow> tiles(const PixelWindow& window);

private:
    // The preview's one ray for a block of pixels.
    Color previewSample(const PixelWindow& block, std::uint64_t seed,
                        std::uint64_t& rayCount) const;

    const Scene& scene_;
    const Integrator& integrator_;
    PixelEstimator pixelEstimator_;  // the image's pixels
    LightEdgeProbe lightEdgeProbe_;  // which of them take more samples
};

}  // namespace lancer
