#include "render/BoxFilter.h"

#include <cmath>

namespace lancer {

BoxFilter::BoxFilter(float radius) : Filter(radius) {}

float BoxFilter::profile(float x) const {
    return std::abs(x) <= radius() ? 0.5f / radius() : 0.0f;
}

}  // namespace lancer
