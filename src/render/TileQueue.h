#pragma once

#include <cstddef>
#include <optional>

namespace lancer {

// Hands out the tiles of a render (indices into Renderer::tiles(window)), one at a time, to the
// threads of this process and, in a cluster render, of other processes. Called from many threads
// at once.
class TileQueue {
public:
    virtual ~TileQueue() = default;
    // The next tile to render, or none when no tile is left for this caller.
    virtual std::optional<std::size_t> next() = 0;
};

}  // namespace lancer
