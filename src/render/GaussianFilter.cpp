#include "render/GaussianFilter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lancer {

GaussianFilter::GaussianFilter(float radius) : Filter(radius), sigma_(radius / 3) {
    const double r = radius, s = sigma_;
    valueAtRadius_ = static_cast<float>(std::exp(-r * r / (2 * s * s)));
    // The integral of exp(-x^2 / (2 s^2)) - valueAtRadius over [-r, r].
    const double integral =
        s * std::sqrt(2 * std::numbers::pi) * std::erf(r / (s * std::sqrt(2.0))) -
        2 * r * valueAtRadius_;
    scale_ = static_cast<float>(1 / integral);
}

float GaussianFilter::profile(float x) const {
    if (std::abs(x) > radius()) return 0;
    return scale_ * std::max(0.0f, std::exp(-x * x / (2 * sigma_ * sigma_)) - valueAtRadius_);
}

}  // namespace lancer
