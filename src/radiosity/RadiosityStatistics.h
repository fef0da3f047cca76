#pragma once

#include <cstdint>

namespace lancer {

// What a solve did, for the report lancer prints.
struct RadiosityStatistics {
    std::uint64_t patches = 0;
    std::uint64_t elements = 0;  // leaves: what the image shows
    std::uint64_t links = 0;     // hierarchical: links between elements and clusters
    std::uint64_t shots = 0;     // iterations of progressive refinement
    double initialPower = 0;     // W (mean over r, g, b): emitted, and received from lights
    double residualPower = 0;    // W left unshot at the end
    double seconds = 0;
    std::uint64_t rays = 0;
};

}  // namespace lancer
