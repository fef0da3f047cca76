#pragma once

#include <chrono>

namespace lancer {

// A one-line progress bar on stderr: percentage, elapsed time and estimated time left. Draws
// nothing when disabled (stderr is not a terminal, or --quiet).
class ProgressBar {
public:
    explicit ProgressBar(bool enabled);

    void update(int done, int total);
    // Erases the bar, leaving the line free for the final report.
    void finish();

private:
    using Clock = std::chrono::steady_clock;

    bool enabled_;
    Clock::time_point start_;
    Clock::time_point lastDraw_;
};

}  // namespace lancer
