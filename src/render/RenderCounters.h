#pragma once

#include <cstdint>

namespace lancer {

// What a render did, counted per thread and summed.
struct RenderCounters {
    std::uint64_t rays = 0;              // every ray traced: camera, shadow and secondary
    std::uint64_t samples = 0;           // camera samples (adaptive sampling varies them by pixel)
    std::uint64_t pixels = 0;            // pixels estimated
    std::uint64_t nonFiniteSamples = 0;  // samples whose radiance was NaN or infinite: dropped

    RenderCounters& operator+=(const RenderCounters& other) {
        rays += other.rays;
        samples += other.samples;
        pixels += other.pixels;
        nonFiniteSamples += other.nonFiniteSamples;
        return *this;
    }

    double meanSamplesPerPixel() const {
        return pixels > 0 ? static_cast<double>(samples) / static_cast<double>(pixels) : 0.0;
    }
};

}  // namespace lancer
