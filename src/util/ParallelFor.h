#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace lancer {

// Runs chunk(begin, end) on oneTBB's threads over chunks that together cover [0, count) once;
// oneTBB splits the range as it balances the load, but no chunk of grainSize indices or fewer.
template <typename Chunk>
void parallelForChunks(std::size_t count, std::size_t grainSize, Chunk&& chunk) {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count, grainSize),
        [&](const tbb::blocked_range<std::size_t>& range) { chunk(range.begin(), range.end()); });
}

// Runs body(i) for every i in [0, count) on oneTBB's threads, in chunks as parallelForChunks.
template <typename Body>
void parallelFor(std::size_t count, std::size_t grainSize, Body&& body) {
    parallelForChunks(count, grainSize, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            body(i);
    });
}

// Runs body(i, count) for every i in [0, count) as parallelFor, where each body adds what it
// counts (rays) to `count`, and returns the sum. Counted per chunk and added once: one counter
// that every body wrote to would be contended by all the threads. Once `*cancel` (if given) is
// set, the chunks not started yet are skipped (the work is being abandoned).
template <typename Body>
std::uint64_t parallelForCounting(std::size_t count, std::size_t grainSize,
                                  const std::atomic<bool>* cancel, const Body& body) {
    std::atomic<std::uint64_t> total{0};
    parallelForChunks(count, grainSize, [&](std::size_t begin, std::size_t end) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return;
        std::uint64_t local = 0;
        for (std::size_t i = begin; i != end; ++i)
            body(i, local);
        total += local;
    });
    return total;
}

}  // namespace lancer
