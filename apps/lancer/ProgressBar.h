#pragma once

#include <chrono>
#include <string>

namespace lancer {

// A one-line progress bar on stderr: percentage, elapsed time and estimated time left. Draws
// nothing when disabled (stderr is not a terminal, or --quiet).
class ProgressBar {
public:
    explicit ProgressBar(bool enabled);

    void update(int done, int total);
    // "42%  elapsed 0:03  ETA 0:05": the text of the bar, also the window's title.
    static std::string describe(int done, int total, double elapsedSeconds);
    // Erases the bar, leaving the line free for the final report.
    void finish();

private:
    using Clock = std::chrono::steady_clock;

    bool enabled_;
    Clock::time_point start_;
    Clock::time_point lastDraw_;
};

}  // namespace lancer
