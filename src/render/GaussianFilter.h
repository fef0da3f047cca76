#pragma once

#include "render/Filter.h"

namespace lancer {

// A Gaussian of standard deviation sigma = radius / 3, minus its value at the radius so that it
// falls to zero there without a step (as pbrt's), rescaled to integrate to 1.
class GaussianFilter : public Filter {
public:
    explicit GaussianFilter(float radius);

    float profile(float x) const override;
    float sigma() const { return sigma_; }

private:
    float sigma_;
    float valueAtRadius_;  // exp(-r^2 / (2 sigma^2)), subtracted
    float scale_;          // 1 / the integral of the shifted Gaussian over [-r, r]
};

}  // namespace lancer
