#include "render/PendingTiles.h"

namespace lancer {

PendingTiles::PendingTiles(const std::vector<bool>& finishedTiles) {
    for (std::size_t t = 0; t < finishedTiles.size(); ++t)
        if (!finishedTiles[t]) pending_.push_back(t);
}

std::optional<std::size_t> PendingTiles::next() {
    const std::size_t p = nextPending_.fetch_add(1);
    if (p >= pending_.size()) return std::nullopt;
    return pending_[p];
}

}  // namespace lancer
