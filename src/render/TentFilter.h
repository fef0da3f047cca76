#pragma once

#include "render/Filter.h"

namespace lancer {

// A weight falling linearly from the centre to zero at the radius (bilinear reconstruction at
// radius 1).
class TentFilter : public Filter {
public:
    explicit TentFilter(float radius);

    float profile(float x) const override;
};

}  // namespace lancer
