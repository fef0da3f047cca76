#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

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

}  // namespace lancer
