#pragma once

#include <vector>

#include "image/Image.h"
#include "render/RenderCounters.h"

namespace lancer {

struct RenderResult {
    Image film;
    std::vector<Image>
        aovFilms{};             // one per RenderOptions::aovs, in its order, holding the same tiles
    bool interrupted = false;   // cancelled: only the tiles finished before are in the film
    RenderCounters counters{};  // rays traced, samples taken, NaN or infinite samples dropped
    double seconds = 0;
    int threads = 0;
};

}  // namespace lancer
