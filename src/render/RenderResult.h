#pragma once

#include <vector>

#include "image/Image.h"
#include "render/RenderCounters.h"

namespace lancer {

struct RenderResult {
    Image film;
    std::vector<Image>
        aovFilms{};            // one per RenderOptions::aovs, in its order, holding the same tiles
    bool interrupted = false;  // cancelled: only the tiles finished before are in the film
    // Per tile of Renderer::tiles(the window rendered), whether it is in the films.
    std::vector<bool> finishedTiles{};
    // Rays traced, samples taken, NaN or infinite samples dropped (those of the resumed render's
    // tiles included).
    RenderCounters counters{};
    double seconds = 0;  // this render's, without a resumed render's
    int threads = 0;     // in all processes
    int processes = 1;   // a cluster render's (Cluster)
};

}  // namespace lancer
