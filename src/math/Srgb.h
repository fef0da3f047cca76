#pragma once

#include <cmath>
#include <cstdint>

#include "math/Float.h"

namespace lancer {

// The sRGB transfer function (IEC 61966-2-1): linear [0,1] to encoded [0,1], and back.
inline float linearToSrgb(float v) {
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}
inline float srgbToLinear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// Linear radiance as an 8-bit sRGB value, as 8-bit images store it and the window shows it:
// clamped to [0, 1], NaN (which should never happen) as black rather than garbage.
inline std::uint8_t linearToSrgb8(float linear) {
    if (std::isnan(linear)) return 0;
    return static_cast<std::uint8_t>(std::lround(linearToSrgb(clamp(linear, 0.0f, 1.0f)) * 255.0f));
}

}  // namespace lancer
