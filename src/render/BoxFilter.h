#pragma once

#include "render/Filter.h"

namespace lancer {

// The same weight everywhere within the radius: with radius 0.5, the plain average of the
// samples over the pixel's area.
class BoxFilter : public Filter {
public:
    explicit BoxFilter(float radius);

    float profile(float x) const override;
};

}  // namespace lancer
