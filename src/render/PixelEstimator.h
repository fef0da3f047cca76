#pragma once

#include <cstdint>

#include "math/Color.h"
#include "render/AovSample.h"
#include "render/FilterSampler.h"
#include "render/FirstHitProbe.h"
#include "render/RenderCounters.h"

namespace lancer {

class Integrator;
class Scene;

// The value of one pixel: its samples (Sampler), their positions and weights under the
// reconstruction filter (FilterSampler), and, with adaptive sampling, when to stop. A pixel
// depends only on (seed, pixel): its samples are numbered from 0 and the stopping rule sees only
// them.
class PixelEstimator {
public:
    // Reads the scene's render settings (filter, spp, adaptive) once; the camera at each call.
    PixelEstimator(const Scene& scene, const Integrator& integrator);

    // onLightEdge: the pixel is on a light's edge (LightEdgeProbe) and takes the scene's
    // lightEdgeFactor times the samples. With `aovs`, also the auxiliary outputs there: what
    // FirstHitProbe finds along the same camera rays, averaged with the same filter weights (the
    // image's value is unchanged).
    Color estimate(int x, int y, std::uint64_t seed, RenderCounters& counters,
                   bool onLightEdge = false, AovSample* aovs = nullptr) const;

    // Below this luminance the adaptive threshold applies to the error relative to this floor
    // rather than to the pixel's own (tiny) value; see estimate().
    static constexpr double kDarkLuminanceFloor = 0.05;

private:
    const Scene& scene_;
    const Integrator& integrator_;
    FirstHitProbe firstHitProbe_;
    FilterSampler filterSampler_;
    int maxSamples_;
    int lightEdgeSamples_;  // what a pixel on a light's edge may take instead
    int batchSize_;         // with adaptive sampling, min_spp; without, 0: all at once
    double threshold_;      // 0 without adaptive sampling
};

}  // namespace lancer
