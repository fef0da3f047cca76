#pragma once

#include "math/Bounds3.h"

namespace lancer {

// What a tessellation is for: radiosity cuts the facets into patches of about patchSize, and
// infinite shapes are cut to the box that matters.
struct TessellationRequest {
    float patchSize;
    Bounds3 clipBox;
};

}  // namespace lancer
