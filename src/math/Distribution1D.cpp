#include "math/Distribution1D.h"

#include <algorithm>
#include <stdexcept>

#include "math/Float.h"

namespace lancer {

Distribution1D::Distribution1D(std::vector<float> weights) : weights_(std::move(weights)) {
    if (weights_.empty()) throw std::invalid_argument("Distribution1D: no weights");
    double sum = 0;
    for (float w : weights_) {
        if (!(w >= 0) || !std::isfinite(w))
            throw std::invalid_argument("Distribution1D: weights must be finite and >= 0");
        sum += w;
    }
    // All zero: every cell equally likely, so that sampling still returns something valid.
    if (sum == 0) std::fill(weights_.begin(), weights_.end(), 1.0f);
    uniform_ = std::all_of(weights_.begin(), weights_.end(),
                           [&](float w) { return w == weights_.front(); });
    const std::size_t n = weights_.size();
    cdf_.resize(n + 1);
    cdf_[0] = 0;
    for (std::size_t i = 0; i < n; ++i)
        cdf_[i + 1] = cdf_[i] + weights_[i];
    const double total = cdf_[n];
    for (double& c : cdf_)
        c /= total;
    cdf_[n] = 1;
    integral_ = static_cast<float>(sum / static_cast<double>(n));
    firstInBucket_.resize(n + 1);
    std::size_t i = 0;
    for (std::size_t j = 0; j <= n; ++j) {
        while (bucket(cdf_[i]) < j)
            ++i;
        firstInBucket_[j] = static_cast<std::uint32_t>(i);
    }
}

std::size_t Distribution1D::bucket(double x) const {
    return static_cast<std::size_t>(x * static_cast<double>(weights_.size()));
}

std::size_t Distribution1D::sampleDiscrete(float u, float* pmfOut, float* uRemapped) const {
    if (uniform_) {
        const double scaled = static_cast<double>(u) * static_cast<double>(weights_.size());
        const std::size_t i =
            std::min(static_cast<std::size_t>(std::max(scaled, 0.0)), weights_.size() - 1);
        if (pmfOut) *pmfOut = pmf(i);
        if (uRemapped)
            *uRemapped = std::clamp(static_cast<float>(scaled - static_cast<double>(i)), 0.0f,
                                    kOneMinusEpsilon);
        return i;
    }
    // The last index i with cdf_[i] <= u; cells of zero weight are never chosen. Bounds in
    // buckets below u's are below u and those in buckets above are above it (bucket() is
    // monotone), so the search needs only the cells from the last bound before u's bucket to
    // the first beyond it.
    const std::size_t j = u > 0 ? std::min(bucket(u), weights_.size() - 1) : 0;
    const auto first = cdf_.begin() + std::max<std::ptrdiff_t>(firstInBucket_[j], 1) - 1;
    const auto upper =
        std::upper_bound(first, cdf_.begin() + firstInBucket_[j + 1], static_cast<double>(u));
    std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(upper - cdf_.begin() - 1, 0));
    i = std::min(i, weights_.size() - 1);
    while (cdf_[i + 1] == cdf_[i] && i > 0)
        --i;
    const double width = cdf_[i + 1] - cdf_[i];
    if (pmfOut) *pmfOut = static_cast<float>(width);
    if (uRemapped)
        *uRemapped = std::min(static_cast<float>((u - cdf_[i]) / width), kOneMinusEpsilon);
    return i;
}

float Distribution1D::pmf(std::size_t i) const {
    return static_cast<float>(cdf_[i + 1] - cdf_[i]);
}

float Distribution1D::sampleContinuous(float u, float* pdfOut) const {
    float pmfOfCell = 0, offset = 0;
    const std::size_t i = sampleDiscrete(u, &pmfOfCell, &offset);
    const float n = static_cast<float>(weights_.size());
    if (pdfOut) *pdfOut = pmfOfCell * n;
    return std::min((static_cast<float>(i) + offset) / n, kOneMinusEpsilon);
}

float Distribution1D::pdf(float x) const {
    const std::size_t n = weights_.size();
    const std::size_t i = std::min(static_cast<std::size_t>(x * static_cast<float>(n)), n - 1);
    return pmf(i) * static_cast<float>(n);
}

}  // namespace lancer
