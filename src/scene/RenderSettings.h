#pragma once

#include <string>

namespace lancer {

// The scene file's "render" block, which the command line may override.
struct RenderSettings {
    int width = 640;
    int height = 480;
    int samplesPerPixel = 16;
    int maxDepth = 5;
    std::string integrator = "whitted";
};

}  // namespace lancer
