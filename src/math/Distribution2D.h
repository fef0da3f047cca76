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
