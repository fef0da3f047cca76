#include "ProgressBar.h"

#include <cstdio>
#include <string>

namespace lancer {

namespace {

std::string formatDuration(double seconds) {
    const auto total = static_cast<long>(seconds + 0.5);
    char text[32];
    if (total >= 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60,
                      total % 60);
    else
        std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
    return text;
}

}  // namespace

ProgressBar::ProgressBar(bool enabled) : enabled_(enabled), start_(Clock::now()) {}

void ProgressBar::update(int done, int total) {
    if (!enabled_ || total <= 0) return;
    const auto now = Clock::now();
    // Redraw at most ten times a second, and always at the end.
    if (done < total && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;
    const double fraction = static_cast<double>(done) / total;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                            std::string(static_cast<std::size_t>(kWidth - filled), '-');
    std::fprintf(stderr, "\r[%s] %s ", bar.c_str(), describe(done, total, elapsed).c_str());
    std::fflush(stderr);
}

std::string ProgressBar::describe(int done, int total, double elapsedSeconds) {
    const double fraction = total > 0 ? static_cast<double>(done) / total : 1.0;
    const std::string eta =
        done > 0 ? formatDuration(elapsedSeconds / fraction - elapsedSeconds) : "?";
    char text[96];
    std::snprintf(text, sizeof text, "%3d%%  elapsed %s  ETA %s", static_cast<int>(fraction * 100),
                  formatDuration(elapsedSeconds).c_str(), eta.c_str());
    return text;
}

void ProgressBar::finish() {
    if (!enabled_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

}  // namespace lancer
