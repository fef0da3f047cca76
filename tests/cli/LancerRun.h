#pragma once

// The vocabulary of the end-to-end tests: run the lancer program in a fresh folder, capture how it
// ended, and read back the images it wrote.

#include <gtest/gtest.h>
#include <array>
#include <chrono>
#include <filesystem>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "TempFolder.h"

namespace lancer::test {

namespace fs = std::filesystem;

// The bytes of a file; throws std::runtime_error when it cannot be read.
std::string readFile(const fs::path& path);

// How a run of lancer ended.
struct RunResult {
    int exitStatus = -1;         // the exit code, or -1 when the process did not exit by itself
    int terminatingSignal = 0;   // the signal that killed it, if one did
    bool timedOut = false;       // killed by the test for running too long
    std::string standardOutput;  // what it printed
    std::string standardError;
    long peakMemoryKilobytes = 0;  // the most resident memory the process had (not on Windows)

    // standardError cut into lines (without their '\n').
    std::vector<std::string> errorLines() const;
};
std::ostream& operator<<(std::ostream& out, const RunResult& run);

// Long enough for any render of this suite under AddressSanitizer with another test running beside
// it on CI's two cores; a run that takes longer is a hang (or a render that should never have
// started). The slowest, radiosity through a glossy floor at 256 spp, takes 37 s alone under
// AddressSanitizer and once went past 60 s beside another test.
constexpr std::chrono::seconds kRunTimeout{120};

// Runs lancer with `arguments` in `workingFolder` and waits for it to end.
RunResult runLancer(const std::vector<std::string>& arguments, const fs::path& workingFolder,
                    std::chrono::milliseconds timeout = kRunTimeout);

#ifndef _WIN32
// The argument vector of a lancer child process, built before fork(): after it, only
// async-signal-safe calls are allowed.
class LancerArguments {
public:
    // `program` runs with `arguments`: lancer, or a launcher such as mpirun given lancer's path.
    explicit LancerArguments(const std::vector<std::string>& arguments,
                             const std::string& program = LANCER_EXE);
    // The pointers point into this object.
    LancerArguments(const LancerArguments&) = delete;
    LancerArguments& operator=(const LancerArguments&) = delete;

    // For execv(): the program, then the arguments, then null.
    char* const* argv() { return pointers_.data(); }

private:
    std::vector<std::string> strings_;
    std::vector<char*> pointers_;
};

// A lancer process running in the background, for tests that signal it while it works.
class LancerProcess {
public:
    // `fileSizeLimit` (bytes, 0 for none) bounds the files lancer may write (RLIMIT_FSIZE): a
    // write past it fails as on a full disk.
    LancerProcess(const std::vector<std::string>& arguments, const fs::path& workingFolder,
                  std::size_t fileSizeLimit = 0, const std::string& program = LANCER_EXE);
    int pid() const { return pid_; }
    ~LancerProcess();  // kills the process if it is still running
    LancerProcess(const LancerProcess&) = delete;
    LancerProcess& operator=(const LancerProcess&) = delete;

    // Sends `signal` unless the process has ended.
    void sendSignal(int signal) const;
    // Whether the process has ended (then wait() returns at once), without waiting.
    bool hasEnded();
    // Waits for the process to end; after `timeout` it is killed and the result says timedOut.
    RunResult wait(std::chrono::milliseconds timeout = kRunTimeout);

private:
    TempFolder captureFolder_;  // its standard output and error, kept out of the working folder
    int pid_ = -1;
    bool ended_ = false;
    int status_ = 0;  // waitpid's, once ended
    long peakMemoryKilobytes_ = 0;
};
#endif

// A decoded image, rows top-down as in lancer's film (FreeImage stores them bottom-up).
struct Image {
    using Rgb = std::array<float, 3>;
    // Float images hold linear radiance; 8-bit images hold the stored values 0..255.
    enum class Encoding { LinearFloat, EightBit };

    int width = 0;
    int height = 0;
    Encoding encoding = Encoding::LinearFloat;
    std::vector<Rgb> pixels;

    const Rgb& at(int x, int y) const { return pixels[static_cast<std::size_t>(y * width + x)]; }
};

// Loads an image in any format FreeImage reads (PFM by our own reading of the netpbm
// definition, as FreeImage gets its row order wrong); throws std::runtime_error when it cannot.
Image loadImage(const fs::path& path);

// The image averaged over blocks of block x block pixels.
Image blockAverage(const Image& image, int block);
// The mean over all pixels and channels.
double meanValue(const Image& image);
// The error measure of the comparisons with Mitsuba (the benchmark's too): the root mean square
// of the difference over all pixels and channels, relative to the reference's mean value.
double relativeRmse(const Image& image, const Image& reference);
// The largest |a - b| over all channels of two images of the same size.
double maxAbsoluteDifference(const Image& a, const Image& b);
// The mean |a - b| over all channels.
double meanAbsoluteDifference(const Image& a, const Image& b);
// The fraction of pixels whose every channel satisfies |a - b| <= absolute + relative * |b|.
double fractionOfPixelsWithin(const Image& a, const Image& b, double absolute, double relative);

// A render's output file: its bytes and its decoded image.
struct RenderedFile {
    std::string bytes;
    Image image;
};

// Writes `scene` as scene.json in a fresh folder, runs `lancer scene.json -o OUTPUT --quiet
// OPTIONS` there and reads the output back. Throws std::runtime_error (with lancer's message) when
// the run fails, which fails the calling test.
RenderedFile renderScene(const nlohmann::json& scene, const std::vector<std::string>& options = {},
                         const std::string& outputName = "out.pfm");
// The same for a scene file left where it is (its relative model and texture paths resolve).
RenderedFile renderSceneFile(const fs::path& scenePath,
                             const std::vector<std::string>& options = {},
                             const std::string& outputName = "out.pfm");

// Names the tests of a parameterized suite after the `name` member of their cases.
struct CaseName {
    template <typename Case>
    std::string operator()(const testing::TestParamInfo<Case>& test) const {
        return test.param.name;
    }
};

// scenes/whitted.json of the source tree, parsed (comments allowed).
nlohmann::json loadWhittedScene();
// The same in 3 frames: the glass ball (named "ball") moves from x - 1 to x + 1 and the camera
// rises from y = 1.5 to 2.5, linearly, so that frame 2 is exactly halfway.
nlohmann::json animatedWhittedScene();

// An orthographic camera 2 units high looking straight down (-y) at (x, 0, z) from y = height
// (below the plane when negative: then looking up), -z at the top of the image, +x to the right
// when looking down: the tests of floors whose uv are the world's (x, z).
nlohmann::json cameraAlongY(double x, double z, double height);

}  // namespace lancer::test
