#pragma once

#include <cstdint>

namespace lancer {

// Where a radiosity solve is, as a RadiosityMethod reports it between its steps (for a live
// view: lancer --window shows it in the title).
struct RadiosityProgress {
    enum class Phase {
        Shooting,     // progressive refinement
        Subdividing,  // adaptive subdivision, before each level
        Refining,     // hierarchical: links refined
        Iterating,    // hierarchical: Jacobi iterations ("shots" counts them)
        Gathering,    // the final gather at the elements' corners
    };
    Phase phase = Phase::Shooting;
    std::uint64_t shots = 0;  // or iterations
    double unshotPower = 0;   // W (mean over r, g, b) not shot yet, or the last iteration's change
    double initialPower = 0;  // W put in: emitted, and received from the lights
    double seconds = 0;       // since the solve started

    static const char* nameOf(Phase phase) {
        switch (phase) {
            case Phase::Shooting:
                return "shooting";
            case Phase::Subdividing:
                return "subdividing";
            case Phase::Refining:
                return "refining links";
            case Phase::Iterating:
                return "iterating";
            case Phase::Gathering:
                return "gathering";
        }
        return "";
    }
};

}  // namespace lancer
