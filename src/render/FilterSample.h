#pragma once

#include "math/Vec2.h"

namespace lancer {

// A sample position for the pixel and the weight its radiance gets.
struct FilterSample {
    Vec2 offset;   // from the pixel centre, in pixels
    float weight;  // filter(offset) / pdf(offset): about 1, negative in a negative lobe
};

}  // namespace lancer
