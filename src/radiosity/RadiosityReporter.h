#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>

#include "radiosity/RadiosityProgress.h"

namespace lancer {

// What a radiosity method's solve shares with its caller: where it is, reported between its steps
// to `onProgress` (if any) on the solving thread, and whether `cancel` (if any) asks it to stop.
class RadiosityReporter {
public:
    RadiosityReporter(const std::function<void(const RadiosityProgress&)>& onProgress,
                      const std::atomic<bool>* cancel)
        : onProgress_(onProgress), cancel_(cancel), start_(std::chrono::steady_clock::now()) {}

    bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
    // Reports where the solve is; false once it is cancelled.
    bool carryOn(RadiosityProgress::Phase phase, std::uint64_t steps, double unshotPower,
                 double initialPower) const {
        if (cancelled()) return false;
        if (onProgress_) {
            RadiosityProgress progress;
            progress.phase = phase;
            progress.shots = steps;
            progress.unshotPower = unshotPower;
            progress.initialPower = initialPower;
            progress.seconds = seconds();
            onProgress_(progress);
        }
        return !cancelled();
    }
    // Since the solve started.
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    const std::function<void(const RadiosityProgress&)>& onProgress_;
    const std::atomic<bool>* cancel_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace lancer
