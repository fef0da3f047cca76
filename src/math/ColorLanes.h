#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "math/Color.h"

namespace lancer {

// A sum of many colour terms kept as kLanes interleaved partial sums, added up in lane order at
// the end. The compiler may not reorder one float sum, so a loop adding into one Color runs a
// term at a time; eight independent sums let it run the terms eight at a time in SIMD lanes, and
// the order of the additions, so the result, is the same on every CPU and for any number of
// threads.
struct ColorLanes {
    static constexpr std::uint32_t kLanes = 8;

    std::array<float, kLanes> r{}, g{}, b{};

    void add(std::uint32_t lane, float weight, float cr, float cg, float cb) {
        r[lane] += weight * cr;
        g[lane] += weight * cg;
        b[lane] += weight * cb;
    }
    // weight x colour added to `ifTrue` where `which`, else to `ifFalse` (+0 to the other). The
    // product is kept or cleared by a bit mask: a condition here becomes a branch (the compiler
    // makes x + (c ? y : 0) a conditional add), and a product by 0 would turn an infinite term
    // into a NaN.
    static void addToOne(bool which, ColorLanes& ifTrue, ColorLanes& ifFalse, std::uint32_t lane,
                         float weight, float cr, float cg, float cb) {
        const std::uint32_t mask = 0u - static_cast<std::uint32_t>(which);
        const auto keep = [](float x, std::uint32_t bits) {
            return std::bit_cast<float>(std::bit_cast<std::uint32_t>(x) & bits);
        };
        const float r = weight * cr, g = weight * cg, b = weight * cb;
        ifTrue.r[lane] += keep(r, mask);
        ifTrue.g[lane] += keep(g, mask);
        ifTrue.b[lane] += keep(b, mask);
        ifFalse.r[lane] += keep(r, ~mask);
        ifFalse.g[lane] += keep(g, ~mask);
        ifFalse.b[lane] += keep(b, ~mask);
    }
    Color total() const {
        Color sum;
        for (std::uint32_t lane = 0; lane < kLanes; ++lane)
            sum += Color(r[lane], g[lane], b[lane]);
        return sum;
    }

    // Calls body(lane, i) for i in [first, last), term i in lane (i - first) % kLanes: whole
    // groups of kLanes in a loop of fixed length the compiler vectorizes, then the rest.
    template <typename Body>
    static void forEach(std::uint32_t first, std::uint32_t last, Body body) {
        std::uint32_t i = first;
        for (; last - i >= kLanes; i += kLanes)
            for (std::uint32_t lane = 0; lane < kLanes; ++lane)
                body(lane, i + lane);
        for (std::uint32_t lane = 0; i < last; ++i, ++lane)
            body(lane, i);
    }
};

}  // namespace lancer
