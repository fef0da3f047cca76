#include "TerminalSolve.h"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "ProgressBar.h"
#include "radiosity/RadiositySolver.h"

namespace lancer {

TerminalSolve::TerminalSolve(RadiositySolver& solver, ProgressBar& progress)
    : solver_(solver), progress_(progress) {}

std::optional<RadiositySolution> TerminalSolve::run(const std::atomic<bool>& cancel) {
    const auto start = std::chrono::steady_clock::now();
    std::mutex mutex;  // guards latest and finished
    std::condition_variable changed;
    std::optional<RadiosityProgress> latest;
    bool finished = false;
    std::optional<RadiositySolution> solution;
    std::exception_ptr failure;  // what the solve threw, thrown again here
    std::thread solving([&] {
        try {
            solution = solver_.solve(
                [&](const RadiosityProgress& p) {
                    const std::lock_guard lock(mutex);
                    latest = p;
                },
                &cancel);
        } catch (...) {
            failure = std::current_exception();
        }
        const std::lock_guard lock(mutex);
        finished = true;
        changed.notify_one();
    });
    {
        std::unique_lock lock(mutex);
        while (!changed.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; }))
            if (latest) {
                RadiosityProgress shown = *latest;
                shown.seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                progress_.update(shown);
            }
    }
    solving.join();
    if (failure) std::rethrow_exception(failure);
    return solution;
}

}  // namespace lancer
