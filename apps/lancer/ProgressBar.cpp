#include "ProgressBar.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
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

// Below this many cells the bar says too little: the text alone is drawn.
constexpr int kNarrowestBar = 10;
constexpr int kWidestBar = 40;
constexpr int kDefaultColumns = 80;

}  // namespace

ProgressBar::ProgressBar(bool enabled) : enabled_(enabled), start_(Clock::now()) {}

void ProgressBar::update(int done, int total) {
    if (!enabled_ || total <= 0) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    draw(static_cast<double>(done) / total, describe(done, total, elapsed), done == total);
}

void ProgressBar::update(const RadiosityProgress& progress) {
    if (!enabled_) return;
    const double shot =
        progress.initialPower > 0 ? 1 - progress.unshotPower / progress.initialPower : 1.0;
    draw(shot, describe(progress) + "  " + formatDuration(progress.seconds), false);
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

std::string ProgressBar::describe(const RadiosityProgress& p) {
    char text[160];
    std::snprintf(text, sizeof text, "radiosity: %s, %llu shots, unshot %.3g W (%.3g%% of %.4g W)",
                  RadiosityProgress::nameOf(p.phase), static_cast<unsigned long long>(p.shots),
                  p.unshotPower, p.initialPower > 0 ? 100 * p.unshotPower / p.initialPower : 0.0,
                  p.initialPower);
    return text;
}

std::string ProgressBar::line(double fraction, const std::string& text, int columns) {
    const int room = columns - 1;
    const int textLength = static_cast<int>(text.size());
    const int cells = std::min(kWidestBar, room - textLength - 3);  // "[" cells "] " text
    if (cells < kNarrowestBar) return text.substr(0, static_cast<std::size_t>(std::max(0, room)));
    const int filled = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * cells);
    return "[" + std::string(static_cast<std::size_t>(filled), '#') +
           std::string(static_cast<std::size_t>(cells - filled), '-') + "] " + text;
}

void ProgressBar::draw(double fraction, const std::string& text, bool force) {
    const auto now = Clock::now();
    if (!force && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;
    // Back to the start of the line and erase it: a bar drawn wider before a resize leaves
    // nothing behind.
    std::fprintf(stderr, "\r\033[K%s", line(fraction, text, terminalColumns()).c_str());
    std::fflush(stderr);
}

int ProgressBar::terminalColumns() {
    winsize size{};
    if (ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
    // Without an answer from the terminal, the shell's COLUMNS, if exported.
    if (const char* columns = std::getenv("COLUMNS")) {
        const int n = std::atoi(columns);
        if (n > 0) return n;
    }
    return kDefaultColumns;
}

void ProgressBar::finish() {
    if (!enabled_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

}  // namespace lancer
