#pragma once

#include <optional>
#include <string>

#include "scene/AdaptiveSettings.h"
#include "scene/AnimationSettings.h"
#include "scene/FilterSettings.h"
#include "scene/RadiositySettings.h"

namespace lancer {

// The scene file's "render" block, which the command line may override.
struct RenderSettings {
    // The deepest recursion the scene file and --max-depth accept: Whitted recursion takes
    // stack per bounce, and this depth stays well inside the 8 MiB the render threads have.
    static constexpr int kMaxDepthLimit = 1024;
    // The widest and tallest image the scene file and --width, --height accept (a 32768 x 32768
    // film takes 12 GiB); the memory the image's buffers need is checked as well.
    static constexpr int kMaxImageSide = 32768;
    // The most stops of exposure either way: 2^64 times any radiance a scene makes still fits
    // a float.
    static constexpr int kMaxExposure = 64;
    // The most samples per pixel the scene file ("spp", "max_spp", "min_spp") and --spp accept:
    // the render stops between a tile's rows when interrupted, and a row of 2^20 samples a pixel
    // still takes seconds, not hours (2^30 took longer than anyone waits, even for 8 x 6 pixels).
    static constexpr int kMaxSamplesPerPixel = 1 << 20;

    int width = 640;
    int height = 480;
    int samplesPerPixel = 16;  // with adaptive sampling, the most a pixel may take
    int maxDepth = 5;
    // whitted and radiosity: a reflected or refracted ray that would carry less than this of its
    // radiance to the pixel, in every channel, is not traced (POV-Ray's adaptive depth control),
    // 0 to 1. 0: every ray is traced, up to maxDepth.
    float adcBailout = 0;
    std::string integrator = "whitted";
    FilterSettings filter;                     // the reconstruction filter
    std::optional<AdaptiveSettings> adaptive;  // none: every pixel takes samplesPerPixel
    // A pixel on the edge of a light the camera sees (LightEdgeProbe) takes this many times the
    // samples (with adaptive sampling, this many times max_spp at most); 1: as any other pixel.
    int lightEdgeFactor = 16;
    // The largest radiance one camera sample may carry (a brighter sample is scaled down to this
    // largest component): fireflies trade for bias. None: samples are kept as they are.
    std::optional<float> sampleClamp;
    float exposure = 0;             // stops: the outputs are scaled by 2^exposure
    std::string tonemap = "clamp";  // the 8-bit outputs' tone operator
    RadiositySettings radiosity;    // the top-level "radiosity" block
    // The top-level "animation" block's frames: none for a still image.
    std::optional<AnimationSettings> animation;
};

}  // namespace lancer
