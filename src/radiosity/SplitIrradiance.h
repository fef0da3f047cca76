#pragma once

#include <array>

#include "math/Color.h"

namespace lancer {

// The irradiance on both sides of a surface point (front, back), and the part of it that comes
// straight from the emitters a render samples: the scene's lights and the emissive surfaces of
// bounded shapes (an emissive infinite plane's light is not sampled, so it is not in this part).
// The rest is the light reflected at least once: indirect = total - direct.
struct SplitIrradiance {
    std::array<Color, 2> total;
    std::array<Color, 2> direct;

    SplitIrradiance& operator+=(const SplitIrradiance& other) {
        for (std::size_t side = 0; side < 2; ++side) {
            total[side] += other.total[side];
            direct[side] += other.direct[side];
        }
        return *this;
    }
};

}  // namespace lancer
