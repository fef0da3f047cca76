// lancer: renders a scene file to an image. See docs/SCENE-FORMAT.md for the contract.

#include <unistd.h>

#include <tbb/global_control.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "BuildInfo.h"
#include "InterruptSignals.h"
#include "LiveRender.h"
#include "LiveSolve.h"
#include "ProgressBar.h"
#include "TerminalSolve.h"
#include "Viewer.h"
#include "cluster/Cluster.h"
#include "integrators/IntegratorRegistry.h"
#include "io/Fingerprint.h"
#include "io/ImageWriter.h"
#include "io/InputFile.h"
#include "io/ModelCache.h"
#include "io/ResumeFile.h"
#include "io/SceneLoader.h"
#include "radiosity/RadiositySolver.h"
#include "render/Aov.h"
#include "render/Renderer.h"
#include "render/ToneMapper.h"
#include "scene/InputError.h"
#include "scene/RenderSettings.h"
#include "util/DidYouMean.h"
#include "util/Registry.h"

namespace fs = std::filesystem;
using namespace lancer;

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;

struct Options {
    std::string scene;
    std::string output;
    std::optional<int> width, height, spp, maxDepth, lightEdgeFactor;
    std::optional<float> adcBailout;
    std::optional<std::string> integrator;
    int threads = 0;
    std::uint64_t seed = 0;
    std::optional<std::string> crop;
    std::optional<std::string> frames;  // --frames' range
    std::optional<std::string> aovs;    // --aov's list
    bool window = false;
    bool quiet = false;
    bool stats = false;
    bool resume = false;
    std::optional<std::string> saveRadiosity, loadRadiosity;
    std::optional<std::string> maxMemory;
    std::optional<std::string> modelCache;  // --model-cache's folder
    bool noModelCache = false;
};

int fail(int status, const std::string& message) {
    std::cerr << message << '\n';
    return status;
}

int usageError(const std::string& message) {
    return fail(kExitBadInput, "lancer: error: " + message);
}

// "X0,Y0,X1,Y1", inclusive-exclusive, inside the image.
std::optional<PixelWindow> parseCrop(const std::string& text, int width, int height,
                                     std::string& error) {
    PixelWindow w;
    char c1 = 0, c2 = 0, c3 = 0;
    std::istringstream in(text);
    if (!(in >> w.x0 >> c1 >> w.y0 >> c2 >> w.x1 >> c3 >> w.y1) || c1 != ',' || c2 != ',' ||
        c3 != ',' || !(in >> std::ws).eof()) {
        error = "--crop \"" + text + "\": expected X0,Y0,X1,Y1 (four whole numbers)";
        return std::nullopt;
    }
    if (w.x0 < 0 || w.y0 < 0 || w.x1 > width || w.y1 > height || w.x0 >= w.x1 || w.y0 >= w.y1) {
        error = "--crop " + text +
                ": the window must satisfy 0 <= X0 < X1 <= " + std::to_string(width) +
                " and 0 <= Y0 < Y1 <= " + std::to_string(height);
        return std::nullopt;
    }
    return w;
}

// The frames --frames asks for, "A:B" or "A"; their range is checked against the animation's
// frames by checkFrames.
struct FrameRange {
    int first, last;
};
std::optional<FrameRange> parseFrames(const std::string& text, std::string& error) {
    FrameRange range{};
    char colon = 0;
    std::istringstream in(text);
    bool read = static_cast<bool>(in >> range.first);
    if (read && !(in >> std::ws).eof())
        read = (in >> colon >> range.last) && colon == ':';
    else
        range.last = range.first;
    if (!read || !(in >> std::ws).eof()) {
        error = "--frames \"" + text + "\": expected A:B or A (frame numbers, from 1)";
        return std::nullopt;
    }
    return range;
}

// The error of a range of --frames (`text`) outside an animation's `frames`, if it is.
std::optional<std::string> checkFrames(const FrameRange& range, const std::string& text,
                                       int frames) {
    if (range.first >= 1 && range.first <= range.last && range.last <= frames) return std::nullopt;
    return "--frames " + text +
           ": the frames must satisfy 1 <= A <= B <= " + std::to_string(frames) +
           " (the animation's frames)";
}

// The model cache that the options ask for (by default, the user's cache folder), or none. Its
// entries are this executable's: a rebuilt lancer makes its own (its layout or trees may differ).
std::optional<ModelCache> modelCacheOf(const Options& options) {
    if (options.noModelCache) return std::nullopt;
    const std::optional<fs::path> folder =
        options.modelCache ? fs::path(*options.modelCache) : ModelCache::defaultFolder();
    if (!folder) return std::nullopt;
    std::error_code error;
    const fs::path self = fs::read_symlink("/proc/self/exe", error);  // Linux's own path to it
    std::string identity = LANCER_VERSION;
    if (!error) identity += " " + std::to_string(Fingerprint().addFile(self).value());
    return ModelCache(*folder, identity);
}

// The output of an animation's frame: OUT-0001.EXT for frame 1 of OUT.EXT.
fs::path numberedOutput(const fs::path& output, int frame) {
    char number[16];
    std::snprintf(number, sizeof number, "-%04d", frame);
    return output.parent_path() / (output.stem().string() + number + output.extension().string());
}

// For an argument CLI11 did not expect: the first unknown option, with the valid ones and a
// suggestion, as the scene loader gives for a key; CLI11's own message for a stray argument.
std::string unexpectedArguments(const CLI::App& app, int argc, char** argv,
                                const CLI::ExtrasError& error) {
    std::vector<std::string> names;    // the options, then the other names they may be known by
    std::vector<std::string> meaning;  // the option each of `names` stands for
    std::vector<std::string> valid;
    for (const CLI::Option* option : app.get_options()) {
        for (const std::string& name : option->get_lnames()) {
            names.push_back("--" + name);
            meaning.push_back("--" + name);
            valid.push_back("--" + name);
        }
    }
    // What other renderers call some of the options, to suggest ours.
    for (const auto& [alias, option] : std::initializer_list<std::pair<const char*, const char*>>{
             {"--samples", "--spp"}, {"--depth", "--max-depth"}, {"--jobs", "--threads"}}) {
        names.emplace_back(alias);
        meaning.emplace_back(option);
    }
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument.size() < 2 || argument[0] != '-') continue;
        const std::string name = argument.substr(0, argument.find('='));
        if (app.get_option_no_throw(name)) continue;
        const std::optional<std::size_t> nearest = nearestName(name, names);
        return "unknown option \"" + name + "\"" +
               (nearest ? " (did you mean \"" + meaning[*nearest] + "\"?)" : "") + "; expected " +
               quotedNames(valid);
    }
    return std::string(error.what()) + " (see lancer --help)";
}

// The memory the image's buffers take, in bytes: the render's film and what the writer needs, and
// the same for each auxiliary output; with the window, also its preview film, its own copy and
// the 8-bit pixels it shows (ours and SDL's); when resuming, the resumed render's films.
std::uint64_t imageMemory(const RenderSettings& settings, const fs::path& output,
                          const std::vector<const Aov*>& aovs, bool window, bool resume) {
    const std::uint64_t pixels =
        static_cast<std::uint64_t>(settings.width) * static_cast<std::uint64_t>(settings.height);
    std::uint64_t bytes =
        pixels * sizeof(Color) + ImageWriter::memoryNeeded(output, settings.width, settings.height);
    for (const Aov* aov : aovs)
        bytes +=
            pixels * sizeof(Color) +
            ImageWriter::memoryNeeded(aov->pathBeside(output), settings.width, settings.height);
    if (window) bytes += pixels * (2 * sizeof(Color) + 2 * 3);
    if (resume) bytes += pixels * sizeof(Color) * (1 + aovs.size());
    return bytes;
}

// The machine's memory in bytes, or 0 when unknown.
std::uint64_t physicalMemory() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0
               ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize)
               : 0;
}

// "38.7 GB", or "12.0 MB" below a gigabyte.
std::string memorySize(std::uint64_t bytes) {
    const bool gigabytes = bytes >= 1000000000;
    char text[32];
    std::snprintf(text, sizeof text, gigabytes ? "%.1f GB" : "%.1f MB",
                  static_cast<double>(bytes) / (gigabytes ? 1e9 : 1e6));
    return text;
}

// A size as --max-memory takes it, in bytes: a whole or decimal number of bytes, or of kilo-,
// mega-, giga- or terabytes with K, M, G or T (powers of 1000, as the messages count); none when
// the text is not such a size, is 0 or is beyond 2^63.
std::optional<std::uint64_t> parseMemorySize(const std::string& text) {
    // DIGITS[.DIGITS][K|M|G|T], read by hand: GCC 12 warns inside <regex> under the sanitizers.
    const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
    std::size_t end = 0;
    while (end < text.size() && isDigit(text[end]))
        ++end;
    if (end == 0) return std::nullopt;
    if (end < text.size() && text[end] == '.')
        for (++end; end < text.size() && isDigit(text[end]);)
            ++end;
    std::size_t power = 0;
    if (end < text.size()) {
        power = std::string("KMGT").find(
            static_cast<char>(std::toupper(static_cast<unsigned char>(text[end]))));
        if (power == std::string::npos || end + 1 != text.size()) return std::nullopt;
        ++power;
    }
    const double bytes = std::stod(text.substr(0, end)) * std::pow(1e3, static_cast<double>(power));
    if (!(bytes >= 1 && bytes < 0x1p63)) return std::nullopt;
    return static_cast<std::uint64_t>(bytes);
}

void printStatistics(const Scene& scene, const RenderCounters& counters) {
    const Scene::Statistics& s = scene.statistics();
    const double megabytes = static_cast<double>(s.meshBytes) / (1 << 20);
    std::fprintf(stderr, "stats: %zu objects in the BVH (%zu bytes of nodes), %zu planes\n",
                 scene.boundedShapeCount(), scene.accelerationStructureBytes(),
                 scene.unboundedShapeCount());
    std::fprintf(stderr, "stats: %zu triangles stored, %zu drawn (instances)\n", s.uniqueTriangles,
                 s.instancedTriangles);
    if (s.uniqueTriangles > 0)
        std::fprintf(
            stderr, "stats: meshes and their BVHs: %.2f MB, %.1f bytes per stored triangle\n",
            megabytes, static_cast<double>(s.meshBytes) / static_cast<double>(s.uniqueTriangles));
    const std::string cached = s.cachedModels == 0
                                   ? ""
                                   : "; " + std::to_string(s.cachedModels) +
                                         (s.cachedModels == 1 ? " model" : " models") +
                                         " taken from the model cache";
    std::fprintf(stderr, "stats: scene loaded in %.3f s (%.3f s of it building BVHs%s)\n",
                 s.loadSeconds, s.buildSeconds, cached.c_str());
    std::fprintf(stderr, "stats: %llu rays, %llu samples, %llu of them NaN or infinite (dropped)\n",
                 static_cast<unsigned long long>(counters.rays),
                 static_cast<unsigned long long>(counters.samples),
                 static_cast<unsigned long long>(counters.nonFiniteSamples));
}

// "16 spp", or with adaptive sampling the mean count actually taken and the range allowed.
std::string describeSamples(const RenderSettings& settings, const RenderCounters& counters) {
    if (!settings.adaptive) return std::to_string(settings.samplesPerPixel) + " spp";
    char text[128];
    std::snprintf(text, sizeof text, "%.1f spp on average (adaptive, %d to %d)",
                  counters.meanSamplesPerPixel(),
                  std::min(settings.adaptive->minSamples, settings.samplesPerPixel),
                  settings.samplesPerPixel);
    return text;
}

std::string describeRate(std::uint64_t rays, double seconds) {
    char text[128];
    std::snprintf(text, sizeof text, "%.2f s, %.1f M rays, %.2f Mrays/s", seconds,
                  static_cast<double>(rays) / 1e6,
                  seconds > 0 ? static_cast<double>(rays) / 1e6 / seconds : 0.0);
    return text;
}

// The solve, its progress on the terminal's bar (if stderr is one and not --quiet).
std::optional<RadiositySolution> solveOnTheTerminal(RadiositySolver& solver,
                                                    const Options& options) {
    if (options.quiet || !isatty(STDERR_FILENO))
        return solver.solve({}, &InterruptSignals::requested());
    ProgressBar progress(true);
    std::optional<RadiositySolution> solution =
        TerminalSolve(solver, progress).run(InterruptSignals::requested());
    progress.finish();
    return solution;
}

// The radiosity solution, solved or loaded (and saved if asked), reported in one line; the solve's
// progress shows in the viewer, if any, or on the terminal. None when the solve was stopped
// (Ctrl-C, or the window closed).
std::optional<RadiositySolution> prepareRadiosity(const Scene& scene, RadiositySolver& solver,
                                                  const Options& options, Viewer* viewer) {
    RadiositySolution solution;
    if (options.loadRadiosity) {
        InputFile::check(*options.loadRadiosity, "a radiosity file", "radiosity files",
                         RadiositySolution::kMaxFileBytes);
        solution = RadiositySolution::load(*options.loadRadiosity);
        if (solution.fingerprint() != solver.fingerprint())
            throw InputError(*options.loadRadiosity,
                             "this radiosity solution was solved for another scene (its geometry, "
                             "materials, lights or \"radiosity\" settings differ)");
    } else {
        std::optional<RadiositySolution> solved =
            viewer ? LiveSolve(*viewer, scene, solver, options.threads)
                         .run(InterruptSignals::requested())
                   : solveOnTheTerminal(solver, options);
        if (!solved) return std::nullopt;
        solution = std::move(*solved);
    }
    if (options.saveRadiosity) {
        InterruptSignals::setPhase(InterruptSignals::Phase::Saving);
        solution.save(*options.saveRadiosity);
        InterruptSignals::setPhase(InterruptSignals::Phase::Working);
    }
    if (!options.quiet) {
        const RadiosityStatistics& s = solution.statistics();
        std::fprintf(
            stderr,
            "lancer: radiosity%s: %llu patches, %llu elements, %s%llu shots, residual "
            "unshot power %.4g W (%.3g%% of %.4g W), solved in %.2f s\n",
            options.loadRadiosity ? (" loaded from " + *options.loadRadiosity).c_str() : "",
            static_cast<unsigned long long>(s.patches), static_cast<unsigned long long>(s.elements),
            s.links > 0 ? (std::to_string(s.links) + " links, ").c_str() : "",
            static_cast<unsigned long long>(s.shots), s.residualPower,
            s.initialPower > 0 ? 100 * s.residualPower / s.initialPower : 0.0, s.initialPower,
            s.seconds);
    }
    return solution;
}

// What the image depends on besides the work of rendering it: the program, the files the scene
// was read from and the options that change the image (not --threads, --quiet or the output's
// format: the film is saved before exposure and tone mapping).
std::uint64_t renderFingerprint(const Scene& scene, const RenderOptions& renderOptions,
                                const PixelWindow& window, const Options& options, int frame) {
    Fingerprint f;
    f.addText(BuildInfo::describeRendering());
#ifdef __linux__
    f.addFile("/proc/self/exe");
#endif
    for (const fs::path& file : scene.sourceFiles())
        f.addFile(file);
    const RenderSettings& settings = scene.settings();
    f.addNumber(static_cast<std::uint64_t>(settings.width))
        .addNumber(static_cast<std::uint64_t>(settings.height))
        .addNumber(static_cast<std::uint64_t>(settings.samplesPerPixel))
        .addNumber(static_cast<std::uint64_t>(settings.maxDepth))
        .addNumber(std::bit_cast<std::uint32_t>(settings.adcBailout))
        .addNumber(static_cast<std::uint64_t>(settings.lightEdgeFactor))
        .addText(settings.integrator)
        .addNumber(renderOptions.seed)
        .addNumber(static_cast<std::uint64_t>(frame));
    for (const int side : {window.x0, window.y0, window.x1, window.y1})
        f.addNumber(static_cast<std::uint64_t>(side));
    for (const Aov* aov : renderOptions.aovs)
        f.addText(aov->name);
    if (options.loadRadiosity) f.addFile(*options.loadRadiosity);
    return f.value();
}

// Renders `scene` (`frame` of an animation, or 0 for a still) to `output` and writes it; returns
// the exit status.
int renderImage(const Options& options, Cluster& cluster, Scene scene, const fs::path& output,
                const std::vector<const Aov*>& aovs, int frame) {
    RenderSettings& settings = scene.settings();
    if (options.width) settings.width = *options.width;
    if (options.height) settings.height = *options.height;
    if (options.spp) settings.samplesPerPixel = *options.spp;
    if (options.maxDepth) settings.maxDepth = *options.maxDepth;
    if (options.adcBailout) settings.adcBailout = *options.adcBailout;
    if (options.lightEdgeFactor) settings.lightEdgeFactor = *options.lightEdgeFactor;
    if (options.integrator) settings.integrator = *options.integrator;
    // The image's buffers are allocated before the render starts, and all at once: refuse an
    // image that cannot fit before the first of them (or the radiosity solve) takes its time.
    // --max-memory replaces the machine's memory as the bound: higher where swap makes up the
    // rest, lower to keep a render from crowding others out.
    const std::uint64_t needed =
        imageMemory(settings, output, aovs, options.window, options.resume);
    const std::uint64_t allowed =
        options.maxMemory ? *parseMemorySize(*options.maxMemory) : physicalMemory();
    if (allowed > 0 && needed > allowed)
        return usageError("a " + std::to_string(settings.width) + " x " +
                          std::to_string(settings.height) + " image needs about " +
                          memorySize(needed) + " of memory for its buffers, more than the " +
                          memorySize(allowed) +
                          (options.maxMemory ? " --max-memory allows"
                                             : " this machine has (--max-memory overrides)"));

    const ToneMapper toneMapper(settings.exposure, settings.tonemap);

    RenderOptions renderOptions;
    renderOptions.threads = options.threads;
    renderOptions.seed = options.seed;
    renderOptions.aovs = aovs;
    if (options.crop) {
        std::string error;
        renderOptions.crop = parseCrop(*options.crop, settings.width, settings.height, error);
        if (!renderOptions.crop) return usageError(error);
    }

    if ((options.saveRadiosity || options.loadRadiosity) && settings.integrator != "radiosity")
        return usageError("--save-radiosity and --load-radiosity need --integrator radiosity");

    // An interrupted render leaves its finished tiles in OUT.resume, which --resume finishes.
    const PixelWindow window =
        renderOptions.crop.value_or(PixelWindow{0, 0, settings.width, settings.height});
    const std::uint64_t fingerprint =
        renderFingerprint(scene, renderOptions, window, options, frame);
    const fs::path resumePath = ResumeFile::pathBeside(output);
    std::optional<RenderResult> resumed;
    if (options.resume) {
        if (fs::exists(resumePath)) {
            resumed = ResumeFile::read(resumePath, fingerprint, settings.width, settings.height,
                                       window, aovs.size());
            renderOptions.resumeFrom = &*resumed;
        } else if (!options.quiet && frame == 0) {
            std::cerr << "lancer: --resume: there is no " << resumePath.string()
                      << ", so the whole image is rendered\n";
        }
    }

    std::unique_ptr<Viewer> viewer;
    if (options.window) {
        std::string error;
        viewer = Viewer::open("lancer: " + fs::path(options.scene).filename().string(),
                              settings.width, settings.height, toneMapper, error);
        if (!viewer && !options.quiet)
            std::cerr << "lancer: warning: --window: " << error << "; rendering without it\n";
    }

    // From here on a signal stops the radiosity solve, then the render.
    InterruptSignals::setPhase(InterruptSignals::Phase::Working);
    std::unique_ptr<Integrator> integrator;
    try {
        IntegratorSetup setup;
        setup.radiositySolution = [&](RadiositySolver& solver) {
            return prepareRadiosity(scene, solver, options, viewer.get());
        };
        integrator = IntegratorRegistry::create(scene, setup);
    } catch (const std::invalid_argument& e) {
        return usageError(e.what());
    }
    if (!integrator) {
        // Nothing was rendered: no image is written (nor any solution), and no file is left.
        std::cerr << "lancer: interrupted during the radiosity solve; nothing was written\n";
        return InterruptSignals::exitStatus();
    }

    // Every process is ready, or all of them stop here.
    if (const int status = cluster.settle(0); status != 0) return status;

    // Writes the image and its auxiliary outputs as soon as its render ends; returns the exit
    // status.
    const auto deliver = [&](RenderResult& result, bool sceneCamera) {
        InterruptSignals::setPhase(InterruptSignals::Phase::Saving);
        // The resume file first: the films are linear until mapped for the output.
        bool resumable = false;
        if (result.interrupted && sceneCamera) {
            try {
                ResumeFile::write(resumePath, fingerprint, window, result);
                resumable = true;
            } catch (const std::runtime_error& e) {
                std::cerr << "lancer: error: " << e.what() << '\n';
            }
        }
        toneMapper.mapForOutput(result.film, ImageWriter::storesLinear(output));
        ImageWriter::write(result.film, output);
        for (std::size_t i = 0; i < aovs.size(); ++i)
            ImageWriter::write(result.aovFilms[i], aovs[i]->pathBeside(output));
        InterruptSignals::setPhase(InterruptSignals::Phase::Working);
        if (result.interrupted) {
            std::cerr << "lancer: interrupted; the part rendered so far was written to "
                      << output.string()
                      << (resumable ? " (the same command with --resume finishes it)" : "") << '\n';
            return InterruptSignals::exitStatus();
        }
        // A finished render needs its resume file no more.
        std::error_code ignored;
        fs::remove(resumePath, ignored);
        if (options.stats) printStatistics(scene, result.counters);
        if (!options.quiet)
            std::cerr << "lancer: " << output.string() << ": " << settings.width << "x"
                      << settings.height << ", " << describeSamples(settings, result.counters)
                      << ", " << result.threads
                      << (result.threads == 1 ? " thread, " : " threads, ")
                      << (result.processes > 1
                              ? "in " + std::to_string(result.processes) + " processes, "
                              : "")
                      << describeRate(result.counters.rays, result.seconds) << '\n';
        return 0;
    };

    renderOptions.cancel = &InterruptSignals::requested();
    if (viewer) {
        // The window stays open after the render, until closed; Ctrl-C closes it too.
        return LiveRender(*viewer, scene, *integrator, renderOptions, output, options.quiet)
            .run(deliver);
    }
    ProgressBar progress(!options.quiet && isatty(STDERR_FILENO));
    RenderResult result =
        cluster.render(Renderer(scene, *integrator), renderOptions, settings.width, settings.height,
                       [&](int done, int total) { progress.update(done, total); });
    progress.finish();
    if (!cluster.leader())
        return InterruptSignals::requested() ? InterruptSignals::exitStatus() : 0;
    return deliver(result, true);
}

int run(Options options, Cluster& cluster) {
    // In a cluster render the leader alone reports, reads the resume file and writes.
    if (!cluster.leader()) {
        options.quiet = true;
        options.stats = false;
        options.resume = false;
        options.saveRadiosity.reset();
    }
    if (cluster.size() > 1 && options.window)
        return usageError("--window shows one process's render: it cannot be used under mpirun (" +
                          std::to_string(cluster.size()) + " processes)");
    // Before anything is read: a signal while the scene loads ends the program cleanly.
    InterruptSignals::install();
    // Beyond the file-size limit (ulimit -f) a write fails with EFBIG, reported as a failed
    // write; the default action would kill lancer and leave its temporary file.
    std::signal(SIGXFSZ, SIG_IGN);
    // The mesh builds, the radiosity solve and the render all run on oneTBB's threads: no more
    // of them at once than --threads allows (and as many, when it asks for more than the cores).
    std::optional<tbb::global_control> threadLimit;
    if (options.threads > 0)
        threadLimit.emplace(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(options.threads));
    // Whitted ray tracing recurses once per bounce: as much stack on the workers as the main
    // thread has (oneTBB's default is half of it).
    const tbb::global_control stackSize(tbb::global_control::thread_stack_size, 8u << 20);
    const fs::path output = options.output.empty()
                                ? fs::path(options.scene).replace_extension(".png")
                                : fs::path(options.output);
    if (!ImageWriter::supports(output)) {
        // supportedExtensions() is ".png, .jpg, ...": its names, for the suggestion.
        std::vector<std::string> extensions;
        std::istringstream list(ImageWriter::supportedExtensions());
        for (std::string extension; std::getline(list >> std::ws, extension, ',');)
            extensions.push_back(extension);
        const std::string extension = output.extension().string();
        return usageError("unknown output format \"" + extension + "\" for " + output.string() +
                          didYouMean(extension, extensions) + " (expected one of " +
                          ImageWriter::supportedExtensions() + ")");
    }
    const fs::path outputFolder =
        output.parent_path().empty() ? fs::path(".") : output.parent_path();
    if (cluster.leader() && !fs::is_directory(outputFolder))
        return fail(kExitFailure, "lancer: error: " + output.string() +
                                      ": cannot write the image (folder " + outputFolder.string() +
                                      " does not exist)");
    if (cluster.leader() && fs::is_directory(output))
        return fail(kExitFailure, "lancer: error: " + output.string() +
                                      ": cannot write the image (it is a folder)");
    std::vector<const Aov*> aovs;
    if (options.aovs) {
        try {
            aovs = Aov::parseList(*options.aovs);
        } catch (const std::invalid_argument& e) {
            return usageError(std::string("--aov ") + e.what());
        }
    }

    // The first frame to render is loaded first: the range is checked once the animation's frames
    // are known.
    std::optional<FrameRange> asked;
    if (options.frames) {
        std::string error;
        asked = parseFrames(*options.frames, error);
        if (!asked) return usageError(error);
    }
    const int firstLoaded = asked ? asked->first : 1;
    std::vector<std::string> warnings;
    const std::optional<ModelCache> modelCache = modelCacheOf(options);
    const ModelCache* models = modelCache ? &*modelCache : nullptr;
    Scene scene = SceneLoader::loadFile(options.scene, warnings, firstLoaded, models);
    if (!options.quiet)
        for (const std::string& warning : warnings)
            std::cerr << warning << '\n';
    const std::optional<AnimationSettings>& animation = scene.settings().animation;
    if (!animation) {
        if (options.frames)
            return usageError("--frames " + *options.frames + ": " + options.scene +
                              " is not animated (it has no \"animation\" block)");
        return renderImage(options, cluster, std::move(scene), output, aovs, 0);
    }

    // An animation: each frame of the range is loaded and rendered in turn, to OUT-0001.EXT...
    const FrameRange range = asked.value_or(FrameRange{1, animation->frames});
    if (asked)
        if (const std::optional<std::string> error =
                checkFrames(*asked, *options.frames, animation->frames))
            return usageError(*error);
    if (options.window && range.last > range.first)
        return usageError("--window shows one image, and the animation of " + options.scene +
                          " has " + std::to_string(range.last - range.first + 1) +
                          " frames to render: choose one with --frames N");
    if ((options.saveRadiosity || options.loadRadiosity) && range.last > range.first)
        return usageError(
            "--save-radiosity and --load-radiosity keep the solution of one frame: "
            "choose it with --frames N");
    for (int frame = range.first; frame <= range.last; ++frame) {
        // A signal between two frames stops before the next (as the leader saw it: every process
        // goes on or stops alike).
        if (cluster.fromLeader(InterruptSignals::requested() ? 1 : 0) != 0) {
            if (cluster.leader())
                std::cerr << "lancer: interrupted before frame " << frame
                          << "; the frames before it were written\n";
            return InterruptSignals::exitStatus();
        }
        const fs::path frameOutput = numberedOutput(output, frame);
        // --resume keeps the frames an earlier run finished: their image, and no resume file.
        const bool finished = options.resume && fs::exists(frameOutput) &&
                              !fs::exists(ResumeFile::pathBeside(frameOutput));
        if (cluster.fromLeader(finished ? 1 : 0) != 0) {
            if (!options.quiet)
                std::cerr << "lancer: --resume: " << frameOutput.string()
                          << " was finished by an earlier run\n";
            continue;
        }
        if (frame != firstLoaded) {
            std::vector<std::string> again;  // the same warnings as the first frame's
            scene = SceneLoader::loadFile(options.scene, again, frame, models);
        }
        if (const int status =
                renderImage(options, cluster, std::move(scene), frameOutput, aovs, frame);
            status != 0)
            return status;
    }
    return 0;
}

// Runs `run` with the exceptions it may throw turned into their exit status and message.
int runReporting(const Options& options, Cluster& cluster) {
    try {
        return run(options, cluster);
    } catch (const InputError& e) {
        return fail(kExitBadInput, e.what());
    } catch (const std::exception& e) {
        return fail(kExitFailure, std::string("lancer: error: ") + e.what());
    }
}

// The command line's status: none when it is fine and run() should follow.
std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ExtrasError& e) {
        return usageError(unexpectedArguments(app, argc, argv, e));
    } catch (const CLI::ParseError& e) {
        return usageError(std::string(e.what()) + " (see lancer --help)");
    }
    return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
    // Under mpirun, this process is one of a cluster; otherwise a cluster of one.
    Cluster cluster(argc, argv);
    Options options;
    CLI::App app{
        "lancer: a CPU ray tracer. Renders SCENE.json to an image by Whitted ray tracing, path "
        "tracing (the ground truth) or radiosity seen through the ray tracer.",
        "lancer"};
    std::string names = "\nWhat a scene can name (docs/SCENE-FORMAT.md):";
    for (const SceneLoader::Vocabulary& v : SceneLoader::vocabulary()) {
        names += "\n  " + v.what + ":";
        for (const std::string& name : v.names)
            names += " " + name;
    }
    app.footer(names);
    app.set_version_flag("--version", [] { return BuildInfo::describe(); });
    app.add_option("scene", options.scene, "Scene file (JSON, see docs/SCENE-FORMAT.md)")
        ->required();
    app.add_option(
        "-o,--output", options.output,
        "Output image; the extension picks the format: .png .jpg .bmp .tga .tif (8-bit sRGB), "
        ".exr .hdr .pfm (linear float); the scene's exposure and tonemap apply. Default: the "
        "scene's name with .png");
    app.add_option("--width", options.width, "Image width in pixels (overrides the scene)")
        ->check(CLI::Range(1, RenderSettings::kMaxImageSide));
    app.add_option("--height", options.height, "Image height in pixels (overrides the scene)")
        ->check(CLI::Range(1, RenderSettings::kMaxImageSide));
    app.add_option("--spp", options.spp, "Samples per pixel (overrides the scene)")
        ->check(CLI::Range(1, RenderSettings::kMaxSamplesPerPixel));
    app.add_option("--max-depth", options.maxDepth, "Recursion depth (overrides the scene)")
        ->check(CLI::Range(0, RenderSettings::kMaxDepthLimit));
    app.add_option("--light-edge-factor", options.lightEdgeFactor,
                   "Pixels on the edge of a light the camera sees take this many times the "
                   "samples, 1 to turn it off (overrides the scene; default 16)")
        ->check(CLI::Range(1, RenderSettings::kMaxSamplesPerPixel));
    app.add_option("--adc-bailout", options.adcBailout,
                   "Whitted and radiosity: leave the reflected and refracted rays that would carry "
                   "less than this fraction of their light to the pixel, 0 to 1 (overrides the "
                   "scene; POV-Ray's adc_bailout)")
        ->check(CLI::Validator(
            [](const std::string& text) {
                char* end = nullptr;
                const double value = std::strtod(text.c_str(), &end);
                return *end == '\0' && value >= 0 && value <= 1
                           ? std::string()
                           : "the bailout must be a number from 0 to 1, got " + text;
            },
            ""));
    app.add_option("--integrator", options.integrator,
                   IntegratorRegistry::table().quotedNames() + " (overrides the scene)")
        ->check(CLI::Validator(
            [](const std::string& name) {
                const std::vector<std::string> valid = IntegratorRegistry::table().names();
                return std::find(valid.begin(), valid.end(), name) != valid.end()
                           ? std::string()
                           : unknownName("integrator", name, valid);
            },
            ""));
    app.add_option("--threads", options.threads, "Worker threads; 0 = all cores")
        ->check(CLI::Range(0, 1024));
    app.add_option("--seed", options.seed,
                   "Random seed: the same seed and scene give the same image")
        // CLI11 would take a negative seed, wrapped around to a huge unsigned one.
        ->check(CLI::Validator(
            [](const std::string& text) {
                return text.rfind('-', 0) == 0 ? "the seed must be a whole number >= 0, got " + text
                                               : std::string();
            },
            ""));
    app.add_option("--crop", options.crop,
                   "Render only the pixels X0,Y0,X1,Y1 (inclusive-exclusive)");
    app.add_option("--frames", options.frames,
                   "Render only the frames A to B (\"A:B\", or \"A\" alone) of the scene's "
                   "animation, numbered from 1, each to OUT-0001.EXT...");
    app.add_option("--aov", options.aovs,
                   "Also write auxiliary outputs beside the image, OUT.NAME.exr, for a denoiser: "
                   "any of " +
                       Aov::types().quotedNames() + ", separated by commas");
    app.add_flag("--window", options.window, "Show the image in a window while it renders");
    app.add_flag("--resume", options.resume,
                 "Finish the render that an interrupted run of the same command left in "
                 "OUT.resume: only the missing tiles are rendered, and the image is the same as "
                 "an uninterrupted render's");
    app.add_flag("--quiet", options.quiet, "No progress bar or summary, only errors");
    app.add_flag("--stats", options.stats,
                 "Print scene statistics: objects, triangles, memory per triangle");
    app.add_option("--save-radiosity", options.saveRadiosity,
                   "Radiosity: save the solution to FILE, for other views of the same scene");
    app.add_option("--load-radiosity", options.loadRadiosity,
                   "Radiosity: use the solution saved in FILE instead of solving again");
    auto* modelCache =
        app.add_option("--model-cache", options.modelCache,
                       "Keep large OBJ models (8 MiB and more), read and built, in FOLDER, and "
                       "take them from there while their files are unchanged; default: "
                       "$XDG_CACHE_HOME/lancer/models or ~/.cache/lancer/models");
    app.add_flag("--no-model-cache", options.noModelCache,
                 "Read every model from its file, and keep none")
        ->excludes(modelCache);
    app.add_option("--max-memory", options.maxMemory,
                   "The most memory the image's buffers may take, as 500M, 64G or 2T; "
                   "default: the machine's memory")
        ->check(CLI::Validator(
            [](const std::string& text) {
                return parseMemorySize(text)
                           ? std::string()
                           : "expected a size such as 500M, 64G or 2T, got \"" + text + "\"";
            },
            ""));

    std::optional<int> status = parseCommandLine(app, argc, argv);
    if (!status) status = runReporting(options, cluster);
    // A failure before every process was ready ends them all, reported once.
    return cluster.finish(cluster.settle(*status));
}
