#pragma once

#include <chrono>
#include <string>

#include "radiosity/RadiosityProgress.h"

namespace lancer {

// A one-line progress bar on stderr, as wide as the terminal: the render's percentage, elapsed
// time and estimated time left, or the radiosity solve's phase, shots, unshot power and time.
// Draws nothing when disabled (stderr is not a terminal, or --quiet).
class ProgressBar {
public:
    explicit ProgressBar(bool enabled);

    // The render: `done` tiles of `total`.
    void update(int done, int total);
    // The radiosity solve, the bar filled by the share of the power shot.
    void update(const RadiosityProgress& progress);
    // "42%  elapsed 0:03  ETA 0:05": the text of the render's bar, also the window's title.
    static std::string describe(int done, int total, double elapsedSeconds);
    // "radiosity: shooting, 120 shots, unshot 0.52 W (2.1% of 24 W)", also the window's title.
    static std::string describe(const RadiosityProgress& progress);
    // The line drawn for `text` with `fraction` done in a terminal `columns` wide: a bar as wide
    // as the room left, or the text alone (cut if need be) when there is little room. It leaves
    // the last column free, where some terminals wrap the line.
    static std::string line(double fraction, const std::string& text, int columns);
    // Erases the bar, leaving the line free for the final report.
    void finish();

private:
    using Clock = std::chrono::steady_clock;

    // Redraws at most ten times a second, unless `force`; the width is asked of the terminal
    // each time, so that the bar follows a resize.
    void draw(double fraction, const std::string& text, bool force);
    static int terminalColumns();

    bool enabled_;
    Clock::time_point start_;
    Clock::time_point lastDraw_;
};

}  // namespace lancer
