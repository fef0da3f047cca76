#pragma once

#include <vector>

#include "math/Distribution1D.h"
#include "math/Vec2.h"

namespace lancer {

// A piecewise-constant density over [0, 1)^2 with one cell per value of a width x height grid
// (row y covers [y / height, (y + 1) / height)), sampled by inversion: a row from the marginal
// distribution of the rows' integrals, then a column from that row's conditional distribution
// (pbrt's PiecewiseConstant2D). The environment light samples its map with it.
class Distribution2D {
public:
    // values row by row (width * height of them), finite and non-negative; all zero is uniform.
    Distribution2D(const std::vector<float>& values, int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    // The mean of the values: the integral of the piecewise-constant function over [0, 1)^2.
    float integral() const { return marginal_.integral(); }

    // A cell (x across, y down) picked in proportion to its value, with its probability, and
    // where u fell within the cell's share of [0, 1)^2, rescaled to [0, 1)^2: a uniform point
    // of the cell, for a caller that places its own point within it.
    struct CellSample {
        int x, y;
        Vec2 offset;
        float probability;
    };
    CellSample sampleCell(const Vec2& u) const;
    // A point (x across, y down) distributed as the density; the density there in *pdf.
    Vec2 sample(const Vec2& u, float* pdf) const;
    // The density at p in [0, 1)^2.
    float pdf(const Vec2& p) const;

private:
    int width_, height_;
    std::vector<Distribution1D> rows_;  // the conditional distribution of x in each row
    Distribution1D marginal_;           // the distribution of y: the rows' integrals
};

}  // namespace lancer
