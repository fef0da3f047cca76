#pragma once

// lancer run in a pseudo-terminal, as a user's shell runs it: for what it draws only on a
// terminal (the progress bar).

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lancer::test {

class TerminalRun {
public:
    // Runs lancer with `arguments` in `workingFolder`, its standard input, output and error a
    // terminal `columns` wide, and reads what it writes there until it exits. `onOutput` (if
    // any) sees all it has written so far after each read, and may resize the terminal.
    TerminalRun(const std::vector<std::string>& arguments,
                const std::filesystem::path& workingFolder, int columns,
                const std::function<void(TerminalRun&, const std::string&)>& onOutput = {},
                std::chrono::milliseconds timeout = std::chrono::seconds(60));

    // Makes the terminal `columns` wide (lancer sees it at its next draw).
    void resize(int columns) const;
    // Ctrl-C.
    void interrupt() const;

    int exitStatus() const { return exitStatus_; }
    // All that was written to the terminal (lines end in "\r\n" there).
    const std::string& output() const { return output_; }
    // The output cut at every '\r' and '\n', with the erase-line sequence taken out: each piece
    // is what one redraw of a line left on the screen.
    std::vector<std::string> pieces() const;

private:
    int pid_ = -1;
    int master_ = -1;
    int exitStatus_ = -1;
    std::string output_;
};

}  // namespace lancer::test
