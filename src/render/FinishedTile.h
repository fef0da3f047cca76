#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "image/Image.h"
#include "render/PixelWindow.h"

namespace lancer {

// A tile just finished, as reported to RenderOptions::onTileDone.
struct FinishedTile {
    const Image& film;                   // holds the tile's pixels; read them during the call only
    const std::vector<Image>& aovFilms;  // the auxiliary outputs' tiles (not a preview's)
    PixelWindow tile;
    // The image's tile's index in Renderer::tiles(window); none for a coarse pass's stand-in
    // pixels (in a film of their own).
    std::optional<std::size_t> index;
    int tilesDone = 0;   // the image's tiles finished so far (previews not counted)
    int tilesTotal = 0;  // the image's tiles

    bool preview() const { return !index; }
};

}  // namespace lancer
