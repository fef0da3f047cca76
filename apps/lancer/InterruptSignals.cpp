#include "InterruptSignals.h"

#include <unistd.h>

#include <csignal>
#include <cstring>

namespace lancer {

namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kExitInterrupted = 128 + SIGINT;

// Lock-free atomics only: the handler may run on any thread at any moment.
std::atomic<bool> stopRequested{false};
std::atomic<int> firstSignal{0};
std::atomic<InterruptSignals::Phase> phase{InterruptSignals::Phase::Loading};
static_assert(std::atomic<int>::is_always_lock_free);
static_assert(std::atomic<InterruptSignals::Phase>::is_always_lock_free);

extern "C" void onSignal(int signal) {
    if (phase.load() == InterruptSignals::Phase::Loading) {
        // Only async-signal-safe calls here: write and _exit.
        const char message[] = "lancer: interrupted while loading the scene; nothing was written\n";
        const ssize_t ignored = write(STDERR_FILENO, message, sizeof message - 1);
        static_cast<void>(ignored);
        _exit(128 + signal);
    }
    int none = 0;
    if (firstSignal.compare_exchange_strong(none, signal)) stopRequested = true;
}

}  // namespace

void InterruptSignals::install() {
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    // Restart interrupted reads and writes: the save must not fail because a signal came.
    action.sa_flags = SA_RESTART;
    for (const int signal : kSignals)
        sigaction(signal, &action, nullptr);
}

void InterruptSignals::setPhase(Phase newPhase) {
    phase = newPhase;
}

const std::atomic<bool>& InterruptSignals::requested() {
    return stopRequested;
}

int InterruptSignals::exitStatus() {
    const int signal = firstSignal.load();
    return signal != 0 ? 128 + signal : kExitInterrupted;
}

}  // namespace lancer
