// The progress bar on a terminal (a pseudo-terminal here): it fits the terminal's width, follows
// a resize, and shows the radiosity solve as well as the render.

#include <gtest/gtest.h>

#include <cstdlib>

#include <string>
#include <vector>

#include "LancerRun.h"
#include "TerminalRun.h"

namespace lancer::test {
namespace {

bool isRenderBar(const std::string& piece) {
    return piece.find("elapsed") != std::string::npos;
}

// The solve's bar in any of its phases (shooting, subdividing): on a quiet machine a short solve
// may shoot within one redraw interval and show only its later phase.
bool isRadiosityBar(const std::string& piece) {
    return piece.find("radiosity: shooting, ") != std::string::npos ||
           piece.find("radiosity: subdividing, ") != std::string::npos;
}

// A render of the Whitted scene long enough for several redraws of the bar.
std::vector<std::string> whittedRender(const TempFolder& folder) {
    folder.write("scene.json", loadWhittedScene().dump());
    return {"scene.json", "-o", "out.png", "--width", "240", "--height", "180", "--spp", "4"};
}

class CliProgressBarWidth : public testing::TestWithParam<int> {};

TEST_P(CliProgressBarWidth, FitsTheTerminalWidthWithoutWrapping) {
    const int columns = GetParam();
    const TempFolder folder;
    const TerminalRun run(whittedRender(folder), folder.path(), columns);
    ASSERT_EQ(run.exitStatus(), 0) << run.output();
    int bars = 0;
    for (const std::string& piece : run.pieces()) {
        if (!isRenderBar(piece)) continue;
        ++bars;
        // The last column is left free: a line that reaches it wraps on some terminals.
        EXPECT_LE(piece.size(), static_cast<std::size_t>(columns - 1)) << piece;
    }
    EXPECT_GT(bars, 0) << run.output();
}

INSTANTIATE_TEST_SUITE_P(Columns, CliProgressBarWidth, testing::Values(20, 40, 80, 200));

TEST(CliProgressBar, UsesTheWidthOfAWideTerminal) {
    const TempFolder folder;
    const TerminalRun run(whittedRender(folder), folder.path(), 200);
    ASSERT_EQ(run.exitStatus(), 0) << run.output();
    for (const std::string& piece : run.pieces())
        if (isRenderBar(piece)) {
            EXPECT_GT(piece.size(), 70u) << piece;
        }
}

// A terminal that does not say its size (0 columns): the shell's COLUMNS, if exported.
TEST(CliProgressBar, FallsBackOnColumns) {
    const TempFolder folder;
    setenv("COLUMNS", "30", 1);
    const TerminalRun run(whittedRender(folder), folder.path(), 0);
    unsetenv("COLUMNS");
    ASSERT_EQ(run.exitStatus(), 0) << run.output();
    int bars = 0;
    for (const std::string& piece : run.pieces()) {
        if (!isRenderBar(piece)) continue;
        ++bars;
        EXPECT_LE(piece.size(), 29u) << piece;
    }
    EXPECT_GT(bars, 0) << run.output();
}

TEST(CliProgressBar, FollowsAResize) {
    const TempFolder folder;
    // Long enough for the resize to come before the end (the last bar is always drawn).
    folder.write("scene.json", loadWhittedScene().dump());
    bool resized = false;
    std::size_t piecesBefore = 0;
    const TerminalRun run(
        {"scene.json", "-o", "out.png", "--width", "480", "--height", "360", "--spp", "8"},
        folder.path(), 120, [&](TerminalRun& terminal, const std::string& output) {
            if (resized || output.find("elapsed") == std::string::npos) return;
            terminal.resize(30);
            resized = true;
            piecesBefore = terminal.pieces().size();
        });
    ASSERT_EQ(run.exitStatus(), 0) << run.output();
    ASSERT_TRUE(resized) << run.output();
    // A bar drawn just before the resize may still be read after it; from the first bar that
    // fits the new width on, every one does.
    const std::vector<std::string> pieces = run.pieces();
    bool fitted = false;
    for (std::size_t i = piecesBefore; i < pieces.size(); ++i) {
        if (!isRenderBar(pieces[i])) continue;
        if (pieces[i].size() <= 29) fitted = true;
        if (fitted) {
            EXPECT_LE(pieces[i].size(), 29u) << pieces[i];
        }
    }
    EXPECT_TRUE(fitted) << "the bar was not redrawn at the new width: " << run.output();
}

TEST(CliProgressBar, ShowsTheRadiositySolve) {
    const TempFolder folder;
    nlohmann::json scene = loadWhittedScene();
    scene["render"]["integrator"] = "radiosity";
    // A short solve (the bar is drawn at its first shot), still with every phase.
    scene["radiosity"] = {{"threshold", 0.2}, {"subdivision_levels", 1}};
    folder.write("scene.json", scene.dump());
    const TerminalRun run(
        {"scene.json", "-o", "out.png", "--width", "32", "--height", "24", "--spp", "1"},
        folder.path(), 120);
    ASSERT_EQ(run.exitStatus(), 0) << run.output();
    int bars = 0;
    for (const std::string& piece : run.pieces()) {
        if (!isRadiosityBar(piece)) continue;
        ++bars;
        EXPECT_NE(piece.find(" shots, unshot "), std::string::npos) << piece;
        EXPECT_NE(piece.find(" W ("), std::string::npos) << piece;
        EXPECT_LE(piece.size(), 119u) << piece;
    }
    EXPECT_GT(bars, 0) << run.output();
}

TEST(CliProgressBar, CtrlCStopsTheSolveItShows) {
    const TempFolder folder;
    nlohmann::json scene = loadWhittedScene();
    scene["render"]["integrator"] = "radiosity";
    scene["radiosity"] = {{"patch_size", 1}};  // seconds of solving
    folder.write("scene.json", scene.dump());
    bool interrupted = false;
    const TerminalRun run(
        {"scene.json", "-o", "out.png", "--width", "32", "--height", "24"}, folder.path(), 120,
        [&](TerminalRun& terminal, const std::string& output) {
            if (interrupted || output.find("radiosity: shooting") == std::string::npos) return;
            terminal.interrupt();
            interrupted = true;
        });
    ASSERT_TRUE(interrupted) << run.output();
    EXPECT_EQ(run.exitStatus(), 130) << run.output();
    EXPECT_NE(run.output().find("interrupted during the radiosity solve"), std::string::npos)
        << run.output();
    EXPECT_EQ(folder.entries(), (std::vector<std::string>{"scene.json"}));
}

TEST(CliProgressBar, QuietDrawsNothing) {
    const TempFolder folder;
    std::vector<std::string> arguments = whittedRender(folder);
    arguments.push_back("--quiet");
    const TerminalRun run(arguments, folder.path(), 80);
    ASSERT_EQ(run.exitStatus(), 0) << run.output();
    EXPECT_EQ(run.output(), "");
}

}  // namespace
}  // namespace lancer::test
