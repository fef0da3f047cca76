#pragma once

#include <cmath>

namespace lancer {

// The sRGB transfer function (IEC 61966-2-1): linear [0,1] to encoded [0,1], and back.
inline float linearToSrgb(float v) {
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}
inline float srgbToLinear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

}  // namespace lancer
