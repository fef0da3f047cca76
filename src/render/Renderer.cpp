#include "render/Renderer.h"

#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "render/Integrator.h"
#include "render/PendingTiles.h"
#include "sampling/Sampler.h"
#include "scene/Scene.h"

namespace lancer {

Renderer::Renderer(const Scene& scene, const Integrator& integrator)
    : scene_(scene),
      integrator_(integrator),
      pixelEstimator_(scene, integrator),
      lightEdgeProbe_(scene) {}

Color Renderer::previewSample(const PixelWindow& block, std::uint64_t seed,
                              std::uint64_t& rayCount) const {
    const RenderSettings& settings = scene_.settings();
    Sampler sampler(seed, block.x0, block.y0);
    sampler.startSample(0);
    const std::optional<Ray> ray =
        scene_.camera().generateRay(0.5f * static_cast<float>(block.x0 + block.x1),
                                    0.5f * static_cast<float>(block.y0 + block.y1), settings.width,
                                    settings.height, Vec2(0.5f, 0.5f));
    if (!ray) return Color();
    // The ray stands for the whole block: textures are filtered over the block's footprint.
    const RayCone blockFootprint =
        scene_.camera()
            .pixelCone(settings.width, settings.height)
            .scaled(static_cast<float>(std::max(block.width(), block.height())));
    return integrator_.radiance(*ray, blockFootprint, sampler, rayCount);
}

namespace {

// `window` cut into tiles of at most size x size pixels, row by row.
std::vector<PixelWindow> cutIntoTiles(const PixelWindow& window, int size) {
    std::vector<PixelWindow> tiles;
    for (int y = window.y0; y < window.y1; y += size)
        for (int x = window.x0; x < window.x1; x += size)
            tiles.push_back({x, y, std::min(x + size, window.x1), std::min(y + size, window.y1)});
    return tiles;
}

// Runs renderTile(t, counters) for every tile t that nextTile() hands out, on as many oneTBB
// workers as the arena has threads, each taking the next tile until none is left, so that tiles
// start in order whatever the threads. renderTile returns false when it stopped early (cancelled),
// which stops its worker. Returns the counts of all the workers.
template <typename NextTile, typename RenderTile>
RenderCounters renderTilesInParallel(const NextTile& nextTile, tbb::task_arena& arena,
                                     const RenderTile& renderTile) {
    std::mutex totalMutex;
    RenderCounters total;
    const auto worker = [&] {
        // Counted locally and added once: per-worker counters side by side in one array would
        // share a cache line that every ray writes to.
        RenderCounters counters;
        while (const std::optional<std::size_t> t = nextTile())
            if (!renderTile(*t, counters)) break;
        std::lock_guard lock(totalMutex);
        total += counters;
    };
    // The calling thread works in the arena too. A worker that finds no thread free starts once
    // another has finished, and then finds no tile left.
    arena.execute([&] {
        tbb::parallel_for(
            0, tbb::this_task_arena::max_concurrency(), [&](int) { worker(); },
            tbb::simple_partitioner());
    });
    return total;
}

// A tile counter for the preview passes: 0, 1, ... tileCount - 1.
auto countTo(std::size_t tileCount) {
    return [tileCount, next = std::make_shared<std::atomic<std::size_t>>(0)] {
        const std::size_t t = next->fetch_add(1);
        return t < tileCount ? std::optional<std::size_t>(t) : std::nullopt;
    };
}

}  // namespace

std::vector<PixelWindow> Renderer::tiles(const PixelWindow& window) {
    return cutIntoTiles(window, kTileSize);
}

RenderResult Renderer::render(const RenderOptions& options) const {
    const auto start = std::chrono::steady_clock::now();
    const RenderSettings& settings = scene_.settings();
    const PixelWindow window =
        options.crop.value_or(PixelWindow{0, 0, settings.width, settings.height});
    const std::vector<PixelWindow> tiles =
        options.previewOnly ? std::vector<PixelWindow>{} : Renderer::tiles(window);

    RenderResult result{Image(settings.width, settings.height)};
    for (std::size_t i = 0; i < options.aovs.size(); ++i)
        result.aovFilms.emplace_back(settings.width, settings.height);
    result.finishedTiles.assign(tiles.size(), false);
    if (const RenderResult* resumed = options.resumeFrom) {
        if (resumed->finishedTiles.size() != tiles.size() ||
            resumed->film.width() != settings.width || resumed->film.height() != settings.height ||
            resumed->aovFilms.size() != options.aovs.size())
            throw std::invalid_argument("the render to resume is not of this image");
        result.film = resumed->film;
        result.aovFilms = resumed->aovFilms;
        result.finishedTiles = resumed->finishedTiles;
        result.counters = resumed->counters;
    }
    result.threads = options.threads > 0
                         ? options.threads
                         : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    // No more threads at once than asked for, the calling thread among them.
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);

    std::mutex reportMutex;
    int tilesDone = 0;
    const int tilesTotal = static_cast<int>(tiles.size());
    const auto cancelled = [&] {
        return options.cancel && options.cancel->load(std::memory_order_relaxed);
    };
    // A preview tile, or with its index one of the image's tiles, finished.
    const auto report = [&](const Image& film, const PixelWindow& tile,
                            std::optional<std::size_t> imageTile) {
        std::lock_guard lock(reportMutex);
        if (imageTile) {
            result.finishedTiles[*imageTile] = true;
            ++tilesDone;
        }
        if (options.onTileDone)
            options.onTileDone({film, result.aovFilms, tile, imageTile, tilesDone, tilesTotal});
    };

    // Each preview pass ends before the next begins, so that a coarser block never lands on a
    // finer one. Their pixels go to a film of their own: an interrupted render's image holds
    // finished tiles only.
    if (!options.previewBlockSizes.empty()) {
        Image preview(settings.width, settings.height);
        for (const int blockSize : options.previewBlockSizes) {
            const std::vector<PixelWindow> passTiles = cutIntoTiles(window, kTileSize * blockSize);
            result.counters += renderTilesInParallel(
                countTo(passTiles.size()), arena, [&](std::size_t t, RenderCounters& counters) {
                    for (const PixelWindow& block : cutIntoTiles(passTiles[t], blockSize)) {
                        if (cancelled()) return false;
                        const Color c = previewSample(block, options.seed, counters.rays);
                        for (int y = block.y0; y < block.y1; ++y)
                            for (int x = block.x0; x < block.x1; ++x)
                                preview.at(x, y) = c;
                    }
                    report(preview, passTiles[t], std::nullopt);
                    return true;
                });
        }
    }

    // The resumed render's tiles are reported as finished, then the others rendered, in the
    // order the queue hands them out.
    for (std::size_t t = 0; t < tiles.size(); ++t)
        if (result.finishedTiles[t]) report(result.film, tiles[t], t);
    std::optional<PendingTiles> pendingTiles;
    TileQueue& queue =
        options.tileQueue ? *options.tileQueue : pendingTiles.emplace(result.finishedTiles);
    const bool withAovs = !options.aovs.empty();
    result.counters += renderTilesInParallel(
        [&] { return queue.next(); }, arena,
        [&](std::size_t t, RenderCounters& counters) {
            const PixelWindow& tile = tiles[t];
            // Pixels go to the films only once their tile is complete, so that an interrupted
            // render holds whole tiles.
            const std::size_t pixelCount = static_cast<std::size_t>(tile.width() * tile.height());
            std::vector<Color> tilePixels(pixelCount);
            std::vector<AovSample> tileAovs(withAovs ? pixelCount : 0);
            const auto index = [&](int x, int y) {
                return static_cast<std::size_t>((y - tile.y0) * tile.width() + (x - tile.x0));
            };
            if (cancelled()) return false;  // before the probe's rays, as before each row
            const std::vector<bool> onLightEdge = lightEdgeProbe_.edges(tile, counters.rays);
            for (int y = tile.y0; y < tile.y1; ++y) {
                if (cancelled()) return false;
                for (int x = tile.x0; x < tile.x1; ++x)
                    tilePixels[index(x, y)] = pixelEstimator_.estimate(
                        x, y, options.seed, counters, onLightEdge[index(x, y)],
                        withAovs ? &tileAovs[index(x, y)] : nullptr);
            }
            for (int y = tile.y0; y < tile.y1; ++y)
                for (int x = tile.x0; x < tile.x1; ++x) {
                    result.film.at(x, y) = tilePixels[index(x, y)];
                    for (std::size_t i = 0; i < options.aovs.size(); ++i)
                        result.aovFilms[i].at(x, y) = options.aovs[i]->value(tileAovs[index(x, y)]);
                }
            report(result.film, tile, t);
            return true;
        });

    // A tile left unfinished was cancelled, or (in a cluster render) rendered elsewhere.
    result.interrupted = std::find(result.finishedTiles.begin(), result.finishedTiles.end(),
                                   false) != result.finishedTiles.end();
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace lancer
