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

    // weight x colour added to the lane where `keep`, +0 where not (which leaves the sum as it
    // was, whatever the terms, infinite or NaN ones too).
    void addIf(bool keep, std::uint32_t lane, float weight, float cr, float cg, float cb) {
        r[lane] += keptIf(keep, weight * cr);
        g[lane] += keptIf(keep, weight * cg);
        b[lane] += keptIf(keep, weight * cb);
    }
    // weight x colour added to `ifTrue` where `which`, else to `ifFalse` (+0 to the other), and
    // to neither where not `keep`: by bit masks, since a condition would become a branch (the
    // compiler makes x + (c ? y : 0) a conditional add).
    static void addToOne(bool keep, bool which, ColorLanes& ifTrue, ColorLanes& ifFalse,
                         std::uint32_t lane, float weight, float cr, float cg, float cb) {
        ifTrue.addIf(keep && which, lane, weight, cr, cg, cb);
        ifFalse.addIf(keep && !which, lane, weight, cr, cg, cb);
    }
    // x where `keep`, else +0: by a bit mask, without a branch in the lanes (and +0 for an
    // infinite or NaN x too, where a product by 0 would give a NaN).
    static float keptIf(bool keep, float x) {
        return std::bit_cast<float>(std::bit_cast<std::uint32_t>(x) &
                                    (0u - static_cast<std::uint32_t>(keep)));
    }
    Color total() const {
        Color sum;
        for (std::uint32_t lane = 0; lane < kLanes; ++lane)
            sum += Color(r[lane], g[lane], b[lane]);
        return sum;
    }

    // What arrays read by forEach must hold past their last item.
    static constexpr std::uint32_t kPadding = kLanes - 1;

    // Calls body(lane, i, inRange) for i from `first` in whole groups of kLanes (a loop of fixed
    // length the compiler vectorizes), term i in lane (i - first) % kLanes. The last group runs
    // on past `last` (by at most kPadding) with inRange false, where the body is to add +0
    // (addIf): that leaves a lane's sum as it was, so the sums are those of the terms in range
    // alone, while a tail taken a term at a time cost more than the groups before it (a sum over
    // a few terms is mostly tail).
    template <typename Body>
    static void forEach(std::uint32_t first, std::uint32_t last, Body body) {
        for (std::uint32_t i = first; i < last; i += kLanes)
            for (std::uint32_t lane = 0; lane < kLanes; ++lane)
                body(lane, i + lane, i + lane < last);
    }

    // The same for items laid out in blocks of kLanes (block b holds items kLanes b to
    // kLanes b + kLanes - 1, one array per number): calls body(block, lane, inRange) for every
    // lane of the blocks that hold items of [first, last), item kLanes block + lane in its own
    // lane, inRange for those of [first, last). A group of lanes then reads one block, however
    // the range starts.
    template <typename Body>
    static void forEachBlock(std::uint32_t first, std::uint32_t last, Body body) {
        if (first >= last) return;
        for (std::uint32_t block = first / kLanes; block * kLanes < last; ++block)
            for (std::uint32_t lane = 0; lane < kLanes; ++lane) {
                const std::uint32_t i = block * kLanes + lane;
                body(block, lane, i >= first && i < last);
            }
    }
};

}  // namespace lancer
