#include "TerminalRun.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stdexcept>

#include "LancerRun.h"

namespace lancer::test {

namespace {

winsize sizeOf(int columns) {
    winsize size{};
    size.ws_row = 24;
    size.ws_col = static_cast<unsigned short>(columns);
    return size;
}

}  // namespace

TerminalRun::TerminalRun(const std::vector<std::string>& arguments,
                         const std::filesystem::path& workingFolder, int columns,
                         const std::function<void(TerminalRun&, const std::string&)>& onOutput,
                         std::chrono::milliseconds timeout) {
    // Everything the child needs is prepared before fork(): after it, only async-signal-safe
    // calls are allowed.
    LancerArguments argv(arguments);
    const std::string folder = workingFolder.string();

    winsize size = sizeOf(columns);
    pid_ = forkpty(&master_, nullptr, nullptr, &size);
    if (pid_ < 0) throw std::runtime_error("forkpty failed");
    if (pid_ == 0) {
        if (chdir(folder.c_str()) != 0) _exit(127);
        signal(SIGINT, SIG_DFL);
        execv(argv.argv()[0], argv.argv());
        _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        pollfd ready{master_, POLLIN, 0};
        if (poll(&ready, 1, 50) > 0) {
            char buffer[4096];
            const ssize_t n = read(master_, buffer, sizeof buffer);
            // EIO: the child has exited and closed the terminal.
            if (n <= 0) break;
            output_.append(buffer, static_cast<std::size_t>(n));
            if (onOutput) onOutput(*this, output_);
        }
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid_, SIGKILL);
            break;
        }
    }
    int status = 0;
    waitpid(pid_, &status, 0);
    close(master_);
    if (WIFEXITED(status)) exitStatus_ = WEXITSTATUS(status);
}

void TerminalRun::resize(int columns) const {
    const winsize size = sizeOf(columns);
    ioctl(master_, TIOCSWINSZ, &size);
}

void TerminalRun::interrupt() const {
    kill(pid_, SIGINT);
}

std::vector<std::string> TerminalRun::pieces() const {
    std::string text = output_;
    for (std::size_t at; (at = text.find("\033[K")) != std::string::npos;)
        text.erase(at, 3);
    std::vector<std::string> pieces;
    std::string piece;
    for (const char c : text) {
        if (c == '\r' || c == '\n') {
            if (!piece.empty()) pieces.push_back(piece);
            piece.clear();
        } else {
            piece += c;
        }
    }
    if (!piece.empty()) pieces.push_back(piece);
    return pieces;
}

}  // namespace lancer::test
