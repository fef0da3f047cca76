#pragma once

#include <cstddef>
#include <vector>

#include "math/Color.h"

namespace lancer {

// Colours kept as three arrays, one per channel (a structure of arrays): loops over many of them
// read each channel in a row, which vectorizes where an array of Color would not.
struct ColorArrays {
    std::vector<float> r, g, b;

    void resize(std::size_t n) {
        r.resize(n);
        g.resize(n);
        b.resize(n);
    }
    void set(std::size_t i, const Color& c) {
        r[i] = c.r;
        g[i] = c.g;
        b[i] = c.b;
    }
};

}  // namespace lancer
