#pragma once

#include <optional>
#include <string>

#include "scene/AdaptiveSettings.h"
#include "scene/FilterSettings.h"
#include "scene/RadiositySettings.h"

namespace lancer {

// The scene file's "render" block, which the command line may override.
struct RenderSettings {
    int width = 640;
    int height = 480;
    int samplesPerPixel = 16;  // with adaptive sampling, the most a pixel may take
    int maxDepth = 5;
    std::string integrator = "whitted";
    FilterSettings filter;                     // the reconstruction filter
    std::optional<AdaptiveSettings> adaptive;  // none: every pixel takes samplesPerPixel
    RadiositySettings radiosity;               // the top-level "radiosity" block
};

}  // namespace lancer
