#pragma once

#include <atomic>
#include <vector>

#include "render/TileQueue.h"

namespace lancer {

// The tiles not yet finished (those of a resumed render are), in order, each handed out once.
class PendingTiles : public TileQueue {
public:
    explicit PendingTiles(const std::vector<bool>& finishedTiles);

    std::optional<std::size_t> next() override;

private:
    std::vector<std::size_t> pending_;
    std::atomic<std::size_t> nextPending_{0};
};

}  // namespace lancer
