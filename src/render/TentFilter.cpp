#include "render/TentFilter.h"

#include <algorithm>
#include <cmath>

namespace lancer {

TentFilter::TentFilter(float radius) : Filter(radius) {}

float TentFilter::profile(float x) const {
    const float r = radius();
    return std::max(0.0f, r - std::abs(x)) / (r * r);
}

}  // namespace lancer
