#include "render/LightEdgeProbe.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "materials/Material.h"
#include "math/Float.h"
#include "scene/Scene.h"

namespace lancer {

LightEdgeProbe::LightEdgeProbe(const Scene& scene)
    : scene_(scene),
      white_(std::exp2(-scene.settings().exposure)),
      active_(scene.settings().lightEdgeFactor > 1 && scene.settings().samplesPerPixel > 1 &&
              (scene.hasEmittingSurface() || scene.environment() != nullptr ||
               scene.background().luminance() > white_)) {}

std::vector<bool> LightEdgeProbe::edges(const PixelWindow& window, std::uint64_t& rayCount) const {
    const int width = window.width(), height = window.height();
    std::vector<bool> onEdge(static_cast<std::size_t>(std::max(width, 0) * std::max(height, 0)));
    if (!active_ || onEdge.empty()) return onEdge;
    // Two rows of corners at a time: the pixel row's top and bottom.
    std::vector<float> top(static_cast<std::size_t>(width + 1));
    std::vector<float> bottom(top.size());
    const auto traceRow = [&](int y, std::vector<float>& row) {
        for (int i = 0; i <= width; ++i)
            row[static_cast<std::size_t>(i)] =
                seenLuminance(static_cast<float>(window.x0 + i), static_cast<float>(y), rayCount);
    };
    traceRow(window.y0, top);
    for (int j = 0; j < height; ++j) {
        traceRow(window.y0 + j + 1, bottom);
        for (int i = 0; i < width; ++i) {
            const auto k = static_cast<std::size_t>(i);
            const auto [darkest, brightest] =
                std::minmax({top[k], top[k + 1], bottom[k], bottom[k + 1]});
            onEdge[static_cast<std::size_t>(j * width + i)] = brightest - darkest > white_;
        }
        std::swap(top, bottom);
    }
    return onEdge;
}

float LightEdgeProbe::seenLuminance(float px, float py, std::uint64_t& rayCount) const {
    const RenderSettings& settings = scene_.settings();
    const std::optional<Ray> ray =
        scene_.camera().generateRay(px, py, settings.width, settings.height, Vec2(0.5f, 0.5f));
    if (!ray) return 0;
    ++rayCount;
    const std::optional<Hit> hit = scene_.intersect(*ray, kInfinity);
    if (!hit) return scene_.background(ray->direction).luminance();
    const Material& material = *hit->material;
    if (material.emission().isBlack() || !hit->seesEmittingSide(*ray)) return 0;
    return material.emission(*hit).luminance();
}

}  // namespace lancer
