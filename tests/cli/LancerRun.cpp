#include "LancerRun.h"

#include <FreeImage.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#ifndef _WIN32
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#else
#include <cstdlib>
#endif

namespace lancer::test {

// --- folders and files ---

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// --- running lancer ---

std::vector<std::string> RunResult::errorLines() const {
    std::vector<std::string> lines;
    std::istringstream in(standardError);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

std::ostream& operator<<(std::ostream& out, const RunResult& run) {
    out << "exit status " << run.exitStatus;
    if (run.terminatingSignal) out << ", killed by signal " << run.terminatingSignal;
    if (run.timedOut) out << ", timed out";
    return out << ", stderr:\n" << run.standardError;
}

#ifndef _WIN32

LancerArguments::LancerArguments(const std::vector<std::string>& arguments,
                                 const std::string& program)
    : strings_{program} {
    strings_.insert(strings_.end(), arguments.begin(), arguments.end());
    for (std::string& argument : strings_)
        pointers_.push_back(argument.data());
    pointers_.push_back(nullptr);
}

LancerProcess::LancerProcess(const std::vector<std::string>& arguments,
                             const fs::path& workingFolder, std::size_t fileSizeLimit,
                             const std::string& program) {
    // Everything the child needs is prepared before fork(): after it, only async-signal-safe
    // calls are allowed.
    LancerArguments argv(arguments, program);
    const std::string folder = workingFolder.string();
    const std::string stdoutPath = (captureFolder_ / "stdout").string();
    const std::string stderrPath = (captureFolder_ / "stderr").string();

    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
        const int out = open(stdoutPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = open(stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (out < 0 || err < 0 || dup2(out, STDOUT_FILENO) < 0 || dup2(err, STDERR_FILENO) < 0 ||
            chdir(folder.c_str()) != 0)
            _exit(127);
        // Whatever the test runner does with Ctrl-C, lancer starts with the default action.
        signal(SIGINT, SIG_DFL);
        const rlimit fileSize{fileSizeLimit, fileSizeLimit};
        if (fileSizeLimit > 0 && setrlimit(RLIMIT_FSIZE, &fileSize) != 0) _exit(127);
        execv(argv.argv()[0], argv.argv());
        _exit(127);
    }
}

LancerProcess::~LancerProcess() {
    if (pid_ > 0 && !ended_) {
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
    }
}

void LancerProcess::sendSignal(int signal) const {
    // Until reaped (which sets ended_), an ended process keeps its number.
    if (pid_ > 0 && !ended_) kill(pid_, signal);
}

bool LancerProcess::hasEnded() {
    if (ended_ || pid_ <= 0) return ended_;
    rusage usage{};
    const pid_t done = wait4(pid_, &status_, WNOHANG, &usage);
    if (done < 0) throw std::runtime_error("wait4 failed");
    ended_ = done == pid_;
    if (ended_) peakMemoryKilobytes_ = usage.ru_maxrss;
    return ended_;
}

RunResult LancerProcess::wait(std::chrono::milliseconds timeout) {
    RunResult result;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!hasEnded()) {
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid_, SIGKILL);
            waitpid(pid_, &status_, 0);
            ended_ = true;
            result.timedOut = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    pid_ = -1;
    const int status = status_;
    result.peakMemoryKilobytes = peakMemoryKilobytes_;
    if (WIFEXITED(status)) result.exitStatus = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.terminatingSignal = WTERMSIG(status);
    result.standardOutput = readFile(captureFolder_ / "stdout");
    result.standardError = readFile(captureFolder_ / "stderr");
    return result;
}

RunResult runLancer(const std::vector<std::string>& arguments, const fs::path& workingFolder,
                    std::chrono::milliseconds timeout) {
    return LancerProcess(arguments, workingFolder).wait(timeout);
}

#else

// Windows: through the shell, without a timeout.
RunResult runLancer(const std::vector<std::string>& arguments, const fs::path& workingFolder,
                    std::chrono::milliseconds) {
    const TempFolder captureFolder;
    const auto quoted = [](const std::string& s) { return "\"" + s + "\""; };
    std::string command = "cd /d " + quoted(workingFolder.string()) + " && " + quoted(LANCER_EXE);
    for (const std::string& argument : arguments)
        command += " " + quoted(argument);
    command += " > " + quoted((captureFolder / "stdout").string()) + " 2> " +
               quoted((captureFolder / "stderr").string());
    RunResult result;
    // cmd.exe drops the outer quotes of a command line that starts with one.
    result.exitStatus = std::system(quoted(command).c_str());
    result.standardOutput = readFile(captureFolder / "stdout");
    result.standardError = readFile(captureFolder / "stderr");
    return result;
}

#endif

// --- images ---

namespace {

struct BitmapDeleter {
    void operator()(FIBITMAP* bitmap) const { FreeImage_Unload(bitmap); }
};
using Bitmap = std::unique_ptr<FIBITMAP, BitmapDeleter>;

// FreeImage reports why a load failed through a global callback; the last message goes into our
// error.
std::string lastFreeImageMessage;
void recordFreeImageMessage(FREE_IMAGE_FORMAT, const char* message) {
    lastFreeImageMessage = message ? message : "";
}

}  // namespace

namespace {

// A PFM file read by the netpbm definition, independently of FreeImage: "PF" (RGB) or "Pf"
// (grey), width and height, a scale whose sign gives the byte order (negative: little-endian),
// then the rows of 32-bit floats, the BOTTOM row first.
Image loadPfm(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    double scale = 0;
    Image image;
    if (!(in >> magic >> image.width >> image.height >> scale) ||
        (magic != "PF" && magic != "Pf") || image.width <= 0 || image.height <= 0 || scale >= 0)
        throw std::runtime_error(path.string() + ": not a little-endian PFM file");
    in.get();  // the single whitespace character that ends the header
    const int channels = magic == "PF" ? 3 : 1;
    std::vector<float> values(static_cast<std::size_t>(image.width * image.height * channels));
    if (!in.read(reinterpret_cast<char*>(values.data()),
                 static_cast<std::streamsize>(values.size() * sizeof(float))))
        throw std::runtime_error(path.string() + ": PFM file shorter than its header says");
    image.pixels.resize(static_cast<std::size_t>(image.width * image.height));
    for (int row = 0; row < image.height; ++row)
        for (int x = 0; x < image.width; ++x) {
            const float* v = &values[static_cast<std::size_t>((row * image.width + x) * channels)];
            const int y = image.height - 1 - row;
            image.pixels[static_cast<std::size_t>(y * image.width + x)] =
                channels == 3 ? Image::Rgb{v[0], v[1], v[2]} : Image::Rgb{v[0], v[0], v[0]};
        }
    return image;
}

}  // namespace

Image loadImage(const fs::path& path) {
    if (path.extension() == ".pfm") return loadPfm(path);
    FreeImage_SetOutputMessage(recordFreeImageMessage);
    lastFreeImageMessage.clear();
    const std::string name = path.string();
    const FREE_IMAGE_FORMAT format = FreeImage_GetFileType(name.c_str(), 0);
    if (format == FIF_UNKNOWN) throw std::runtime_error(name + ": not an image FreeImage knows");
    const Bitmap loaded(FreeImage_Load(format, name.c_str(), 0));
    if (!loaded)
        throw std::runtime_error(name + ": FreeImage cannot load it (" + lastFreeImageMessage +
                                 ")");

    Image image;
    image.width = static_cast<int>(FreeImage_GetWidth(loaded.get()));
    image.height = static_cast<int>(FreeImage_GetHeight(loaded.get()));
    image.pixels.resize(static_cast<std::size_t>(image.width) *
                        static_cast<std::size_t>(image.height));
    const bool isFloat = FreeImage_GetImageType(loaded.get()) != FIT_BITMAP;
    image.encoding = isFloat ? Image::Encoding::LinearFloat : Image::Encoding::EightBit;
    const Bitmap rgb(isFloat ? FreeImage_ConvertToRGBF(loaded.get())
                             : FreeImage_ConvertTo24Bits(loaded.get()));
    if (!rgb) throw std::runtime_error(name + ": cannot convert to RGB");

    for (int y = 0; y < image.height; ++y) {
        // Scanline 0 is the bottom row.
        BYTE* scanline = FreeImage_GetScanLine(rgb.get(), image.height - 1 - y);
        for (int x = 0; x < image.width; ++x) {
            Image::Rgb& pixel = image.pixels[static_cast<std::size_t>(y * image.width + x)];
            if (isFloat) {
                const FIRGBF& p = reinterpret_cast<const FIRGBF*>(scanline)[x];
                pixel = {p.red, p.green, p.blue};
            } else {
                const BYTE* p = scanline + 3 * x;
                pixel = {float(p[FI_RGBA_RED]), float(p[FI_RGBA_GREEN]), float(p[FI_RGBA_BLUE])};
            }
        }
    }
    return image;
}

namespace {

void requireSameSize(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::runtime_error("images of different sizes: " + std::to_string(a.width) + "x" +
                                 std::to_string(a.height) + " and " + std::to_string(b.width) +
                                 "x" + std::to_string(b.height));
}

}  // namespace

Image blockAverage(const Image& image, int block) {
    Image out;
    out.width = image.width / block;
    out.height = image.height / block;
    out.pixels.assign(static_cast<std::size_t>(out.width * out.height), {0, 0, 0});
    for (int y = 0; y < out.height * block; ++y)
        for (int x = 0; x < out.width * block; ++x)
            for (int c = 0; c < 3; ++c)
                out.pixels[static_cast<std::size_t>((y / block) * out.width + x / block)]
                          [static_cast<std::size_t>(c)] +=
                    image.at(x, y)[static_cast<std::size_t>(c)] / static_cast<float>(block * block);
    return out;
}

double meanValue(const Image& image) {
    double sum = 0;
    for (const Image::Rgb& p : image.pixels)
        sum += p[0] + p[1] + p[2];
    return sum / (3.0 * static_cast<double>(image.pixels.size()));
}

double relativeRmse(const Image& image, const Image& reference) {
    requireSameSize(image, reference);
    double sum = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c) {
            const double d = image.pixels[i][c] - reference.pixels[i][c];
            sum += d * d;
        }
    return std::sqrt(sum / (3.0 * static_cast<double>(image.pixels.size()))) / meanValue(reference);
}

double maxAbsoluteDifference(const Image& a, const Image& b) {
    requireSameSize(a, b);
    double largest = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c)
            largest = std::max(largest, std::abs(double(a.pixels[i][c]) - b.pixels[i][c]));
    return largest;
}

double meanAbsoluteDifference(const Image& a, const Image& b) {
    requireSameSize(a, b);
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c)
            sum += std::abs(double(a.pixels[i][c]) - b.pixels[i][c]);
    return sum / (3.0 * static_cast<double>(a.pixels.size()));
}

double fractionOfPixelsWithin(const Image& a, const Image& b, double absolute, double relative) {
    requireSameSize(a, b);
    std::size_t within = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        bool close = true;
        for (std::size_t c = 0; c < 3; ++c)
            close = close && std::abs(double(a.pixels[i][c]) - b.pixels[i][c]) <=
                                 absolute + relative * std::abs(double(b.pixels[i][c]));
        within += close ? 1 : 0;
    }
    return static_cast<double>(within) / static_cast<double>(a.pixels.size());
}

// --- rendering ---

namespace {

// Runs `lancer SCENE -o OUTPUT --quiet OPTIONS` in `folder` and reads the output back.
RenderedFile renderIn(const TempFolder& folder, const std::string& scene,
                      const std::vector<std::string>& options, const std::string& outputName) {
    std::vector<std::string> arguments{scene, "-o", outputName, "--quiet"};
    arguments.insert(arguments.end(), options.begin(), options.end());
    const RunResult run = runLancer(arguments, folder.path());
    if (run.exitStatus != 0) {
        std::ostringstream message;
        message << "lancer failed to render: " << run;
        throw std::runtime_error(message.str());
    }
    return {readFile(folder / outputName), loadImage(folder / outputName)};
}

}  // namespace

RenderedFile renderScene(const nlohmann::json& scene, const std::vector<std::string>& options,
                         const std::string& outputName) {
    const TempFolder folder;
    folder.write("scene.json", scene.dump(2));
    return renderIn(folder, "scene.json", options, outputName);
}

RenderedFile renderSceneFile(const fs::path& scenePath, const std::vector<std::string>& options,
                             const std::string& outputName) {
    const TempFolder folder;
    return renderIn(folder, fs::absolute(scenePath).string(), options, outputName);
}

nlohmann::json loadWhittedScene() {
    return nlohmann::json::parse(readFile(fs::path(LANCER_SOURCE_DIR) / "scenes/whitted.json"),
                                 nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
}

nlohmann::json animatedWhittedScene() {
    nlohmann::json scene = loadWhittedScene();
    scene["objects"][2]["name"] = "ball";
    scene["animation"] = {
        {"frames", 3},
        {"camera",
         {{{"frame", 1}, {"position", {0, 1.5, 7}}}, {{"frame", 3}, {"position", {0, 2.5, 7}}}}},
        {"objects",
         {{"ball",
           {{{"frame", 1}, {"transform", {{"translate", {-1, 0, 0}}}}},
            {{"frame", 3}, {"transform", {{"translate", {1, 0, 0}}}}}}}}}};
    return scene;
}

nlohmann::json cameraAlongY(double x, double z, double height) {
    return {{"type", "orthographic"},
            {"position", {x, height, z}},
            {"look_at", {x, 0, z}},
            {"up", {0, 0, -1}},
            {"height", 2}};
}

}  // namespace lancer::test
