// BVH micro-benchmarks: build time on 1M triangles, and closest-hit and occlusion throughput on
// random incoherent rays, at 1 and 2 threads.
//
//   bvh_benchmark --benchmark_filter=Build

#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "accel/Bvh.h"
#include "geometry/Triangle.h"

namespace lancer {
namespace {

// Triangles as three vertices each, the layout a mesh owner would reorder into leaf order.
struct Triangles {
    std::vector<Vec3> vertices;

    std::size_t size() const { return vertices.size() / 3; }
    void add(const Vec3& a, const Vec3& b, const Vec3& c) {
        vertices.insert(vertices.end(), {a, b, c});
    }
    std::vector<Bounds3> bounds() const {
        std::vector<Bounds3> b(size());
        for (std::size_t i = 0; i < size(); ++i)
            b[i] = merge(Bounds3(vertices[3 * i], vertices[3 * i + 1]), vertices[3 * i + 2]);
        return b;
    }
};

// 1M random triangles of side about 0.01 in the unit cube: a hard case, all overlapping boxes.
Triangles randomSoup() {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0, 1), offset(-0.005f, 0.005f);
    Triangles t;
    for (int i = 0; i < 1'000'000; ++i) {
        const Vec3 c(u(rng), u(rng), u(rng));
        t.add(c + Vec3(offset(rng), offset(rng), offset(rng)),
              c + Vec3(offset(rng), offset(rng), offset(rng)),
              c + Vec3(offset(rng), offset(rng), offset(rng)));
    }
    return t;
}

// A 708 x 708 height field (1,002,528 triangles) with hills on several scales: a mesh-like case.
Triangles terrain() {
    constexpr int kCells = 708;
    const auto height = [](float x, float z) {
        return 0.1f * std::sin(6 * x) * std::cos(5 * z) + 0.02f * std::sin(40 * x + 3 * z) +
               0.005f * std::cos(150 * z - 20 * x);
    };
    const auto vertex = [&](int i, int j) {
        const float x = static_cast<float>(i) / kCells, z = static_cast<float>(j) / kCells;
        return Vec3(x, height(x, z), z);
    };
    Triangles t;
    for (int i = 0; i < kCells; ++i)
        for (int j = 0; j < kCells; ++j) {
            t.add(vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1));
            t.add(vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1));
        }
    return t;
}

Vec3 randomDirection(std::mt19937& rng) {
    std::normal_distribution<float> normal;
    for (;;) {
        const Vec3 d(normal(rng), normal(rng), normal(rng));
        if (lengthSquared(d) > 1e-6f) return normalize(d);
    }
}

// A scene ready to trace: the BVH, the triangles in its leaf order, and 1M incoherent rays
// starting at random points of the scene's box in random directions.
struct Scene {
    explicit Scene(const Triangles& triangles) : bvh(triangles.bounds()) {
        for (const std::uint32_t i : bvh.primitiveOrder())
            leafOrdered.add(triangles.vertices[3 * i], triangles.vertices[3 * i + 1],
                            triangles.vertices[3 * i + 2]);
        std::mt19937 rng(2);
        std::uniform_real_distribution<float> u(0, 1);
        const Bounds3& box = bvh.bounds();
        const Vec3 d = box.diagonal();
        rays.resize(1'000'000);
        for (Ray& ray : rays)
            ray = {box.min + Vec3(u(rng) * d.x, u(rng) * d.y, u(rng) * d.z), randomDirection(rng)};
    }

    bool intersect(std::uint32_t k, const Ray& ray, float& tMax) const {
        const auto at =
            Triangle::intersect(leafOrdered.vertices[3 * k], leafOrdered.vertices[3 * k + 1],
                                leafOrdered.vertices[3 * k + 2], ray, tMax);
        if (!at) return false;
        tMax = at->t;
        return true;
    }

    Bvh bvh;
    Triangles leafOrdered;
    std::vector<Ray> rays;
};

const Triangles& sceneTriangles(int scene) {
    static const Triangles soup = randomSoup();
    static const Triangles mesh = terrain();
    return scene == 0 ? soup : mesh;
}

const Scene& traceScene(int scene) {
    static const Scene soup(sceneTriangles(0));
    static const Scene mesh(sceneTriangles(1));
    return scene == 0 ? soup : mesh;
}

const char* sceneName(int scene) {
    return scene == 0 ? "soup" : "terrain";
}

// Arguments: scene (0 random soup, 1 terrain), threads.
void BM_Build(benchmark::State& state) {
    const std::vector<Bounds3> bounds = sceneTriangles(static_cast<int>(state.range(0))).bounds();
    const tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(state.range(1)));
    std::size_t nodes = 0, bytes = 0;
    for (auto _ : state) {
        const Bvh bvh(bounds);
        nodes = bvh.nodeCount();
        bytes = bvh.memoryBytes();
        benchmark::DoNotOptimize(bvh.nodes().data());
    }
    state.SetLabel(sceneName(static_cast<int>(state.range(0))));
    state.counters["nodes"] = static_cast<double>(nodes);
    state.counters["bytes/tri"] = static_cast<double>(bytes) / static_cast<double>(bounds.size());
    state.counters["Mtri/s"] = benchmark::Counter(static_cast<double>(bounds.size()) * 1e-6,
                                                  benchmark::Counter::kIsIterationInvariantRate);
}

// Traces all the scene's rays on `threads` threads; `query` runs one ray and returns whether it
// hit.
template <typename Query>
void traceRays(benchmark::State& state, Query&& query) {
    const Scene& scene = traceScene(static_cast<int>(state.range(0)));
    const tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(state.range(1)));
    std::size_t hits = 0;
    for (auto _ : state) {
        std::vector<std::uint8_t> hit(scene.rays.size());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, scene.rays.size(), 1024),
                          [&](const auto& r) {
                              for (std::size_t i = r.begin(); i < r.end(); ++i)
                                  hit[i] = query(scene, scene.rays[i]);
                          });
        hits = 0;
        for (const std::uint8_t h : hit)
            hits += h;
    }
    state.SetLabel(sceneName(static_cast<int>(state.range(0))));
    state.counters["hit%"] =
        100.0 * static_cast<double>(hits) / static_cast<double>(scene.rays.size());
    state.counters["Mrays/s"] = benchmark::Counter(static_cast<double>(scene.rays.size()) * 1e-6,
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

void BM_ClosestHit(benchmark::State& state) {
    traceRays(state, [](const Scene& scene, const Ray& ray) {
        float tMax = kInfinity;
        return scene.bvh.intersect(ray, tMax, [&](std::uint32_t k, const Ray& r, float& t) {
            return scene.intersect(k, r, t);
        });
    });
}

// Shadow rays to a point at distance 1 along the ray, so that some are blocked and some not.
void BM_Occluded(benchmark::State& state) {
    traceRays(state, [](const Scene& scene, const Ray& ray) {
        return scene.bvh.occluded(ray, 1.0f, [&](std::uint32_t k, const Ray& r, float tMax) {
            return scene.intersect(k, r, tMax);
        });
    });
}

void sceneAndThreads(benchmark::internal::Benchmark* b) {
    b->ArgNames({"scene", "threads"});
    for (const int scene : {0, 1})
        for (const int threads : {1, 2})
            b->Args({scene, threads});
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK(BM_Build)->Apply(sceneAndThreads)->MinTime(2.0);
BENCHMARK(BM_ClosestHit)->Apply(sceneAndThreads);
BENCHMARK(BM_Occluded)->Apply(sceneAndThreads);

}  // namespace
}  // namespace lancer
