#pragma once

#include <atomic>
#include <optional>

#include "radiosity/RadiositySolution.h"

namespace lancer {

class ProgressBar;
class RadiositySolver;

// A radiosity solve with its progress on the terminal's bar: the solver runs on a thread of its
// own while this one redraws the bar (phase, shots, unshot power, time) a few times a second, so
// that the time goes on during a long step (the final gather reports only as it starts).
class TerminalSolve {
public:
    TerminalSolve(RadiositySolver& solver, ProgressBar& progress);

    // Solves; nothing when `cancel` (Ctrl-C) stopped it before the end.
    std::optional<RadiositySolution> run(const std::atomic<bool>& cancel);

private:
    RadiositySolver& solver_;
    ProgressBar& progress_;
};

}  // namespace lancer
