#include "render/Renderer.h"

#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>
#include <vector>

#include "render/Integrator.h"
#include "render/Sampler.h"
#include "scene/Scene.h"

namespace lancer {

Renderer::Renderer(const Scene& scene, const Integrator& integrator)
    : scene_(scene), integrator_(integrator) {}

Color Renderer::renderPixel(int x, int y, std::uint64_t seed, std::uint64_t& rayCount) const {
    const RenderSettings& settings = scene_.settings();
    const int spp = settings.samplesPerPixel;
    Sampler sampler(seed, x, y, spp);
    // Each of n samples covers about 1/sqrt(n) of the pixel's width; the floor keeps some
    // texture filtering at very high sample counts (as pbrt does).
    const float pixelSpread = scene_.camera().pixelSpreadAngle(settings.height) *
                              std::max(0.125f, 1 / std::sqrt(static_cast<float>(spp)));
    Color sum;
    for (int s = 0; s < spp; ++s) {
        sampler.startSample(s);
        // One sample goes through the pixel centre, as a classic ray tracer's; more are stratified
        // over the pixel's area.
        const Vec2 offset = spp == 1 ? Vec2(0.5f, 0.5f) : sampler.get2D();
        const Vec2 lens = sampler.get2D();
        const Ray ray = scene_.camera().generateRay(static_cast<float>(x) + offset.x,
                                                    static_cast<float>(y) + offset.y,
                                                    settings.width, settings.height, lens);
        sum += integrator_.radiance(ray, pixelSpread, sampler, rayCount);
    }
    return sum / static_cast<float>(spp);
}

RenderResult Renderer::render(const RenderOptions& options) const {
    const auto start = std::chrono::steady_clock::now();
    const RenderSettings& settings = scene_.settings();
    const PixelWindow window =
        options.crop.value_or(PixelWindow{0, 0, settings.width, settings.height});

    std::vector<PixelWindow> tiles;
    for (int y = window.y0; y < window.y1; y += kTileSize)
        for (int x = window.x0; x < window.x1; x += kTileSize)
            tiles.push_back(
                {x, y, std::min(x + kTileSize, window.x1), std::min(y + kTileSize, window.y1)});

    RenderResult result{Film(settings.width, settings.height)};
    result.threads = options.threads > 0
                         ? options.threads
                         : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));

    std::atomic<std::size_t> nextTile{0};
    std::atomic<bool> interrupted{false};
    std::mutex progressMutex;
    int tilesDone = 0;
    std::vector<std::uint64_t> raysPerThread(static_cast<std::size_t>(result.threads), 0);
    const auto cancelled = [&] {
        return options.cancel && options.cancel->load(std::memory_order_relaxed);
    };

    const auto worker = [&](std::size_t threadIndex) {
        std::vector<Color> tilePixels(static_cast<std::size_t>(kTileSize * kTileSize));
        std::uint64_t& rays = raysPerThread[threadIndex];
        for (std::size_t t; (t = nextTile.fetch_add(1)) < tiles.size();) {
            const PixelWindow& tile = tiles[t];
            // Pixels go to the film only once their tile is complete, so that an interrupted
            // render holds whole tiles.
            for (int y = tile.y0; y < tile.y1; ++y) {
                if (cancelled()) {
                    interrupted = true;
                    return;
                }
                for (int x = tile.x0; x < tile.x1; ++x)
                    tilePixels[static_cast<std::size_t>((y - tile.y0) * kTileSize +
                                                        (x - tile.x0))] =
                        renderPixel(x, y, options.seed, rays);
            }
            for (int y = tile.y0; y < tile.y1; ++y)
                for (int x = tile.x0; x < tile.x1; ++x)
                    result.film.setPixel(x, y,
                                         tilePixels[static_cast<std::size_t>(
                                             (y - tile.y0) * kTileSize + (x - tile.x0))]);
            std::lock_guard lock(progressMutex);
            ++tilesDone;
            if (options.onTileDone) options.onTileDone(tilesDone, static_cast<int>(tiles.size()));
        }
    };

    std::vector<std::thread> pool;
    for (std::size_t i = 1; i < raysPerThread.size(); ++i)
        pool.emplace_back(worker, i);
    worker(0);
    for (auto& thread : pool)
        thread.join();

    for (std::uint64_t rays : raysPerThread)
        result.rays += rays;
    result.interrupted = interrupted || cancelled();
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace lancer
