#pragma once

namespace lancer {

// The "adaptive" block of the scene's "render" block. The largest sample count is the render's
// samplesPerPixel ("spp", "max_spp" or --spp), so that one number is the budget in every mode.
struct AdaptiveSettings {
    int minSamples = 16;      // taken in every pixel; also the size of each further batch
    float threshold = 0.05f;  // relative standard error of the pixel's luminance to stop at
};

}  // namespace lancer
