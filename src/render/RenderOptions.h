#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "render/Aov.h"
#include "render/FinishedTile.h"
#include "render/PixelWindow.h"
#include "render/RenderResult.h"
#include "render/TileQueue.h"

namespace lancer {

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
    // The auxiliary outputs to render besides the image (RenderResult::aovFilms), none by
    // default.
    std::vector<const Aov*> aovs;
    // An interrupted render of the same image (the same scene, settings, seed, crop and auxiliary
    // outputs) to finish: its finished tiles are kept as they are and reported first, the others
    // rendered. Its films must be the image's size, with one per auxiliary output.
    const RenderResult* resumeFrom = nullptr;
    // Where the image's tiles come from: by default every tile not finished (PendingTiles), in
    // order; a cluster render's queue shares them out between processes.
    TileQueue* tileQueue = nullptr;
    // Called under a lock after each tile, preview tiles included, in the order they finish;
    // every tile of a pass is reported before any of the next pass.
    std::function<void(const FinishedTile&)> onTileDone;
};

}  // namespace lancer
