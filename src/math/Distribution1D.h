#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lancer {

// A piecewise-constant density over [0, 1) with one cell per weight (or a discrete distribution
// over the weights' indices), sampled by inverting its cumulative distribution. Light selection
// in proportion to power and tabulated filter sampling are both built on it.
class Distribution1D {
public:
    // Weights must be finite and non-negative; if they are all zero the distribution is uniform.
    explicit Distribution1D(std::vector<float> weights);

    std::size_t size() const { return weights_.size(); }
    // The sum of the weights divided by their count: the integral of the piecewise function.
    float integral() const { return integral_; }

    // The index whose cumulative interval holds u in [0,1); its probability in *pmf if given, and
    // in *uRemapped where u falls within that interval, rescaled to [0,1) for reuse.
    std::size_t sampleDiscrete(float u, float* pmf = nullptr, float* uRemapped = nullptr) const;
    // The probability of picking index i.
    float pmf(std::size_t i) const;

    // A point x in [0,1) distributed as the piecewise-constant density; the density there in *pdf.
    float sampleContinuous(float u, float* pdf = nullptr) const;
    // The density at x in [0,1).
    float pdf(float x) const;

private:
    std::vector<float> weights_;
    // Which bucket of [0, 1), cut into size() equal parts, holds x: monotone in x, so that it
    // narrows the search for u to the cells whose bounds fall in u's bucket.
    std::size_t bucket(double x) const;

    std::vector<double> cdf_;  // cdf_[i]: probability of the cells before i; cdf_.back() = 1
    // firstInBucket_[j]: the first i with bucket(cdf_[i]) >= j, for j in [0, size()].
    std::vector<std::uint32_t> firstInBucket_;
    // Whether the weights are all equal (a box filter's profile, a single light): u then finds
    // its cell as u * size(), without a search.
    bool uniform_ = false;
    float integral_ = 0;
};

}  // namespace lancer
