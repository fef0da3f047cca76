#pragma once

#include "image/Image.h"
#include "render/PixelWindow.h"

namespace lancer {

// A tile just finished, as reported to RenderOptions::onTileDone.
struct FinishedTile {
    const Image& film;  // holds the tile's pixels; read them during the call only
    PixelWindow tile;
    bool preview;       // a coarse pass's stand-in pixels (in a film of their own), not the image's
    int tilesDone = 0;  // the image's tiles finished so far (previews not counted)
    int tilesTotal = 0;  // the image's tiles
};

}  // namespace lancer
