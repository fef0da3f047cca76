#pragma once

#include <atomic>

namespace lancer {

// Ctrl-C (SIGINT), SIGTERM and SIGHUP, handled alike: the first asks the work under way to stop
// (requested()), and the program ends with exitStatus(), 128 + the signal's number, as a shell
// reports a process the signal ended. What a signal does depends on the program's phase:
// - Loading (from install() on): nothing has been written and nothing would be, so it exits at
//   once with one line.
// - Working (the radiosity solve, the render, the window): it sets requested(); the work stops
//   soon and what was rendered is saved.
// - Saving (an image or a solution being written): it only sets requested(), so that the file is
//   complete; the save goes on.
// Signals after the first are ignored in every phase but Loading: a second Ctrl-C cannot break
// the save that the first one asked for.
class InterruptSignals {
public:
    enum class Phase { Loading, Working, Saving };

    // Installs the handlers, in the Loading phase.
    static void install();
    static void setPhase(Phase phase);

    static const std::atomic<bool>& requested();
    // 128 + the first signal's number, or 130 (as for Ctrl-C) when the stop came from elsewhere
    // (the window closed).
    static int exitStatus();
};

}  // namespace lancer
