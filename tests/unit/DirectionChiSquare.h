#pragma once

// The chi-square test of a sampling routine against the density it states, over the sphere of
// directions (as pbrt-v3's bsdfs test and Mitsuba's chi2 module), for the BSDF tests.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "math/Float.h"
#include "math/Vec2.h"
#include "math/Vec3.h"

namespace lancer::test {

// Uniform numbers in [0, 1) from a seeded generator: the tests are repeatable.
class UniformSource {
public:
    explicit UniformSource(unsigned seed) : engine_(seed) {}
    float next() { return std::min(distribution_(engine_), 0x1.fffffep-1f); }
    Vec2 next2D() { return {next(), next()}; }

private:
    std::mt19937 engine_;
    std::uniform_real_distribution<float> distribution_{0.0f, 1.0f};
};

inline Vec3 direction(float thetaDegrees, float phiDegrees) {
    const float theta = radians(thetaDegrees), phi = radians(phiDegrees);
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Q(a, x), the regularized upper incomplete gamma function (Numerical Recipes' gammq): the
// probability that a chi-square variable of 2a degrees of freedom exceeds 2x.
inline double upperIncompleteGamma(double a, double x) {
    constexpr double kEpsilon = 1e-14, kTiny = 1e-300;
    const double logPrefactor = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1) {  // the series of P = 1 - Q
        double term = 1 / a, sum = term;
        for (double ap = a + 1; std::abs(term) > std::abs(sum) * kEpsilon; ap += 1) {
            term *= x / ap;
            sum += term;
        }
        return 1 - sum * std::exp(logPrefactor);
    }
    // Q's continued fraction, by Lentz's method.
    double b = x + 1 - a, c = 1 / kTiny, d = 1 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < kEpsilon) break;
    }
    return std::exp(logPrefactor) * h;
}

// A way of drawing directions, and the density it claims for them.
struct DirectionSampler {
    std::function<std::optional<Vec3>(UniformSource&)> sample;
    std::function<double(const Vec3&)> pdf;
};

// The cells of the sphere a chi-square test counts directions in: bands of theta from +z (equal
// in theta, or equal in cos theta: cells of equal solid angle, as Mitsuba's chi2 test), each cut
// into equal ranges of phi; the density is integrated over each cell by the midpoint rule on
// subCells x subCells points.
struct SphereGrid {
    int thetaCells = 16, phiCells = 32, subCells = 24;
    bool equalCosTheta = false;
};

// Draws `count` directions and compares their histogram over a grid of the sphere with the
// counts the density predicts. Cells expecting fewer than 5 hits are pooled (the chi-square
// approximation needs it). Returns the p-value of the observed histogram; a direction where the
// density says none can be also fails the test.
inline double chiSquarePValue(const DirectionSampler& sampler, int count, unsigned seed,
                              std::string& problem, const SphereGrid& grid = {}) {
    const int kThetaCells = grid.thetaCells, kPhiCells = grid.phiCells, kSubCells = grid.subCells;
    // The band's coordinate in [0, 1) from the pole +z: theta / pi, or (1 - cos theta) / 2.
    const auto bandCoordinate = [&](double cosTheta) {
        return grid.equalCosTheta ? (1 - cosTheta) / 2 : std::acos(cosTheta) / std::numbers::pi;
    };
    const auto cellOf = [&](const Vec3& w) {
        const double band = bandCoordinate(std::clamp(static_cast<double>(w.z), -1.0, 1.0));
        double phi = std::atan2(static_cast<double>(w.y), static_cast<double>(w.x));
        if (phi < 0) phi += 2 * std::numbers::pi;
        const int i = std::min(kThetaCells - 1, static_cast<int>(band * kThetaCells));
        const int j =
            std::min(kPhiCells - 1, static_cast<int>(phi / (2 * std::numbers::pi) * kPhiCells));
        return i * kPhiCells + j;
    };
    std::vector<double> observed(kThetaCells * kPhiCells, 0.0);
    UniformSource random(seed);
    for (int k = 0; k < count; ++k)
        if (const auto w = sampler.sample(random))
            observed[static_cast<std::size_t>(cellOf(*w))] += 1;

    std::vector<double> expected(observed.size(), 0.0);
    // Each cell is integrated on sub-points evenly spaced in theta and phi (the solid angle
    // element sin theta dtheta dphi), also for bands of equal cos theta: near the poles, where
    // those are wide in theta, a narrow lobe is still resolved.
    const auto bandTheta = [&](int i) {
        return grid.equalCosTheta ? std::acos(std::clamp(1 - 2.0 * i / kThetaCells, -1.0, 1.0))
                                  : i * std::numbers::pi / kThetaCells;
    };
    const double dPhi = 2 * std::numbers::pi / kPhiCells;
    for (int i = 0; i < kThetaCells; ++i) {
        const double thetaLow = bandTheta(i), dTheta = bandTheta(i + 1) - thetaLow;
        for (int j = 0; j < kPhiCells; ++j) {
            double sum = 0;
            for (int a = 0; a < kSubCells; ++a)
                for (int b = 0; b < kSubCells; ++b) {
                    const double theta = thetaLow + (a + 0.5) / kSubCells * dTheta;
                    const double phi = (j + (b + 0.5) / kSubCells) * dPhi;
                    const Vec3 w(static_cast<float>(std::sin(theta) * std::cos(phi)),
                                 static_cast<float>(std::sin(theta) * std::sin(phi)),
                                 static_cast<float>(std::cos(theta)));
                    sum += sampler.pdf(w) * std::sin(theta);
                }
            expected[static_cast<std::size_t>(i * kPhiCells + j)] =
                sum * dTheta * dPhi / (kSubCells * kSubCells) * count;
        }
    }

    std::vector<std::size_t> order(observed.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
    double chiSquare = 0, pooledExpected = 0, pooledObserved = 0;
    int bins = 0;
    for (std::size_t k : order) {
        if (expected[k] == 0 && observed[k] > count * 1e-5) {
            std::ostringstream out;
            out << observed[k] << " samples in cell " << k << " where the pdf is 0";
            problem = out.str();
            return 0;
        }
        if (expected[k] < 5) {
            pooledExpected += expected[k];
            pooledObserved += observed[k];
        } else {
            const double diff = observed[k] - expected[k];
            chiSquare += diff * diff / expected[k];
            ++bins;
        }
    }
    if (pooledExpected > 0) {
        const double diff = pooledObserved - pooledExpected;
        chiSquare += diff * diff / std::max(pooledExpected, 5.0);
        ++bins;
    }
    const int degreesOfFreedom = bins - 1;
    return upperIncompleteGamma(degreesOfFreedom / 2.0, chiSquare / 2);
}

}  // namespace lancer::test
