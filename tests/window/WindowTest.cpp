// lancer --window end to end, on a virtual X server (Xvfb) of the test's own: the window shows
// the saved image once the render ends, S saves snapshots, closing the window or Esc stops the
// render as Ctrl-C does, dragging and the wheel move the camera, a radiosity solve shows its
// progress and can be stopped the same way, and without a display the render goes on without a
// window.

#include <X11/keysym.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdlib>
#include <optional>
#include <ostream>
#include <thread>

#include "LancerRun.h"
#include "X11Window.h"
#include "XvfbServer.h"

namespace lancer::test {
namespace {

using namespace std::chrono_literals;

// Generous, for sanitizer builds on two busy cores; the tests end as soon as things happen.
constexpr std::chrono::seconds kWait{30};
constexpr int kScreenWidth = 800, kScreenHeight = 600;
// The title's prefix: "lancer: " and the scene file's name.
const std::string kTitle = "lancer: scene.json";

// Renders of a few tenths of a second: the Whitted scene, small.
std::vector<std::string> quickRender(const std::string& output, int width = 96, int height = 64) {
    return {"scene.json",
            "-o",
            output,
            "--width",
            std::to_string(width),
            "--height",
            std::to_string(height),
            "--spp",
            "2",
            "--threads",
            "2"};
}

std::vector<std::string> withWindow(std::vector<std::string> arguments) {
    arguments.push_back("--window");
    return arguments;
}

// Waits up to `timeout` for `path` to exist.
bool waitForFile(const fs::path& path, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!fs::exists(path)) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(20ms);
    }
    return true;
}

// The percentage in a title such as "lancer: scene.json   42%  elapsed 0:03  ETA 0:05"; -1 if
// there is none.
int percentDone(const std::string& title) {
    const std::size_t percent = title.find('%');
    if (percent == std::string::npos) return -1;
    std::size_t start = percent;
    while (start > 0 && std::isdigit(static_cast<unsigned char>(title[start - 1])))
        --start;
    return start < percent ? std::stoi(title.substr(start, percent - start)) : -1;
}

class LiveWindow : public testing::Test {
protected:
    void SetUp() override {
        if (!XvfbServer::installed())
            GTEST_SKIP() << "Xvfb is not installed (Debian package xvfb): the window is untested";
        server_.emplace(kScreenWidth, kScreenHeight);
        // lancer inherits these: it must meet this server, through X11.
        setenv("DISPLAY", server_->display().c_str(), 1);
        unsetenv("WAYLAND_DISPLAY");
        setenv("SDL_VIDEODRIVER", "x11", 1);
        // Under LeakSanitizer: the system libraries SDL loads for X11 (D-Bus, and libraries it
        // unloads at exit, so that their names are lost) leak a few blocks that lancer cannot
        // free. The other suites check lancer's own leaks.
        if (const char* options = std::getenv("ASAN_OPTIONS")) asanOptions_ = options;
        setenv("ASAN_OPTIONS", (asanOptions_.value_or("") + ":detect_leaks=0").c_str(), 1);
        folder_.write("scene.json", loadWhittedScene().dump());
    }

    void TearDown() override {
        unsetenv("DISPLAY");
        unsetenv("SDL_VIDEODRIVER");
        if (asanOptions_)
            setenv("ASAN_OPTIONS", asanOptions_->c_str(), 1);
        else
            unsetenv("ASAN_OPTIONS");
    }

    // The window of the lancer process just started.
    X11Window findWindow() const { return X11Window(server_->display(), kTitle, kWait); }

    std::optional<XvfbServer> server_;
    std::optional<std::string> asanOptions_;  // as the test started
    TempFolder folder_;
};

TEST_F(LiveWindow, ShowsTheSavedImageOnceTheRenderEndsAndStaysOpenUntilClosed) {
    LancerProcess lancer(withWindow(quickRender("out.png")), folder_.path());
    const X11Window window = findWindow();
    ASSERT_TRUE(window.waitForTitle("done", kWait)) << "title: " << window.title();
    EXPECT_EQ(window.width(), 96);
    EXPECT_EQ(window.height(), 64);
    ASSERT_TRUE(fs::exists(folder_ / "out.png")) << "written when the render ends, not at close";

    const Image saved = loadImage(folder_ / "out.png");
    EXPECT_EQ(maxAbsoluteDifference(window.screenshot(), saved), 0)
        << "the window shows the 8-bit image exactly";

    std::this_thread::sleep_for(200ms);
    EXPECT_TRUE(window.title().find("done") != std::string::npos) << "still open";
    window.close();
    const RunResult run = lancer.wait(kWait);
    EXPECT_EQ(run.exitStatus, 0) << run;
    EXPECT_EQ(folder_.entries(), (std::vector<std::string>{"out.png", "scene.json"}));

    // The same image as without the window, bit for bit.
    const RunResult plain = runLancer(quickRender("plain.png"), folder_.path());
    ASSERT_EQ(plain.exitStatus, 0) << plain;
    EXPECT_EQ(readFile(folder_ / "plain.png"), readFile(folder_ / "out.png"));
}

// The window shows the image as the 8-bit output stores it, exposure and tone operator included,
// and saves its snapshots the same way.
TEST_F(LiveWindow, ShowsTheExposedAndToneMappedImageAsThePngHoldsIt) {
    nlohmann::json scene = loadWhittedScene();
    scene["render"]["exposure"] = 1.5;
    scene["render"]["tonemap"] = "aces";
    folder_.write("scene.json", scene.dump());
    LancerProcess lancer(withWindow(quickRender("out.png")), folder_.path());
    const X11Window window = findWindow();
    ASSERT_TRUE(window.waitForTitle("done", kWait)) << "title: " << window.title();
    const Image saved = loadImage(folder_ / "out.png");
    EXPECT_EQ(maxAbsoluteDifference(window.screenshot(), saved), 0);
    window.pressKey(XK_s);
    ASSERT_TRUE(waitForFile(folder_ / "out-snapshot-1.png", kWait));
    window.close();
    EXPECT_EQ(lancer.wait(kWait).exitStatus, 0);
    EXPECT_EQ(maxAbsoluteDifference(loadImage(folder_ / "out-snapshot-1.png"), saved), 0);

    // Not the plain image: the mapping changed what is shown.
    scene["render"].erase("exposure");
    scene["render"].erase("tonemap");
    folder_.write("scene.json", scene.dump());
    ASSERT_EQ(runLancer(quickRender("plain.png"), folder_.path()).exitStatus, 0);
    EXPECT_GT(maxAbsoluteDifference(loadImage(folder_ / "plain.png"), saved), 10);
}

// The auxiliary outputs are written with the image, the same as without the window.
TEST_F(LiveWindow, WritesTheAuxiliaryOutputsWithTheImage) {
    std::vector<std::string> arguments = withWindow(quickRender("out.png"));
    arguments.insert(arguments.end(), {"--aov", "depth"});
    LancerProcess lancer(arguments, folder_.path());
    const X11Window window = findWindow();
    ASSERT_TRUE(window.waitForTitle("done", kWait)) << "title: " << window.title();
    window.close();
    EXPECT_EQ(lancer.wait(kWait).exitStatus, 0);
    EXPECT_EQ(folder_.entries(),
              (std::vector<std::string>{"out.depth.exr", "out.png", "scene.json"}));

    std::vector<std::string> plain = quickRender("plain.png");
    plain.insert(plain.end(), {"--aov", "depth"});
    ASSERT_EQ(runLancer(plain, folder_.path()).exitStatus, 0);
    EXPECT_EQ(readFile(folder_ / "plain.depth.exr"), readFile(folder_ / "out.depth.exr"));
}

TEST_F(LiveWindow, SSavesWhatTheWindowShowsNextToTheOutput) {
    LancerProcess lancer(withWindow(quickRender("out.png")), folder_.path());
    const X11Window window = findWindow();
    ASSERT_TRUE(window.waitForTitle("done", kWait)) << "title: " << window.title();

    window.pressKey(XK_s);
    ASSERT_TRUE(waitForFile(folder_ / "out-snapshot-1.png", kWait));
    window.pressKey(XK_s);
    ASSERT_TRUE(waitForFile(folder_ / "out-snapshot-2.png", kWait)) << "a new name each time";
    const Image saved = loadImage(folder_ / "out.png");
    EXPECT_EQ(maxAbsoluteDifference(loadImage(folder_ / "out-snapshot-1.png"), saved), 0);
    EXPECT_EQ(maxAbsoluteDifference(window.screenshot(), saved), 0);

    window.pressKey(XK_Escape);
    const RunResult run = lancer.wait(kWait);
    EXPECT_EQ(run.exitStatus, 0) << "Esc after the render closes the window: " << run;
    EXPECT_NE(run.standardError.find("snapshot written to out-snapshot-1.png"), std::string::npos)
        << run;
}

// A render of many seconds, stopped once some of its tiles are done.
enum class Stop { ClosingTheWindow, Escape, CtrlC };
constexpr const char* nameOf(Stop stop) {
    switch (stop) {
        case Stop::ClosingTheWindow:
            return "ByClosingTheWindow";
        case Stop::Escape:
            return "ByEscape";
        case Stop::CtrlC:
            return "ByCtrlC";
    }
    return "";
}
// Names the parameter in test listings (gtest prints raw bytes otherwise).
void PrintTo(Stop stop, std::ostream* out) {
    *out << nameOf(stop);
}

// Stops lancer the way a user would.
void stop(Stop how, const X11Window& window, const LancerProcess& lancer) {
    switch (how) {
        case Stop::ClosingTheWindow:
            window.close();
            break;
        case Stop::Escape:
            window.pressKey(XK_Escape);
            break;
        case Stop::CtrlC:
            lancer.sendSignal(SIGINT);
            break;
    }
}
class StoppedMidRender : public LiveWindow, public testing::WithParamInterface<Stop> {};

TEST_P(StoppedMidRender, SavesTheFinishedTilesAndExits130AsCtrlCDoes) {
    LancerProcess lancer({"scene.json", "-o", "out.pfm", "--width", "640", "--height", "480",
                          "--spp", "64", "--threads", "2", "--window"},
                         folder_.path());
    const X11Window window = findWindow();
    // The title counts the image's tiles: wait until some are done.
    const auto deadline = std::chrono::steady_clock::now() + kWait;
    while (percentDone(window.title()) <= 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(20ms);
    ASSERT_GT(percentDone(window.title()), 0) << "title: " << window.title();
    ASSERT_LT(percentDone(window.title()), 100) << "title: " << window.title();
    EXPECT_NE(window.title().find("ETA"), std::string::npos) << "title: " << window.title();

    stop(GetParam(), window, lancer);
    const RunResult run = lancer.wait(kWait);

    EXPECT_EQ(run.exitStatus, 130) << run;
    EXPECT_NE(run.standardError.find("interrupted; the part rendered so far was written to "
                                     "out.pfm"),
              std::string::npos)
        << run;
    EXPECT_EQ(folder_.entries(),
              (std::vector<std::string>{"out.pfm", "out.pfm.resume", "scene.json"}));
    const Image image = loadImage(folder_ / "out.pfm");
    // Every rendered pixel of this scene is lit at least by the ambient light: black is "not
    // rendered", and what the preview showed there is not saved.
    const auto black = std::count(image.pixels.begin(), image.pixels.end(), Image::Rgb{0, 0, 0});
    EXPECT_GT(black, 0) << "stopped before the end";
    EXPECT_LT(black, static_cast<long>(image.pixels.size())) << "the finished tiles are saved";
}

INSTANTIATE_TEST_SUITE_P(LiveWindow, StoppedMidRender,
                         testing::Values(Stop::ClosingTheWindow, Stop::Escape, Stop::CtrlC),
                         [](const testing::TestParamInfo<Stop>& test) {
                             return nameOf(test.param);
                         });

// The Whitted scene with the radiosity integrator and `radiosity` settings.
nlohmann::json radiosityScene(const nlohmann::json& radiosity) {
    nlohmann::json scene = loadWhittedScene();
    scene["render"]["integrator"] = "radiosity";
    scene["radiosity"] = radiosity;
    return scene;
}

// A solve of under a second in a release build (521 patches, about 380 shots), all of it shooting.
const nlohmann::json kQuickSolve = {
    {"patch_size", 1}, {"subdivision_levels", 0}, {"threshold", 0.02}};
// A solve of many seconds (about 7 s in a release build), to be stopped.
const nlohmann::json kLongSolve = {{"patch_size", 1}};

TEST_F(LiveWindow, ShowsTheRadiositySolveThenTheRenderOfItsSolution) {
    folder_.write("scene.json", radiosityScene(kQuickSolve).dump());
    LancerProcess lancer(withWindow(quickRender("out.png")), folder_.path());
    const X11Window window = findWindow();

    // While it solves, the title gives the phase, the shots and the power left, and the window
    // shows previews of the solution as it stands (the scene's lights light it at once).
    bool sawProgress = false, sawPreview = false;
    const auto deadline = std::chrono::steady_clock::now() + kWait;
    std::string title;
    while ((title = window.title()).find("done") == std::string::npos &&
           std::chrono::steady_clock::now() < deadline) {
        if (title.find("radiosity: shooting") != std::string::npos) {
            sawProgress = true;
            EXPECT_NE(title.find(" shots, unshot "), std::string::npos) << title;
            const Image shown = window.screenshot();
            sawPreview |= std::any_of(shown.pixels.begin(), shown.pixels.end(),
                                      [](const Image::Rgb& p) { return p[0] + p[1] + p[2] > 0; });
        }
        std::this_thread::sleep_for(10ms);
    }
    EXPECT_TRUE(sawProgress) << "the title showed the solve";
    EXPECT_TRUE(sawPreview) << "the window showed the solution as it stood";
    ASSERT_TRUE(window.waitForTitle("done", kWait)) << "title: " << window.title();
    ASSERT_TRUE(fs::exists(folder_ / "out.png"));
    EXPECT_EQ(maxAbsoluteDifference(window.screenshot(), loadImage(folder_ / "out.png")), 0)
        << "the window ends on the saved image";

    window.close();
    const RunResult run = lancer.wait(kWait);
    EXPECT_EQ(run.exitStatus, 0) << run;
    EXPECT_NE(run.standardError.find("lancer: radiosity: "), std::string::npos) << run;
    EXPECT_EQ(folder_.entries(), (std::vector<std::string>{"out.png", "scene.json"}));

    // The same solution and image as without the window, bit for bit.
    const RunResult plain = runLancer(quickRender("plain.png"), folder_.path());
    ASSERT_EQ(plain.exitStatus, 0) << plain;
    EXPECT_EQ(readFile(folder_ / "plain.png"), readFile(folder_ / "out.png"));
}

class StoppedMidSolve : public LiveWindow, public testing::WithParamInterface<Stop> {};

TEST_P(StoppedMidSolve, WritesNothingAndExits130) {
    folder_.write("scene.json", radiosityScene(kLongSolve).dump());
    LancerProcess lancer(withWindow(quickRender("out.png")), folder_.path());
    const X11Window window = findWindow();
    ASSERT_TRUE(window.waitForTitle("radiosity: shooting", kWait)) << "title: " << window.title();

    const auto stopped = std::chrono::steady_clock::now();
    stop(GetParam(), window, lancer);
    const RunResult run = lancer.wait(kWait);
    // The solver stops between shots (each a few milliseconds, more under sanitizers).
    EXPECT_LT(std::chrono::steady_clock::now() - stopped, 5s);

    EXPECT_EQ(run.exitStatus, 130) << run;
    EXPECT_EQ(run.errorLines(), (std::vector<std::string>{"lancer: interrupted during the "
                                                          "radiosity solve; nothing was written"}))
        << run;
    EXPECT_EQ(folder_.entries(), (std::vector<std::string>{"scene.json"}));
}

INSTANTIATE_TEST_SUITE_P(LiveWindow, StoppedMidSolve,
                         testing::Values(Stop::ClosingTheWindow, Stop::Escape, Stop::CtrlC),
                         [](const testing::TestParamInfo<Stop>& test) {
                             return nameOf(test.param);
                         });

TEST_F(LiveWindow, DraggingOrbitsAndTheWheelZoomsWithoutTouchingTheOutput) {
    LancerProcess lancer(withWindow(quickRender("out.png", 64, 48)), folder_.path());
    const X11Window window = findWindow();
    ASSERT_TRUE(window.waitForTitle("done", kWait)) << "title: " << window.title();
    const std::string output = readFile(folder_ / "out.png");
    const Image before = window.screenshot();

    // The view changes, and settles on a new complete render.
    const auto changedFrom = [&](const Image& previous) {
        const auto deadline = std::chrono::steady_clock::now() + kWait;
        while (std::chrono::steady_clock::now() < deadline) {
            if (window.title().find("done") != std::string::npos &&
                meanAbsoluteDifference(window.screenshot(), previous) > 2)
                return true;
            std::this_thread::sleep_for(20ms);
        }
        return false;
    };
    window.drag(16, 24, 48, 30);
    ASSERT_TRUE(changedFrom(before)) << "title: " << window.title();
    const Image orbited = window.screenshot();
    window.scroll(32, 24, 3);
    EXPECT_TRUE(changedFrom(orbited)) << "title: " << window.title();

    window.close();
    const RunResult run = lancer.wait(kWait);
    EXPECT_EQ(run.exitStatus, 0) << run;
    EXPECT_EQ(readFile(folder_ / "out.png"), output) << "the output is the scene camera's render";
}

TEST_F(LiveWindow, AnImageLargerThanTheScreenGetsAWindowScaledDownToFit) {
    LancerProcess lancer(withWindow(quickRender("out.png", 1000, 125)), folder_.path());
    const X11Window window = findWindow();
    EXPECT_EQ(window.width(), kScreenWidth);
    EXPECT_NEAR(static_cast<double>(window.width()) / window.height(), 8.0, 0.1)
        << window.width() << "x" << window.height();
    ASSERT_TRUE(window.waitForTitle("done", kWait)) << "title: " << window.title();
    window.close();
    const RunResult run = lancer.wait(kWait);
    EXPECT_EQ(run.exitStatus, 0) << run;
    EXPECT_EQ(loadImage(folder_ / "out.png").width, 1000) << "the image keeps its size";
}

// An environment variable that lancer inherits set to `value` (unset for nullptr) until the end of
// the scope, then as it was.
class ScopedEnvironment {
public:
    ScopedEnvironment(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        set(value);
    }
    ~ScopedEnvironment() { set(old_ ? old_->c_str() : nullptr); }
    ScopedEnvironment(const ScopedEnvironment&) = delete;
    ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

private:
    void set(const char* value) const {
        if (value)
            setenv(name_.c_str(), value, 1);
        else
            unsetenv(name_.c_str());
    }

    std::string name_;
    std::optional<std::string> old_;
};

// A --window run that could not open its window: it ends well with one warning, which says
// `warning`, and the image of the same render without --window.
void expectOneWarningAndTheSameImage(const RunResult& windowed, const TempFolder& folder,
                                     const std::string& warning) {
    EXPECT_EQ(windowed.exitStatus, 0) << windowed;
    const std::vector<std::string> lines = windowed.errorLines();
    ASSERT_EQ(std::count_if(lines.begin(), lines.end(),
                            [](const std::string& l) { return l.find("warning") != l.npos; }),
              1)
        << windowed;
    EXPECT_NE(windowed.standardError.find(warning), std::string::npos) << windowed;
    const RunResult plain = runLancer(quickRender("plain.png"), folder.path());
    ASSERT_EQ(plain.exitStatus, 0) << plain;
    EXPECT_EQ(readFile(folder / "window.png"), readFile(folder / "plain.png"));
}

TEST(WindowWithoutDisplay, WarnsOnceAndRendersTheSameImage) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    RunResult windowed;
    {
        // Whatever the test runner has, lancer gets no display at all.
        const ScopedEnvironment noDisplay("DISPLAY", nullptr);
        const ScopedEnvironment noWayland("WAYLAND_DISPLAY", nullptr);
        windowed = runLancer(withWindow(quickRender("window.png")), folder.path());
    }
    expectOneWarningAndTheSameImage(windowed, folder, "--window");
}

// SDL2 and its libraries (X11, Wayland, audio) are loaded only when a window is asked for (or
// lancer --version names its version): they would double the start-up of every other run. The
// dynamic loader's own log (glibc's LD_DEBUG) says which libraries a run loaded.
TEST(WindowLibrary, IsLoadedOnlyWhenAWindowIsAskedFor) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    RunResult plain, windowed, version;
    {
        // The window is asked for, not opened: the library is loaded all the same.
        const ScopedEnvironment noDisplay("DISPLAY", nullptr);
        const ScopedEnvironment loaderLog("LD_DEBUG", "files");
        plain = runLancer(quickRender("plain.png"), folder.path());
        windowed = runLancer(withWindow(quickRender("window.png")), folder.path());
        version = runLancer({"--version"}, folder.path());
    }

    ASSERT_EQ(plain.exitStatus, 0) << plain;
    if (plain.standardError.find("libfreeimage") == std::string::npos)
        GTEST_SKIP() << "the dynamic loader does not log the libraries it loads (LD_DEBUG)";
    EXPECT_EQ(plain.standardError.find("libSDL2"), std::string::npos) << plain;
    EXPECT_NE(windowed.standardError.find("libSDL2"), std::string::npos) << windowed;
    EXPECT_NE(version.standardError.find("libSDL2"), std::string::npos) << version;
    EXPECT_NE(version.standardOutput.find("SDL2 2."), std::string::npos) << version;
}

// Without a usable SDL2 library (here a damaged one found first), --window warns once and the
// image is rendered as without it: the library is looked for only then, and its absence is not an
// error.
TEST(WindowLibrary, AMissingLibraryIsAWarningAndTheSameImage) {
    const TempFolder folder;
    folder.write("scene.json", loadWhittedScene().dump());
    folder.write("libs/libSDL2-2.0.so.0", "not a library");
    RunResult windowed;
    {
        const ScopedEnvironment damagedFirst("LD_LIBRARY_PATH", (folder / "libs").c_str());
        windowed = runLancer(withWindow(quickRender("window.png")), folder.path());
    }
    expectOneWarningAndTheSameImage(windowed, folder, "warning: --window: cannot load SDL2");
}

}  // namespace
}  // namespace lancer::test
